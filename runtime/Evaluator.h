#pragma once
/// \file
/// The compute BSDF evaluator: f(wo, wi) |cos theta_i| for batches of direction pairs, and the
/// directional albedo by Monte Carlo (the white furnace), returned to the host.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "runtime/ComputeKernel.h"
#include "runtime/MaterialResources.h"

namespace mxc::rt {

/// Directions are unit vectors in the local frame of a flat surface: normal +z, tangent +x.
struct DirectionPair {
  glm::vec3 wo;
  glm::vec3 wi;
};

/// A material's compute shader with its bindings: the tables, the material's resources, and
/// the batch block (compiler/glsl/stages/mxc_batch.glsl).
class MaterialKernel {
 public:
  MaterialKernel(VulkanContext& context, const AlbedoTables& tables, const MaterialResources& resources,
                 const glsl::MaterialInterface& material, const std::vector<uint32_t>& spirv);
  ~MaterialKernel();
  MaterialKernel(const MaterialKernel&) = delete;
  MaterialKernel& operator=(const MaterialKernel&) = delete;

 protected:
  /// Runs `groups` work groups over `in` (read) and `out` (written) with the batch counts.
  void run(const Buffer& in, const Buffer& out, uint32_t groups, uint32_t rows, uint32_t samples, uint32_t seed);

  VulkanContext& context_;
  /// Samples an invocation may draw per dispatch (no limit: UINT32_MAX).
  uint32_t samplesPerDispatch_ = UINT32_MAX;

 private:
  std::unique_ptr<ComputeKernel> kernel_;
  Buffer batch_;
};

/// Lavapipe (llvmpipe) ends a shader loop once it has run 65535 iterations in an invocation,
/// counted over every entry of that loop (gallivm's guard against infinite loops), and the
/// invocation then carries on as if the loop had finished: a long Monte Carlo loop is cut
/// silently. Shaders whose samples are long (the reference tier's walks) say how many samples an
/// invocation may draw per dispatch (MaterialInterface::samplesPerDispatch); more samples are
/// more dispatches, and the furnace checks that every invocation drew all of its own.
class MaterialEvaluator : MaterialKernel {
 public:
  /// `spirv`: the material's shader of kind glsl::ShaderKind::Eval.
  using MaterialKernel::MaterialKernel;
  /// Per pair: rgb = f(wo, wi) |wi.z|, a = the pdf of sampling wi from wo. `dispatches` > 1
  /// averages that many dispatches with different seeds (the reference tier's estimate of f cos
  /// is random; the other tiers' is not, and they use 1). Dispatch d uses the seed `seed + d`:
  /// calls whose seed ranges do not overlap are independent estimates.
  std::vector<glm::vec4> evaluate(const std::vector<DirectionPair>& pairs, uint32_t dispatches = 1,
                                  uint32_t seed = 1);
};

/// The directional albedo at one view direction, split into reflected (wi.z > 0) and
/// transmitted parts, with the standard error of each Monte Carlo mean.
struct Albedo {
  glm::vec3 reflected{0.0f};
  glm::vec3 transmitted{0.0f};
  glm::vec3 reflectedError{0.0f};
  glm::vec3 transmittedError{0.0f};
  glm::vec3 total() const { return reflected + transmitted; }
};

class FurnaceEstimator : MaterialKernel {
 public:
  /// `spirv`: the material's shader of kind glsl::ShaderKind::Furnace.
  using MaterialKernel::MaterialKernel;
  /// `samples` per view direction (rounded up to a multiple of 64 invocations), drawn in
  /// dispatches of at most the shader's samples per dispatch per invocation. Throws std::runtime_error when
  /// an invocation did not draw all of its samples (a loop cut by the device).
  std::vector<Albedo> estimate(const std::vector<glm::vec3>& views, uint32_t samples, uint32_t seed = 1);
};

/// One direction drawn by the closure's sampling.
struct SampledDirection {
  enum class Kind : uint8_t { None, Continuous, Delta };
  glm::vec3 wi{0.0f};
  Kind kind = Kind::None;  ///< Continuous: distributed with the closure's pdf; None: the draw failed
};

class DirectionSampler : MaterialKernel {
 public:
  /// `spirv`: the material's shader of kind glsl::ShaderKind::Sample.
  using MaterialKernel::MaterialKernel;
  /// `samples` directions per view (rounded up to a multiple of 64), view by view.
  std::vector<std::vector<SampledDirection>> sample(const std::vector<glm::vec3>& views, uint32_t samples,
                                                    uint32_t seed = 1);
};

}  // namespace mxc::rt
