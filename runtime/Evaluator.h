#pragma once
/// \file
/// The compute BSDF evaluator: f(wo, wi) |cos theta_i| for batches of direction pairs, and the
/// directional albedo by Monte Carlo (the white furnace), returned to the host.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "runtime/ComputeKernel.h"
#include "runtime/MaterialResources.h"

namespace mxc::rt {

/// The most samples one invocation of a compute stage draws in one dispatch (MaterialKernel).
inline constexpr uint32_t kMaxSamplesPerDispatch = 1024;

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

  /// The most samples an invocation draws per dispatch (the default: the shader's own limit, at
  /// most kMaxSamplesPerDispatch). A device without lavapipe's loop guard may take more; a
  /// dispatch the device cuts is run again smaller whatever is asked.
  void setSamplesPerDispatch(uint32_t samples) { samplesPerDispatch_ = std::max<uint32_t>(samples, 1); }

 protected:
  /// Runs `groups` work groups over `in` (read) and `out` (written) with the batch counts.
  void run(const Buffer& in, const Buffer& out, uint32_t groups, uint32_t rows, uint32_t samples, uint32_t seed);

  /// After a dispatch in which an invocation drew only `drawn` of its `chunk` samples (a loop
  /// cut by the device, below): the samples an invocation may draw per dispatch from now on,
  /// half of what it managed, so that the dispatch can be run again whole. Throws
  /// std::runtime_error when even one sample per dispatch was cut (`what` names the stage).
  uint32_t shrinkAfterCut(uint32_t drawn, uint32_t chunk, const char* what);

  VulkanContext& context_;
  /// Samples an invocation may draw per dispatch: the shader's own limit, at most
  /// kMaxSamplesPerDispatch, lowered further by shrinkAfterCut.
  uint32_t samplesPerDispatch_ = UINT32_MAX;

 private:
  std::unique_ptr<ComputeKernel> kernel_;
  Buffer batch_;
};

/// Lavapipe (llvmpipe) ends a shader loop once it has run 65535 iterations in an invocation,
/// counted over every entry of that loop and of the loops nested in it (gallivm's guard against
/// infinite loops; a sample of a closure runs its lobe loops inside the stage's sample loop), and
/// the invocation then carries on as if the loop had finished: a long Monte Carlo loop is cut
/// silently. So an invocation draws at most kMaxSamplesPerDispatch samples per dispatch (a
/// sample may then run 64 loop iterations), shaders whose samples are long (the reference tier's
/// walks) say how many they may draw (MaterialInterface::samplesPerDispatch), more samples are
/// more dispatches, and the furnace and the sampler check that every invocation drew all of its
/// own: a dispatch that was cut is run again with half the samples its invocations managed.
class MaterialEvaluator : MaterialKernel {
 public:
  using MaterialKernel::setSamplesPerDispatch;
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
  using MaterialKernel::setSamplesPerDispatch;
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
  using MaterialKernel::setSamplesPerDispatch;
  /// `spirv`: the material's shader of kind glsl::ShaderKind::Sample.
  using MaterialKernel::MaterialKernel;
  /// `samples` directions per view (rounded up to a multiple of 64), view by view.
  std::vector<std::vector<SampledDirection>> sample(const std::vector<glm::vec3>& views, uint32_t samples,
                                                    uint32_t seed = 1);
};

}  // namespace mxc::rt
