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

/// A buffer destroyed when it goes out of scope, also when a dispatch throws.
struct OwnedBuffer {
  VulkanContext& context;
  Buffer buffer;
  OwnedBuffer(VulkanContext& c, Buffer b) : context(c), buffer(b) {}
  ~OwnedBuffer() { context.destroy(buffer); }
  OwnedBuffer(const OwnedBuffer&) = delete;
  OwnedBuffer& operator=(const OwnedBuffer&) = delete;
};

}  // namespace

MaterialKernel::MaterialKernel(VulkanContext& context, const AlbedoTables& tables, const MaterialResources& resources,
                               const glsl::MaterialInterface& material, const std::vector<uint32_t>& spirv)
    : context_(context),
      samplesPerDispatch_(std::min(material.samplesPerDispatch ? material.samplesPerDispatch : UINT32_MAX,
                                   kMaxSamplesPerDispatch)) {
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

uint32_t MaterialKernel::shrinkAfterCut(uint32_t drawn, uint32_t chunk, const char* what) {
  if (chunk <= 1) {
    throw std::runtime_error(
        fmt::format("the device cut the {}'s loop at its first sample (its loops run too long for the device)", what));
  }
  // The guard counts loop iterations: half of what an invocation drew keeps clear of it however
  // the samples' lengths vary (the lobe choice stops at the lobe it picks).
  samplesPerDispatch_ = std::clamp<uint32_t>(drawn / 2, 1u, chunk - 1);
  return samplesPerDispatch_;
}

std::vector<glm::vec4> MaterialEvaluator::evaluate(const std::vector<DirectionPair>& pairs, uint32_t dispatches,
                                                   uint32_t seed) {
  if (pairs.empty()) return {};
  const size_t n = pairs.size();
  OwnedBuffer inBuffer(context_, context_.createBuffer(n * 2 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  OwnedBuffer outBuffer(context_, context_.createBuffer(n * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  const Buffer& in = inBuffer.buffer;
  const Buffer& out = outBuffer.buffer;
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
  return result;
}

std::vector<Albedo> FurnaceEstimator::estimate(const std::vector<glm::vec3>& views, uint32_t samples, uint32_t seed) {
  if (views.empty()) return {};
  const size_t n = views.size();
  const uint32_t perInvocation = std::max<uint32_t>((samples + kGroup - 1) / kGroup, 1);
  OwnedBuffer inBuffer(context_, context_.createBuffer(n * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  OwnedBuffer outBuffer(context_,
                        context_.createBuffer(n * kGroup * 4 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  const Buffer& in = inBuffer.buffer;
  const Buffer& out = outBuffer.buffer;
  auto* dirs = static_cast<glm::vec4*>(in.mapped);
  for (size_t i = 0; i < n; ++i) dirs[i] = glm::vec4(views[i], 0.0f);
  std::vector<glm::dvec3> r(n, glm::dvec3(0.0)), t(n, glm::dvec3(0.0)), r2(n, glm::dvec3(0.0)), t2(n, glm::dvec3(0.0));
  uint32_t dispatch = 0;
  for (uint32_t done = 0; done < perInvocation; ++dispatch) {
    const uint32_t chunk = std::min(samplesPerDispatch_, perInvocation - done);
    // Each dispatch its own seed: seed + dispatch * 2^16 keeps seeds of different runs apart (a
    // dispatch run again after a cut takes the next seed).
    run(in, out, static_cast<uint32_t>(n), static_cast<uint32_t>(n), chunk, seed + (dispatch << 16));
    const auto* sums = static_cast<const glm::vec4*>(out.mapped);
    float fewest = float(chunk);
    for (size_t i = 0; i < n * kGroup; ++i) fewest = std::min(fewest, sums[4 * i].w);
    if (fewest != float(chunk)) {
      shrinkAfterCut(static_cast<uint32_t>(std::max(fewest, 0.0f)), chunk, "furnace");
      continue;  // nothing of the cut dispatch is kept
    }
    for (size_t a = 0; a < n; ++a) {
      for (uint32_t i = 0; i < kGroup; ++i) {
        const glm::vec4* s = &sums[4 * (a * kGroup + i)];
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
  return result;
}

std::vector<std::vector<SampledDirection>> DirectionSampler::sample(const std::vector<glm::vec3>& views,
                                                                   uint32_t samples, uint32_t seed) {
  if (views.empty()) return {};
  const size_t n = views.size();
  const uint32_t perInvocation = std::max<uint32_t>((samples + kGroup - 1) / kGroup, 1);
  OwnedBuffer inBuffer(context_, context_.createBuffer(n * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
  const Buffer& in = inBuffer.buffer;
  auto* dirs = static_cast<glm::vec4*>(in.mapped);
  for (size_t i = 0; i < n; ++i) dirs[i] = glm::vec4(views[i], 0.0f);
  std::vector<std::vector<SampledDirection>> result(n);
  for (auto& r : result) r.reserve(size_t{perInvocation} * kGroup);
  // The stage writes kind 0, 1 or 2 exactly (mxc_sample.comp); a slot still holding this after
  // the dispatch was not reached: the device cut the invocation's loop.
  constexpr float kUnwritten = -1.0f;
  OwnedBuffer outBuffer(context_, Buffer{});
  Buffer& out = outBuffer.buffer;
  size_t outSlots = 0;
  uint32_t dispatch = 0;
  for (uint32_t done = 0; done < perInvocation; ++dispatch) {
    const uint32_t chunk = std::min(samplesPerDispatch_, perInvocation - done);
    const size_t slots = n * kGroup * chunk;
    if (slots > outSlots) {
      context_.destroy(out);
      out = context_.createBuffer(slots * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      outSlots = slots;
    }
    auto* drawn = static_cast<glm::vec4*>(out.mapped);
    std::fill(drawn, drawn + slots, glm::vec4(0.0f, 0.0f, 0.0f, kUnwritten));
    // Seeds as the furnace's: seed + dispatch * 2^16.
    run(in, out, static_cast<uint32_t>(n), static_cast<uint32_t>(n), chunk, seed + (dispatch << 16));
    // Invocation i wrote slots [i chunk, (i + 1) chunk) in order: the first unwritten one is
    // how many it drew.
    uint32_t fewest = chunk;
    for (size_t i = 0; i < n * kGroup && fewest == chunk; ++i) {
      for (uint32_t s = 0; s < chunk; ++s) {
        if (drawn[i * chunk + s].w == kUnwritten) {
          fewest = std::min(fewest, s);
          break;
        }
      }
    }
    if (fewest != chunk) {
      shrinkAfterCut(fewest, chunk, "sampler");
      continue;  // nothing of the cut dispatch is kept
    }
    for (size_t a = 0; a < n; ++a) {
      for (size_t i = 0; i < size_t{kGroup} * chunk; ++i) {
        const glm::vec4& d = drawn[a * kGroup * chunk + i];
        SampledDirection sampled;
        sampled.wi = glm::vec3(d);
        sampled.kind = d.w > 1.5f   ? SampledDirection::Kind::Delta
                       : d.w > 0.5f ? SampledDirection::Kind::Continuous
                                    : SampledDirection::Kind::None;
        result[a].push_back(sampled);
      }
    }
    done += chunk;
  }
  return result;
}

}  // namespace mxc::rt
