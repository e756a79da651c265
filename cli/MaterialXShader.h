#pragma once
/// \file
/// MaterialX's own generated shaders (VkShaderGenerator, vertex and pixel stages) run in mxc's
/// raster harness: both stages compiled by glslang with reflection, the uniform blocks laid
/// out from that reflection and filled by name (camera and light from the render settings,
/// material inputs from the values MaterialX's generator reported), textures bound to their
/// samplers, mesh attributes to the stage inputs. For the side-by-side comparison
/// (tests/bench/CompareBench.cpp) and `mxc bench specialize --materialx`: MaterialX itself is
/// not used, only the GLSL its generator wrote (tests/bench/materialx_compare.py makes it).

#include <filesystem>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

#include "compiler/spirv/SpirvCompiler.h"
#include "runtime/Renderer.h"

namespace mxc::cli {

/// A value of MaterialX's public uniform block, as its generator printed it.
struct MaterialXUniform {
  std::string name;
  std::string type;   ///< MaterialX type name: float, color3, filename, boolean, ...
  std::string value;  ///< MaterialX value string; "" when the generator gave none
};

/// The uniform values tests/bench/materialx_compare.py writes beside the stages: per block, a
/// list of {"name", "type", "value"}; entries whose value is null are left out. Throws a
/// std::exception (nlohmann::json's) on malformed text.
std::vector<MaterialXUniform> parseMaterialXUniforms(const std::string& json);

class MaterialXShader {
 public:
  /// Compiles both stages (with reflection). `uniforms` are the pixel stage's block values;
  /// filenames are resolved against `folder`. Returns an error message instead.
  static std::variant<MaterialXShader, std::string> load(const std::string& vertexGlsl, const std::string& pixelGlsl,
                                                           std::vector<MaterialXUniform> uniforms,
                                                           const std::filesystem::path& folder);

  /// Renders the mesh with the settings' camera and directional lights (MaterialX has no
  /// point light of the same units here, so the settings must hold directional ones only).
  /// Warnings (unknown uniforms left at zero, unreadable textures) go to `warnings`.
  rt::RenderResult render(rt::VulkanContext& context, rt::Renderer& renderer, const rt::Mesh& mesh,
                          const rt::RenderSettings& settings, std::vector<std::string>& warnings) const;

  const std::vector<uint32_t>& vertexSpirv() const { return vertex_; }
  const std::vector<uint32_t>& pixelSpirv() const { return pixel_; }

 private:
  std::vector<uint32_t> vertex_, pixel_;
  spirv::Reflection vertexInterface_, pixelInterface_;
  /// The value string of a uniform MaterialX gave one (filenames, address modes), or null.
  const std::string* valueOf(const std::string& name) const;

  std::unordered_map<std::string, MaterialXUniform> uniforms_;  ///< by name
  /// Numeric uniforms' components, parsed once from their value strings by the document
  /// model's parser (row by row for matrices; 0 or 1 for booleans).
  std::unordered_map<std::string, std::vector<float>> values_;
  std::filesystem::path folder_;
};

}  // namespace mxc::cli
