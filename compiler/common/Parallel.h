#pragma once
/// \file
/// Independent jobs on every core: the one thread pool of mxc's commands (shaders compiled by
/// glslang, pipelines compiled by the Vulkan driver).
///
/// The pool's threads are made once and live as long as the process. Besides saving the cost
/// of a thread per call, that matters at start-up: glibc holds its TLS lock for the whole of a
/// dlopen, so a thread created while the image module loads (0.2-0.4 s, rt::ImageModulePreload)
/// waits for the load to finish. Threads made before the load never wait.

#include <cstddef>
#include <functional>

namespace mxc {

/// The threads worth running at once: one per core (at least 1).
size_t coreCount();

/// Makes the pool's coreCount() - 1 threads now, if they do not exist yet. runOnEveryCore does
/// this itself; call it first where threads must not be created later (before a dlopen on
/// another thread).
void startWorkers();

/// Runs job(0), ..., job(count - 1), each once, on up to coreCount() threads (the caller's
/// among them), each thread taking the next index in turn. Returns when all have stopped; the
/// failure of the lowest index, if any, is then rethrown. Jobs must be safe to run at once.
/// Calls may nest or come from several threads at once: a call made while the pool serves
/// another runs on threads of its own.
void runOnEveryCore(size_t count, const std::function<void(size_t)>& job);

/// runOnEveryCore on `threads` threads (the caller's among them) instead of one per core: the
/// pool's when that is its size, else threads of the call's own (`mxc compile -j N`).
void runOnThreads(size_t count, size_t threads, const std::function<void(size_t)>& job);

}  // namespace mxc
