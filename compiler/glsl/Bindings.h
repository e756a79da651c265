#pragma once
/// \file
/// The descriptor bindings (set 0) shared by every generated shader and the Vulkan harness that
/// runs it. The harness binds what a stage declares; unused bindings are simply absent.

#include <cstdint>

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

/// Under MXC_SEPARATE_SAMPLERS (the WGSL target, which has no combined image sampler), the
/// sampler of the texture at binding b of a set is at binding b + kSeparateSamplerOffset of that
/// set. Below WebGPU's limit on binding numbers (maxBindingsPerBindGroup, 1000) with room for
/// every texture a material can name.
constexpr uint32_t kSeparateSamplerOffset = 512;

/// Texels per axis of each albedo table (view cosine across, roughness down).
constexpr uint32_t kTableSize = 32;
/// Number of dielectric reflection tables, one per IOR step (stages/mxc_tables.comp).
constexpr uint32_t kTableSlices = 32;
/// The tables image: kTableSize wide, the split-sum/sheen table then the dielectric slices below.
constexpr uint32_t kTableHeight = kTableSize * (1 + kTableSlices);

}  // namespace mxc::glsl
