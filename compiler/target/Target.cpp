#include "compiler/target/Target.h"

#include <algorithm>
#include <array>
#include <numeric>

#include <fmt/format.h>

#include "compiler/glsl/Bindings.h"

namespace mxc::target {

namespace {

struct TargetInfo {
  Target target;
  std::string_view name;
  std::string_view extension;
  TextureLimit textures;
};

// The textures per stage every implementation of a target takes. Each texture of an mxc shader
// is one sampled image and one sampler in every target (SPIR-V's combined image samplers are
// split by SPIRV-Cross and naga), so the lesser of the two limits counts.
constexpr std::array<TargetInfo, 6> kTargets{
    {{Target::Spirv, "spirv", ".spv", {16, "Vulkan's required maxPerStageDescriptorSamplers"}},
     {Target::Glsl, "glsl", ".glsl", {16, "OpenGL 4.5's required GL_MAX_TEXTURE_IMAGE_UNITS"}},
     {Target::Essl, "essl", ".essl", {16, "OpenGL ES 3.2's required GL_MAX_TEXTURE_IMAGE_UNITS"}},
     {Target::Msl, "msl", ".metal", {16, "Metal's sampler argument table"}},
     {Target::Hlsl, "hlsl", ".hlsl", {16, "Direct3D 12's samplers per stage at resource binding tier 1"}},
     {Target::Wgsl, "wgsl", ".wgsl", {16, "WebGPU's default maxSampledTexturesPerShaderStage and maxSamplersPerShaderStage"}}}};

const TargetInfo& info(Target target) {
  for (const TargetInfo& t : kTargets) {
    if (t.target == target) return t;
  }
  return kTargets[0];
}

}  // namespace

std::string_view targetName(Target target) { return info(target).name; }
std::string_view fileExtension(Target target) { return info(target).extension; }

std::optional<std::string> textureLimitWarning(const std::vector<Resource>& resources) {
  const auto textures = static_cast<uint32_t>(std::count_if(
      resources.begin(), resources.end(), [](const Resource& r) { return r.kind == Resource::Kind::Texture; }));
  std::vector<std::string> exceeded;
  for (const TargetInfo& t : kTargets) {
    if (textures > t.textures.perStage) exceeded.push_back(fmt::format("{} ({}, {})", t.name, t.textures.perStage, t.textures.source));
  }
  if (exceeded.empty()) return std::nullopt;
  return fmt::format("the shader samples {} textures in one stage (mxc's own among them), more than {} guarantee{}: it "
                     "runs only on devices that take more",
                     textures, fmt::join(exceeded, ", "), exceeded.size() == 1 ? "s" : "");
}
bool isText(Target target) { return target != Target::Spirv; }

std::optional<Target> parseTarget(std::string_view name) {
  for (const TargetInfo& t : kTargets) {
    if (t.name == name) return t.target;
  }
  return std::nullopt;
}

const std::vector<Target>& allTargets() {
  static const std::vector<Target> all = [] {
    std::vector<Target> out;
    for (const TargetInfo& t : kTargets) out.push_back(t.target);
    return out;
  }();
  return all;
}

std::string targetNames() {
  std::string out;
  for (const TargetInfo& t : kTargets) out += (out.empty() ? "" : "|") + std::string(t.name);
  return out;
}

std::optional<Target> targetOfExtension(std::string_view extension) {
  if (extension == ".msl") return Target::Msl;
  for (const TargetInfo& t : kTargets) {
    if (t.extension == extension) return t.target;
  }
  return std::nullopt;
}

std::vector<Placement> placeResources(const std::vector<Resource>& resources, Target target) {
  std::vector<Placement> out(resources.size());
  // In (set, binding) order, so that the numbering of the flat namespaces does not depend on
  // the order the interface lists its descriptors in.
  std::vector<size_t> order(resources.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::pair(resources[a].set, resources[a].binding) < std::pair(resources[b].set, resources[b].binding);
  });
  int uniformBuffers = 0, storageBuffers = 0, textures = 0, buffers = 0;
  for (size_t i : order) {
    const Resource& r = resources[i];
    Placement& p = out[i];
    p.resource = r;
    switch (target) {
      case Target::Spirv:
        p.binding = static_cast<int>(r.binding);
        break;
      case Target::Glsl:
      case Target::Essl:
        // OpenGL has no descriptor sets: uniform blocks, storage blocks and texture units each
        // have one namespace of bindings.
        p.binding = r.kind == Resource::Kind::Texture         ? textures++
                    : r.kind == Resource::Kind::UniformBuffer ? uniformBuffers++
                                                              : storageBuffers++;
        break;
      case Target::Msl:
        // Metal's argument table: buffers (uniform and storage alike) from 0, textures from 0,
        // each texture's sampler at the texture's index. Vertex buffers go above the resources'
        // buffers (docs/shader-interface.md).
        if (r.kind == Resource::Kind::Texture) {
          p.texture = p.sampler = textures++;
        } else {
          p.buffer = buffers++;
        }
        break;
      case Target::Hlsl:
        // register(<class><binding>, space<set>): constant buffers b, read-only storage buffers
        // (ByteAddressBuffer) and textures t, written storage buffers (RWByteAddressBuffer) u;
        // a texture's SamplerState s at the texture's number.
        p.binding = static_cast<int>(r.binding);
        p.registerClass = r.kind == Resource::Kind::UniformBuffer ? 'b'
                          : r.kind == Resource::Kind::Texture     ? 't'
                          : r.writable                            ? 'u'
                                                                  : 't';
        break;
      case Target::Wgsl:
        // @group(set) @binding(binding); WGSL has no combined image sampler, so a texture's
        // sampler is a binding of its own (glsl::kSeparateSamplerOffset above the texture's).
        p.binding = static_cast<int>(r.binding);
        if (r.kind == Resource::Kind::Texture) p.samplerBinding = static_cast<int>(r.binding + glsl::kSeparateSamplerOffset);
        break;
    }
  }
  return out;
}

