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
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.erase(key);
    done_.notify_all();
    throw;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  done_.notify_all();  // they wake once the lock is released
  if (!words) {
    entries_.erase(key);
    return words;
  }
  Entry& entry = entries_.at(key);
  entry.words = std::move(*words);  // a move: nothing here throws before the entry is complete
  entry.pending = false;
  return entry.words;
}

size_t ShaderCache::hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}

}  // namespace mxc
