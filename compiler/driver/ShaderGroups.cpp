#include "compiler/driver/ShaderGroups.h"

#include <map>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "compiler/glsl/ShaderGroup.h"
#include "compiler/spirv/ModuleCut.h"

namespace mxc {

std::string shaderCacheKey(const glsl::MaterialShader& shader, const CompileRequest& request) {
  return fmt::format("{}{}\n{}", spirv::stageName(shader.glsl.stage), request.optimize ? " -O" : "", shader.codeKey);
}

void planShaderGroups(ShaderCache& cache, const std::vector<std::shared_ptr<const glsl::MaterialShader>>& shaders,
                      const CompileRequest& request) {
  if (request.optimize) return;
  // One member per distinct code (materials of one code share its module anyway), by library
  // and stage.
  using Members = std::vector<std::shared_ptr<const glsl::MaterialShader>>;
  std::map<std::string, Members> libraries;
  std::set<std::string> seen;
  for (const auto& s : shaders) {
    if (s->codeKey.empty() || s->closureEnd <= s->closureFirst) continue;  // built by hand: no closure lines
    if (!seen.insert(shaderCacheKey(*s, request)).second) continue;
    const std::string library = fmt::format("{}\n{}", spirv::stageName(s->glsl.stage), s->libraryKey);
    libraries[library].push_back(s);
  }
  for (auto& [library, members] : libraries) {
    if (members.size() < 2) continue;
    std::vector<std::string> keys;
    for (const auto& s : members) keys.push_back(shaderCacheKey(*s, request));
    cache.addGroup(keys, [group = std::move(members), keys] {
      std::vector<const glsl::MaterialShader*> pointers;
      for (const auto& s : group) pointers.push_back(s.get());
      std::map<std::string, ShaderCache::Words> made;
      // A group that does not compile leaves each member to compile alone, with its own
      // document's messages: this one's are dropped.
      Diagnostics diagnostics;
      const std::optional<std::vector<uint32_t>> words = spirv::compile(glsl::groupSource(pointers), {}, diagnostics);
      if (!words) return made;
      const spirv::ModuleCutter cutter(*words);
      for (size_t k = 0; k < pointers.size(); ++k) {
        std::string error;
        auto cut = cutter.cut({glsl::kClosureFunction, glsl::groupMemberFunction(k)}, error);
        if (cut) made.emplace(keys[k], std::move(*cut));
      }
      return made;
    });
  }
}

}  // namespace mxc
