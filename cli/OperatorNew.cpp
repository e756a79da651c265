// The mxc program's operator new, for builds where mimalloc serves malloc (cli/CMakeLists.txt).
//
// mimalloc's library also replaces operator new, and where the allocation fails with no new
// handler its version aborts (it is written in C and cannot throw). The standard's operator new
// throws std::bad_alloc instead, which mxc reports as "error: out of memory" with exit code 4,
// its temporaries removed (cli/Main.cpp). The program's own definitions come before every shared
// library's, so these restore the standard's behaviour over mimalloc's malloc. operator delete
// stays mimalloc's: it frees what its malloc returned.

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {

/// [new.delete.single]: loop on the new handler while there is one, else throw.
void* allocate(std::size_t size, std::size_t alignment) {
  if (size == 0) size = 1;  // a distinct pointer for each zero-size request
  for (;;) {
    void* p = nullptr;
    if (alignment <= alignof(std::max_align_t)) {
      p = std::malloc(size);
    } else if (::posix_memalign(&p, std::max(alignment, sizeof(void*)), size) != 0) {
      p = nullptr;  // posix_memalign leaves p unspecified on failure
    }
    if (p) return p;
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size, 0); }
void* operator new[](std::size_t size) { return allocate(size, 0); }
void* operator new(std::size_t size, std::align_val_t alignment) {
  return allocate(size, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return allocate(size, static_cast<std::size_t>(alignment));
}
