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
        touch(it->second);
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
  auto entry = entries_.find(key);
  if (!completeEntry(entry, *words)) return words;  // not kept, as a failed compile's
  return entry->second.words;
}

bool ShaderCache::completeEntry(std::map<std::string, Entry>::iterator entry, Words& words) {
  // Only the list node allocates: should it fail, the entry is dropped (its waiters wake to
  // compile the code themselves) and `words` stays the caller's.
  try {
    used_.push_front(&entry->first);
  } catch (...) {
    entries_.erase(entry);
    return false;
  }
  entry->second.words = std::move(words);
  entry->second.pending = false;
  entry->second.used = used_.begin();
  held_ += bytesOf(entry->first, entry->second);
  while (held_ > capacity_ && used_.size() > 1) {
    auto victim = entries_.find(*used_.back());
    held_ -= bytesOf(victim->first, victim->second);
    used_.pop_back();
    entries_.erase(victim);
    ++evicted_;
  }
  return true;
}

void ShaderCache::touch(Entry& entry) { used_.splice(used_.begin(), used_, entry.used); }

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
    auto entry = entries_.find(key);
    entry->second.unclaimed = true;
    if (completeEntry(entry, it->second)) ++grouped_;
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

size_t ShaderCache::heldBytes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return held_;
}

size_t ShaderCache::evicted() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return evicted_;
}

size_t ShaderCache::hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}

}  // namespace mxc
