#pragma once
/// \file
/// Assembles whole GLSL shaders: the shader library (compiler/glsl/library/*.glsl), the material's
/// closure function generated from the IR, and a stage main (compiler/glsl/stages/*). Only the
/// library parts the material uses are compiled in (lobe kinds, thin film, procedural nodes).

#include <string>
#include <vector>

#include "compiler/common/Accuracy.h"
#include "compiler/glsl/Bindings.h"
#include "compiler/glsl/ClosureEmitter.h"
#include "compiler/glsl/ExprEmitter.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::glsl {

/// What a material shader is for.
enum class ShaderKind : uint8_t {
  Raster,   ///< fragment shader of the sphere renderer (lights, environment, accumulation)
  Eval,     ///< compute: f(wo, wi) |cos theta_i| for a batch of direction pairs
  Furnace,  ///< compute: directional albedo (reflected and transmitted) by Monte Carlo
  Sample,   ///< compute: directions drawn by the closure's sampling (to check them against its pdf)
};

std::string_view shaderKindName(ShaderKind kind);

/// One member of the material's parameter block (binding kParameterBinding), std140 layout.
struct UniformField {
  std::string name;
  ir::Type type = ir::Type::Float;
  uint32_t offset = 0;
  std::vector<float> value;  ///< its default (componentCount floats; 1 for Bool, Int)
  /// A bit-mask member's value (missing_textures*), written as a uint: a float holds only 24
  /// bits exactly, so texture 24's bit and texture 0's could not both be set through `value`.
  uint32_t bits = 0;
};

/// What the harness must provide to run a material shader.
struct MaterialInterface {
  std::vector<TextureBinding> textures;
  std::vector<UniformField> parameters;  ///< always has missing_textures, frame and time first
                                         ///< (then missing_textures_32... past 32 textures)
  uint32_t parameterBytes = 0;
  int lobes = 0;                        ///< lobes of the closure (MXC_MAX_LOBES)
  /// Samples (walks) one invocation may draw per dispatch: 0 for no limit; 1 for the reference
  /// tier, whose walk may run up to the device's loop cap on its own (mxc_walk.glsl, MXC_WALK_BUDGET).
  uint32_t samplesPerDispatch = 0;
  FlagSet<ir::LobeKind> lobeKinds;      ///< the lobe kinds compiled in (MXC_HAS_*)
  bool transmission = false;            ///< the lobes' refraction code is compiled in (MXC_TRANSMISSION)
  bool absorption = false;              ///< absorption above the lobes is computed (MXC_ABSORPTION)
  bool subgroups = true;                ///< parameters are read through subgroupBroadcastFirst (MXC_SUBGROUPS)
  std::vector<std::string> geomprops;
};

/// Every material shader's closure function (what the stages call, `mxc_material_closure(g, wo,
/// c)`): its name, parameters and the arguments that pass them on.
inline constexpr const char* kClosureFunction = "mxc_material_closure";
inline constexpr const char* kClosureParameters = "in MxcGeometry g, vec3 wo, out MxcClosure c";
inline constexpr const char* kClosureArguments = "g, wo, c";

struct MaterialShader {
  spirv::GlslSource glsl;
  MaterialInterface interface;
  /// The shader's code: its GLSL but for the comment lines naming the material, each library
  /// file by its path (its text is fixed in the executable). Two shaders with the same key
  /// compile to the same SPIR-V (ShaderCache).
  std::string codeKey;
  /// The code key but for the body of `mxc_material_closure`, the texture declarations and
  /// comments: shaders with the same library key compile as one shader in a batch
  /// (ShaderGroup.h). A texture's declaration depends only on its index (binding
  /// kFirstTextureBinding + i, name mxc_texture_<i>), so shaders that differ in how many textures
  /// they read share a library: the group declares the most any member reads.
  std::string libraryKey;
  /// The lines [first, end) of glsl.text that define `mxc_material_closure`.
  size_t closureFirst = 0;
  size_t closureEnd = 0;
  /// The lines [first, end) of glsl.text that declare the textures (empty for none).
  size_t texturesFirst = 0;
  size_t texturesEnd = 0;
};

struct BuildOptions {
  Accuracy accuracy = Accuracy::Balanced;
  /// The reference tier: random walks per evaluation of f cos (MXC_REFERENCE_SAMPLES); sampling
  /// is one walk per sample.
  int referenceSamples = 1;
  /// Paste the shader library files in (a standalone shader, what glslang compiles). When
  /// false, each library file is an `#include` line instead: the material-specific part only,
  /// which is what the golden files under generated/glsl hold.
  bool expandLibrary = true;
  /// Compile only the library code the material's closure uses (false, `--no-specialize`: the
  /// refraction and absorption code whatever the lobes' modes, as a general shader has it).
  bool specialize = true;
  /// Each texture and its sampler as two bindings (MXC_SEPARATE_SAMPLERS, Bindings.h): the WGSL
  /// target's SPIR-V, since WGSL has no combined image sampler.
  bool separateSamplers = false;
  /// Parameters read through subgroupBroadcastFirst (MXC_SUBGROUPS, mxc_codes.glsl): what mxc's
  /// renderer needs on lavapipe. False for the other targets, whose hosts need no subgroups.
  bool subgroups = true;
};

/// The shader of a material for a use. Its GLSL lines map back to the document elements that
/// produced them (GlslSource::origins).
MaterialShader buildMaterialShader(const ir::Material& material, ShaderKind kind, const BuildOptions& options = {});

/// The vertex shader of the raster renderer (the same for every material).
spirv::GlslSource buildVertexShader();
/// buildVertexShader() as validated SPIR-V, compiled once per process: the renderer's and the
/// vertex stage `mxc compile` writes beside each fragment shader.
const std::vector<uint32_t>& vertexStageSpirv();
/// The compute shader that fills the albedo tables the lobes read (kTableSize^2 texels).
spirv::GlslSource buildTablesShader();

/// The compute shader drawing directions from an environment image's distribution
/// (stages/mxc_environment_sample.comp), for runtime/EnvironmentMap's sample().
spirv::GlslSource buildEnvironmentSampleShader();

}  // namespace mxc::glsl

namespace mxc::glsl {
/// The bytes of the parameter block: each field's value at its std140 offset (matrices given
/// row by row, as ExprGraph::constantComponents lists them, are stored as padded columns).
std::vector<uint8_t> packParameters(const std::vector<UniformField>& fields, uint32_t bytes);
/// The GLSL type a parameter block member is declared with (the missing_textures masks are uints).
std::string parameterType(const UniformField& field);
}  // namespace mxc::glsl
