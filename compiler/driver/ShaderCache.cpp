#include "compiler/driver/ShaderCache.h"

#include <utility>

namespace mxc {

std::optional<ShaderCache::Words> ShaderCache::getOrCompile(const std::string& key,
                                                             const std::function<std::optional<Words>()>& compile,
                                                             Served* served) {
  Served how = Served::Compiled;
  if (!served) served = &how;
  *served = Served::Compiled;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      auto it = entries_.find(key);
      if (it == entries_.end()) {
        if (auto group = groups_.find(key); group != groups_.end()) {
          runGroup(lock, std::shared_ptr<Group>(group->second));
          continue;  // the key's words are ready, or it compiles alone
        }
        entries_.emplace(key, Entry{});  // ours to compile
        break;
      }
      if (!it->second.pending) {
        if (it->second.unclaimed) {
          it->second.unclaimed = false;  // the material it was made for
          *served = Served::CutFromGroup;
        } else {
          ++hits_;
          *served = Served::SameCode;
        }
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

void ShaderCache::addGroup(const std::vector<std::string>& keys, GroupCompile compile) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto group = std::make_shared<Group>();
  group->compile = std::move(compile);
  for (const std::string& key : keys) {
    if (!entries_.count(key) && !groups_.count(key)) group->keys.push_back(key);
  }
  if (group->keys.size() < 2) return;  // one key compiles as well alone
  for (const std::string& key : group->keys) groups_[key] = group;
}

void ShaderCache::runGroup(std::unique_lock<std::mutex>& lock, const std::shared_ptr<Group>& group) {
  for (const std::string& key : group->keys) {
    groups_.erase(key);
    entries_.emplace(key, Entry{});
  }
  lock.unlock();
  std::map<std::string, Words> made;
  try {
    made = group->compile();
  } catch (...) {
    // Each key then compiles alone (the exception is the group's, not a material's).
    made.clear();
  }
  lock.lock();
  for (const std::string& key : group->keys) {
    auto it = made.find(key);
    if (it == made.end()) {
      entries_.erase(key);
      continue;
    }
    Entry& entry = entries_.at(key);
    entry.words = std::move(it->second);
    entry.pending = false;
    entry.unclaimed = true;
    ++grouped_;
  }
  done_.notify_all();
}

bool ShaderCache::compileAGroup() {
  std::unique_lock<std::mutex> lock(mutex_);
  std::shared_ptr<Group> largest;
  for (const auto& [key, group] : groups_) {
    if (!largest || group->keys.size() > largest->keys.size()) largest = group;
  }
  if (!largest) return false;
  runGroup(lock, largest);
  return true;
}

size_t ShaderCache::grouped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return grouped_;
}

size_t ShaderCache::hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}

}  // namespace mxc