std::vector<Resource> resourcesOfInterface(const nlohmann::json& interface) {
  std::vector<Resource> out;
  if (!interface.contains("descriptors")) return out;
  for (const nlohmann::json& d : interface["descriptors"]) {
    Resource r;
    r.set = d.value("set", 0u);
    r.binding = d.value("binding", 0u);
    r.name = d.value("name", std::string());
    const std::string type = d.value("type", std::string());
    r.kind = type == "uniform_buffer"   ? Resource::Kind::UniformBuffer
             : type == "storage_buffer" ? Resource::Kind::StorageBuffer
                                        : Resource::Kind::Texture;
    r.writable = r.kind == Resource::Kind::StorageBuffer && !d.value("readonly", false);
    out.push_back(std::move(r));
  }
  return out;
}

nlohmann::json placementJson(const Placement& p, Target target) {
  const bool texture = p.resource.kind == Resource::Kind::Texture;
  switch (target) {
    case Target::Spirv: return {{"set", p.resource.set}, {"binding", p.resource.binding}};
    case Target::Glsl:
    case Target::Essl: return {{"binding", p.binding}};
    case Target::Msl:
      if (texture) return {{"texture", p.texture}, {"sampler", p.sampler}};
      return {{"buffer", p.buffer}};
    case Target::Hlsl: {
      nlohmann::json out{{"register", fmt::format("{}{}", p.registerClass, p.binding)}, {"space", p.resource.set}};
      if (texture) out["sampler"] = fmt::format("s{}", p.binding);
      return out;
    }
    case Target::Wgsl: {
      nlohmann::json out{{"group", p.resource.set}, {"binding", p.binding}};
      if (texture) out["samplerBinding"] = p.samplerBinding;
      return out;
    }
  }
  return {};
}

}  // namespace mxc::target
