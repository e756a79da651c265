#pragma once
/// \file
/// Running work on a thread with a large stack. Resolution and lowering recurse along the
/// connections of a node graph, so a graph that chains 100,000 nodes needs far more than the
/// 8 MiB main-thread stack. The stack is reserved address space: only the pages a run touches
/// become resident.

#include <cstddef>
#include <functional>

namespace mxc {

/// Stack of the thread that runs a command: 1 GiB of address space.
constexpr size_t kLargeStackBytes = size_t{1} << 30;

/// Runs `work` on a new thread with a stack of `bytes` and waits for it. If the thread cannot
/// be created, runs `work` on the calling thread.
void runWithLargeStack(const std::function<void()>& work, size_t bytes = kLargeStackBytes);

/// Bytes of stack left on the calling thread below the caller's frame (from the thread's stack
/// bounds; SIZE_MAX when the bounds cannot be read). Recursive walks check it to stop with an
/// error where a graph is deeper than the stack, instead of overflowing it.
size_t stackRemaining();

}  // namespace mxc
