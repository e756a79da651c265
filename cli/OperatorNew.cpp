// The mxc program's operator new, for builds where mimalloc serves malloc (cli/CMakeLists.txt).
//
// mimalloc's library also replaces operator new, and where the allocation fails with no new
// handler its version aborts (it is written in C and cannot throw). The standard's operator new
// throws std::bad_alloc instead, which mxc reports as "error: out of memory" with exit code 4,
// its temporaries removed (cli/Main.cpp). The program's own definitions come before every shared
// library's, so these restore the standard's behaviour over mimalloc's allocation functions
// (called directly: this file is built only with mimalloc). operator delete stays mimalloc's: it
// frees what they return.

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>

#include <mimalloc.h>

namespace {

/// [new.delete.single]'s loop, once the first attempt has failed: the new handler while there
/// is one, else std::bad_alloc.
[[gnu::noinline]] void* allocateSlowly(std::size_t size, std::size_t alignment) {
  for (;;) {
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
    if (void* p = alignment ? mi_malloc_aligned(size, alignment) : mi_malloc(size)) return p;
  }
}

/// A distinct pointer for each zero-size request (the standard's rule): mimalloc's malloc(0)
/// already returns one. The first attempt is all but every call: straight to mimalloc, a few
/// instructions (the batch makes 2.8 million allocations).
inline void* allocate(std::size_t size) {
  if (void* p = mi_malloc(size)) [[likely]] return p;
  return allocateSlowly(size, 0);
}

inline void* allocateAligned(std::size_t size, std::size_t alignment) {
  if (void* p = mi_malloc_aligned(size, alignment)) [[likely]] return p;
  return allocateSlowly(size, alignment);
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, std::align_val_t alignment) {
  return allocateAligned(size, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return allocateAligned(size, static_cast<std::size_t>(alignment));
}
