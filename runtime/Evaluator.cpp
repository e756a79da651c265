#include "runtime/Evaluator.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "compiler/glsl/Contract.h"

namespace mxc::rt {

namespace {

constexpr uint32_t kGroup = glsl::kWorkGroupSize;  // local_size_x of the compute stages

}  // namespace

MaterialKernel::MaterialKernel(VulkanContext& context, const AlbedoTables& tables, const MaterialResources& resources,
                               const glsl::MaterialInterface& material, const std::vector<uint32_t>& spirv)
    : context_(context), samplesPerDispatch_(material.samplesPerDispatch ? material.samplesPerDispatch : UINT32_MAX) {
  kernel_ = std::make_unique<ComputeKernel>(context, spirv, MaterialResources::layout(material), 0);
  batch_ = context.createBuffer(glsl::std140Layout(glsl::batchMembers()).size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  resources.bind(kernel_->descriptors(), tables);
  kernel_->descriptors().bind(glsl::kStageBinding, batch_);
}

MaterialKernel::~MaterialKernel() {
  kernel_.reset();
  context_.destroy(batch_);
}

void MaterialKernel::run(const Buffer& in, const Buffer& out, uint32_t groups, uint32_t rows, uint32_t samples,
                         uint32_t seed) {
  // MxcBatch, through the contract's table (compiler/glsl/Contract.h).
  glsl::BlockWriter block(glsl::batchMembers());
  block.set("counts", glm::uvec4(rows, samples, seed, 0u));
  block.set("uv", glm::vec4(0.5f, 0.5f, 0.0f, 0.0f));
  std::memcpy(batch_.mapped, block.bytes().data(), block.bytes().size());
  kernel_->descriptors().bind(glsl::kInputBinding, in);
  kernel_->descriptors().bind(glsl::kOutputBinding, out);
  kernel_->dispatch(groups, 1, nullptr);
}

std::vector<glm::vec4> MaterialEvaluator::evaluate(const std::vector<DirectionPair>& pairs, uint32_t dispatches,
                                                   uint32_t seed) {
  if (pairs.empty()) return {};
  const size_t n = pairs.size();
  Buffer in = context_.createBuffer(n * 2 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  Buffer out = context_.createBuffer(n * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  auto* dirs = static_cast<glm::vec4*>(in.mapped);
  for (size_t i = 0; i < n; ++i) {
    dirs[2 * i] = glm::vec4(pairs[i].wo, 0.0f);
    dirs[2 * i + 1] = glm::vec4(pairs[i].wi, 0.0f);
  }
  dispatches = std::max<uint32_t>(dispatches, 1);
  std::vector<glm::dvec4> sum(n, glm::dvec4(0.0));
  for (uint32_t d = 0; d < dispatches; ++d) {
    run(in, out, static_cast<uint32_t>((n + kGroup - 1) / kGroup), static_cast<uint32_t>(n), 1, seed + d);
    const auto* values = static_cast<const glm::vec4*>(out.mapped);
    for (size_t i = 0; i < n; ++i) sum[i] += glm::dvec4(values[i]);
  }
  std::vector<glm::vec4> result(n);
  for (size_t i = 0; i < n; ++i) result[i] = glm::vec4(sum[i] / double(dispatches));
  context_.destroy(in);
  context_.destroy(out);
  return result;
}

std::vector<Albedo> FurnaceEstimator::estimate(const std::vector<glm::vec3>& views, uint32_t samples, uint32_t seed) {
  if (views.empty()) return {};
  const size_t n = views.size();
  const uint32_t perInvocation = std::max<uint32_t>((samples + kGroup - 1) / kGroup, 1);
  Buffer in = context_.createBuffer(n * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  Buffer out = context_.createBuffer(n * kGroup * 4 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  auto* dirs = static_cast<glm::vec4*>(in.mapped);
  for (size_t i = 0; i < n; ++i) dirs[i] = glm::vec4(views[i], 0.0f);
  std::vector<glm::dvec3> r(n, glm::dvec3(0.0)), t(n, glm::dvec3(0.0)), r2(n, glm::dvec3(0.0)), t2(n, glm::dvec3(0.0));
  uint32_t dispatch = 0;
  for (uint32_t done = 0; done < perInvocation; ++dispatch) {
    const uint32_t chunk = std::min(samplesPerDispatch_, perInvocation - done);
    // Each dispatch its own seed: seed + dispatch * 2^16 keeps seeds of different runs apart.
    run(in, out, static_cast<uint32_t>(n), static_cast<uint32_t>(n), chunk, seed + (dispatch << 16));
    const auto* sums = static_cast<const glm::vec4*>(out.mapped);
    for (size_t a = 0; a < n; ++a) {
      for (uint32_t i = 0; i < kGroup; ++i) {
        const glm::vec4* s = &sums[4 * (a * kGroup + i)];
        if (s[0].w != float(chunk)) {
          throw std::runtime_error(fmt::format(
              "the device cut the furnace's sampling loop ({} of {} samples drawn by an invocation)", s[0].w, chunk));
        }
        r[a] += glm::dvec3(s[0]);
        t[a] += glm::dvec3(s[1]);
        r2[a] += glm::dvec3(s[2]);
        t2[a] += glm::dvec3(s[3]);
      }
    }
    done += chunk;
  }
  std::vector<Albedo> result(n);
  const double count = double(perInvocation) * kGroup;
  // Mean and standard error of the mean: sqrt((E[x^2] - E[x]^2) / (N - 1)); count >= 64.
  auto error = [&](glm::dvec3 sum, glm::dvec3 squares) {
    glm::dvec3 mean = sum / count;
    glm::dvec3 variance = glm::max(squares / count - mean * mean, glm::dvec3(0.0));
    return glm::vec3(glm::sqrt(variance / (count - 1.0)));
  };
  for (size_t a = 0; a < n; ++a) {
    result[a].reflected = glm::vec3(r[a] / count);
    result[a].transmitted = glm::vec3(t[a] / count);
    result[a].reflectedError = error(r[a], r2[a]);
    result[a].transmittedError = error(t[a], t2[a]);
  }
  context_.destroy(in);
  context_.destroy(out);
  return result;
}

std::vector<std::vector<SampledDirection>> DirectionSampler::sample(const std::vector<glm::vec3>& views,
                                                                   uint32_t samples, uint32_t seed) {
  if (views.empty()) return {};
  const size_t n = views.size();
  const uint32_t perInvocation = std::max<uint32_t>((samples + kGroup - 1) / kGroup, 1);
  const size_t perView = size_t{perInvocation} * kGroup;
  Buffer in = context_.createBuffer(n * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  Buffer out = context_.createBuffer(n * perView * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  auto* dirs = static_cast<glm::vec4*>(in.mapped);
  for (size_t i = 0; i < n; ++i) dirs[i] = glm::vec4(views[i], 0.0f);
  run(in, out, static_cast<uint32_t>(n), static_cast<uint32_t>(n), perInvocation, seed);
  const auto* drawn = static_cast<const glm::vec4*>(out.mapped);
  std::vector<std::vector<SampledDirection>> result(n);
  for (size_t a = 0; a < n; ++a) {
    result[a].resize(perView);
    for (size_t i = 0; i < perView; ++i) {
      const glm::vec4& d = drawn[a * perView + i];
      // The stage writes kind 0, 1 or 2 exactly (mxc_sample.comp).
      result[a][i].wi = glm::vec3(d);
      result[a][i].kind = d.w > 1.5f   ? SampledDirection::Kind::Delta
                          : d.w > 0.5f ? SampledDirection::Kind::Continuous
                                       : SampledDirection::Kind::None;
    }
  }
  context_.destroy(in);
  context_.destroy(out);
  return result;
}

}  // namespace mxc::rt
