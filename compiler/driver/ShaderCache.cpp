#include "compiler/driver/ShaderCache.h"

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
      // is then gone and this worker compiles for itself, to report its own errors).
      done_.wait(lock, [&] {
        auto now = entries_.find(key);
        return now == entries_.end() || !now->second.pending;
      });
      auto now = entries_.find(key);
      if (now == entries_.end()) return compile();
    }
  }
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
  if (words) {
    Entry& entry = entries_.at(key);
    entry.words = *words;
    entry.pending = false;
  } else {
    entries_.erase(key);
  }
  done_.notify_all();
  return words;
}

size_t ShaderCache::hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}

}  // namespace mxc
