#pragma once
/// \file
/// Independent jobs on every core: the one thread pool of mxc's commands (shaders compiled by
/// glslang, pipelines compiled by the Vulkan driver).

#include <cstddef>
#include <functional>

namespace mxc {

/// The threads worth running at once: one per core (at least 1).
size_t coreCount();

/// Runs job(0), ..., job(count - 1), each once, on up to coreCount() threads (the caller's
/// among them), each thread taking the next index in turn. Returns when all have stopped; the
/// failure of the lowest index, if any, is then rethrown. Jobs must be safe to run at once.
void runOnEveryCore(size_t count, const std::function<void(size_t)>& job);

}  // namespace mxc
