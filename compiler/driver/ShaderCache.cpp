#include "compiler/driver/ShaderCache.h"

#include <utility>

namespace mxc {

std::optional<ShaderCache::Words> ShaderCache::getOrCompile(const std::string& key,
                                                             const std::function<std::optional<Words>()>& compile) {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      auto it = entries_.find(key);
      if (it == entries_.end()) {
        entries_.emplace(key, Entry{});  // ours to compile
        break;
      }
      if (!it->second.pending) {
        ++hits_;
        return it->second.words;
      }
      // Another worker compiles this code: wait for its words, or for its failure (the entry
      // is then gone, and this worker takes the compile over, to report its own errors).
      done_.wait(lock, [&] {
        auto now = entries_.find(key);
        return now == entries_.end() || !now->second.pending;
      });
    }
  }
  // Whatever happens from here on, the entry leaves the pending state and the waiters wake.
  std::optional<Words> words;
  try {
    words = compile();
    if (words) {
      Words kept = *words;  // copied before the lock: a bad_alloc here is the catch's case
      std::lock_guard<std::mutex> lock(mutex_);
      Entry& entry = entries_.at(key);
      entry.words = std::move(kept);
      entry.pending = false;
      done_.notify_all();
      return words;
    }
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.erase(key);
    done_.notify_all();
    throw;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.erase(key);
  done_.notify_all();
  return words;
}

size_t ShaderCache::hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}

}  // namespace mxc
