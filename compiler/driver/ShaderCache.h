#pragma once
/// \file
/// The SPIR-V of shaders already compiled in this process, shared by the workers of a batch.
///
/// Two materials whose shaders have the same code compile to the same module: glslang and
/// SPIRV-Tools are deterministic, and a shader's code is its GLSL but for the comment lines that
/// name its material. In a batch that happens for a document's look and its material, for
/// materials that differ only in inputs the shader does not read, and above all under
/// `--param-all`, where every material of one structure (the OpenPBR presets, say) shares one
/// shader: 25 distinct shaders for the corpus's 75 materials (`mxc compile --param-all`). Each
/// is compiled and validated once; the other materials copy its words.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace mxc {

class ShaderCache {
 public:
  using Words = std::vector<uint32_t>;
  /// What the complete entries may hold, keys and modules together, before the least recently
  /// used are dropped: a document of 100k distinct materials would otherwise keep every module
  /// (about 110 kB for an OpenPBR shader) and key to the end. A dropped code is compiled again
  /// if a later material has it, so the bound costs time only when sharing spans more shaders
  /// than it holds (256 MiB: over a thousand OpenPBR shaders, 110 kB of module each and a key).
  static constexpr size_t kDefaultCapacityBytes = size_t(256) << 20;
  explicit ShaderCache(size_t capacityBytes = kDefaultCapacityBytes) : capacity_(capacityBytes) {}
  /// How getOrCompile came by a key's module.
  enum class Served {
    Compiled,      ///< compiled for this call
    SameCode,      ///< compiled earlier for a material of the same code
    CutFromGroup,  ///< cut from the compile of its library's group (addGroup)
  };

  /// The module of the shader whose code is `key` (glsl::MaterialShader::codeKey): compiled
  /// by `compile` unless another worker has compiled it (then copied) or is compiling it (then
  /// awaited). A compile that fails is not kept: each material whose shader fails compiles it
  /// itself, so its errors name its own document. An exception from `compile` passes through;
  /// a worker waiting for that compile takes it over. A successful compile must
  /// report nothing (spirv::compile reports errors only): a material served from the cache
  /// gets no messages.
  ///
  /// Entries live as long as the cache (a batch, a workspace) or until the capacity drops them:
  /// a key is the generated part of a shader (library files count by their paths: under a
  /// fifth of the text, ShaderBuilderTest checks) and a module 25-110 kB.
  std::optional<Words> getOrCompile(const std::string& key, const std::function<std::optional<Words>()>& compile,
                                    Served* served = nullptr);

  /// Keys that compile together (shaders of one library, driver/ShaderGroups.h): the first
  /// getOrCompile of any of them runs `compile` once for all, which returns the words of each
  /// key it could make; a key it could not compiles alone, as if there were no group. Keys
  /// already in a group or compiled are left out of this one.
  using GroupCompile = std::function<std::map<std::string, Words>()>;
  void addGroup(const std::vector<std::string>& keys, GroupCompile compile);
  /// Compiles the largest group no worker has started; false when there is none. A batch's
  /// workers call it until false before their documents, so that none waits on another's
  /// group (the documents of one library are often neighbours in a folder).
  bool compileAGroup();

  /// Materials served from a compile of another material's shader of the same code so far.
  size_t hits() const;
  /// Modules made by group compiles so far.
  size_t grouped() const;
  /// Bytes of keys and modules the complete entries hold now (at most the capacity, but for
  /// one entry larger than it, kept until the next).
  size_t heldBytes() const;
  /// Complete entries dropped to stay within the capacity so far.
  size_t evicted() const;

 private:
  struct Entry {
    bool pending = true;
    bool unclaimed = false;  ///< made by a group compile, not yet taken by its material
    Words words;
    std::list<const std::string*>::iterator used;  ///< its place in used_, once complete
  };
  struct Group {
    std::vector<std::string> keys;
    GroupCompile compile;
  };
  /// Runs `group` (taken out of groups_, its keys' entries pending) with the lock released.
  void runGroup(std::unique_lock<std::mutex>& lock, const std::shared_ptr<Group>& group);
  /// Makes the pending `entry` complete with `words` (moved from) and most recently used, then
  /// drops the least recently used complete entries past the capacity (never `entry` itself).
  /// False, `entry` erased and `words` left as they were, when there was no memory for it.
  bool completeEntry(std::map<std::string, Entry>::iterator entry, Words& words);
  /// `key`'s complete entry is used again: it moves to the front.
  void touch(Entry& entry);
  static size_t bytesOf(const std::string& key, const Entry& entry) {
    return key.size() + entry.words.size() * sizeof(uint32_t);
  }

  mutable std::mutex mutex_;
  std::condition_variable done_;
  std::map<std::string, Entry> entries_;  ///< a key's entry is erased when its compile fails
  std::map<std::string, std::shared_ptr<Group>> groups_;  ///< the group of each key not yet compiled
  size_t hits_ = 0;
  size_t grouped_ = 0;
  size_t capacity_;
  size_t held_ = 0;    ///< bytesOf every complete entry
  size_t evicted_ = 0;
  /// The keys (in entries_, whose nodes do not move) of the complete entries, most recently
  /// used first.
  std::list<const std::string*> used_;
};

}  // namespace mxc
