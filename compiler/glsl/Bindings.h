#pragma once
/// \file
/// The descriptor bindings (set 0) shared by every generated shader and the Vulkan harness that
/// runs it. The harness binds what a stage declares; unused bindings are simply absent.

#include <cstddef>
#include <cstdint>
#include <string>

namespace mxc::glsl {

enum Binding : uint32_t {
  kTablesBinding = 0,      ///< sampler2D: albedo tables (computed by the tables stage)
  kStageBinding = 1,       ///< uniform block of the stage (camera and lights, or batch sizes)
  /// The material's parameters (`--param`, frame, time): a read-only storage buffer in std140
  /// layout, which lavapipe never specialises a shader on (runtime/MaterialResources.cpp).
  kParameterBinding = 2,
  kInputBinding = 3,       ///< storage buffer read by compute stages
  kOutputBinding = 4,      ///< storage buffer written by compute stages
  kFirstTextureBinding = 5 ///< sampler2D per image file, in ExprEmitter order
};

/// The parameter block member (kParameterBinding) holding the "could not be read" bit of
/// texture k: a uint each for textures 0-31 (missing_textures), 32-63 (missing_textures_32) and
/// so on; its bit is k % 32. The harness sets it, the shader then uses the image node's default.
inline std::string missingTexturesMember(size_t k) {
  return k < 32 ? std::string("missing_textures") : "missing_textures_" + std::to_string(k / 32 * 32);
}
/// Whether a parameter block member is one of the missing_textures masks.
inline bool isMissingTexturesMember(const std::string& name) {
  return name == "missing_textures" || name.rfind("missing_textures_", 0) == 0;
}

/// Under MXC_SEPARATE_SAMPLERS (the WGSL target, which has no combined image sampler), the
/// sampler of the texture at binding b of a set is at binding b + kSeparateSamplerOffset of that
/// set. Below WebGPU's limit on binding numbers (maxBindingsPerBindGroup, 1000) with room for
/// every texture a material can name.
constexpr uint32_t kSeparateSamplerOffset = 512;

/// Texels per axis of each albedo table (view cosine across, roughness down).
constexpr uint32_t kTableSize = 32;
/// Number of dielectric reflection tables, one per IOR step (stages/mxc_tables.comp).
constexpr uint32_t kTableSlices = 32;
/// The rows the tables compute shader writes: the split-sum/sheen table, then the dielectric slices.
constexpr uint32_t kComputedTableHeight = kTableSize * (1 + kTableSlices);

/// The reference walk's tables (compiler/glsl/WalkTables.h; measured by
/// tools/GenerateWalkFits.cpp), rows of the same image under the computed ones. Their grids:
/// the relative IOR eta = (1 + u) / (1 - u) for u = 0.5 k / (kWalkEtaSteps - 1) (F0 = u^2 up to
/// 0.25: eta 1 to 3, densest near 1), Henyey-Greenstein g = -0.9 + 1.8 k / (kWalkAnisotropySteps - 1),
/// specular roughness k / (kWalkRoughnessSteps - 1).
constexpr uint32_t kWalkEtaSteps = 13;
constexpr uint32_t kWalkAnisotropySteps = 9;
constexpr uint32_t kWalkRoughnessSteps = 5;
/// kWalkEtaSteps rows, one per eta: across, the roughness k / (kTableSize - 1); .x the walk's
/// dielectric's internal diffuse reflectance r_i.
constexpr uint32_t kWalkGlossRow = kComputedTableHeight;
/// One row per (roughness, g, eta), eta fastest: across, the observed colour C = k /
/// (kTableSize - 1); .x van de Hulst's s of the medium the walk needs for that colour.
constexpr uint32_t kWalkMediumRow = kWalkGlossRow + kWalkEtaSteps;
/// kTableSize rows per eta (eta slowest): down, the roughness x = k / (kTableSize - 1) (alpha =
/// x^2); across, the view cosine mu = (k / (kTableSize - 1))^2, as the albedo tables; .x the
/// walk's dielectric's reflectance from outside, every order of scattering.
constexpr uint32_t kWalkReflectanceRow = kWalkMediumRow + kWalkEtaSteps * kWalkAnisotropySteps * kWalkRoughnessSteps;
constexpr uint32_t kWalkTableRows = kWalkReflectanceRow + kWalkEtaSteps * kTableSize - kWalkGlossRow;

/// The tables image: kTableSize wide, the computed tables then the walk's.
constexpr uint32_t kTableHeight = kComputedTableHeight + kWalkTableRows;

}  // namespace mxc::glsl
