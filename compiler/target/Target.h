#pragma once
/// \file
/// The languages `mxc compile --target` writes, and where each binds a shader's resources.
///
/// Every target is made from the validated SPIR-V of the material: SPIR-V as it is, GLSL (OpenGL
/// 4.5), ESSL (OpenGL ES 3.2), MSL (Metal 2.1) and HLSL (shader model 6.0) by SPIRV-Cross, WGSL by
/// naga (compiler/target/Translate.h). SPIR-V names a resource by (set, binding); the other
/// languages have their own namespaces, so each descriptor of the shader interface gets a
/// Placement in the target, decided here once for both stages (docs/shader-interface.md,
/// "Targets") and written into the interface JSON beside the shader.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace mxc::target {

enum class Target : uint8_t { Spirv, Glsl, Essl, Msl, Hlsl, Wgsl };

/// "spirv", "glsl", "essl", "msl", "hlsl", "wgsl": the names --target takes.
std::string_view targetName(Target target);
std::optional<Target> parseTarget(std::string_view name);
/// Every target, in the order of targetNames().
const std::vector<Target>& allTargets();
/// "spirv|glsl|essl|msl|hlsl|wgsl", for help texts.
std::string targetNames();
/// The file extension a target's shader is written with: ".spv", ".glsl", ".essl", ".metal",
/// ".hlsl", ".wgsl".
std::string_view fileExtension(Target target);
/// The textures per shader stage every device or implementation of a target takes, and where
/// that figure comes from (textureLimitWarning's table).
struct TextureLimit {
  uint32_t perStage = 0;
  std::string_view source;
};

/// The target a file extension names (".spv" and the above, also ".msl"), if any.
std::optional<Target> targetOfExtension(std::string_view extension);
/// Whether the target is a text (every one but SPIR-V).
bool isText(Target target);

/// A descriptor of the shader interface, as SPIR-V binds it.
struct Resource {
  enum class Kind : uint8_t { Texture, UniformBuffer, StorageBuffer };
  uint32_t set = 0;
  uint32_t binding = 0;
  Kind kind = Kind::Texture;
  bool writable = false;  ///< storage buffers the shader writes
  std::string name;
};

/// Where a target binds a Resource. -1: not used by the target.
struct Placement {
  Resource resource;
  /// GLSL/ESSL: the binding of its class (uniform buffers, storage buffers and texture units
  /// are numbered separately). WGSL: the @binding in @group(set); a texture's sampler is at
  /// `samplerBinding`.
  int binding = -1;
  int samplerBinding = -1;
  /// MSL: [[buffer(n)]], or [[texture(n)]] and [[sampler(n)]].
  int buffer = -1, texture = -1, sampler = -1;
  /// HLSL: register(<registerClass><binding>, space<set>); a texture's sampler is s<binding>.
  char registerClass = 0;
};

/// The placements of `resources` in `target`, one per resource, in their order. The same
/// resources give the same placements, so that a vertex and a fragment stage translated apart
/// agree (the vertex stage's resources are a subset of its material's).
std::vector<Placement> placeResources(const std::vector<Resource>& resources, Target target);

/// The resources of a shader interface (compiler/glsl/ShaderInterface.h) as its "descriptors"
/// list them.
std::vector<Resource> resourcesOfInterface(const nlohmann::json& interface);

/// The targets whose guaranteed texture limit a shader of `resources` exceeds, as a warning
/// naming each with its figure; nothing when every target takes it.
std::optional<std::string> textureLimitWarning(const std::vector<Resource>& resources);

/// A Placement as the interface JSON writes it in a descriptor's "target" member.
nlohmann::json placementJson(const Placement& placement, Target target);

}  // namespace mxc::target
