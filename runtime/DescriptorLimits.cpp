#include "runtime/DescriptorLimits.h"

#include <fmt/format.h>

namespace mxc::rt {
namespace {

/// Descriptors of a stage (or of the whole layout), counted as the limits count them: a
/// combined image sampler is one sampler and one sampled image (Vulkan 1.3, s. 14.2.2).
struct Counts {
  uint32_t samplers = 0, sampledImages = 0, uniformBuffers = 0, storageBuffers = 0, storageImages = 0;
  uint32_t resources() const { return sampledImages + uniformBuffers + storageBuffers + storageImages; }
  void add(VkDescriptorType type) {
    switch (type) {
      case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: ++samplers, ++sampledImages; break;
      case VK_DESCRIPTOR_TYPE_SAMPLER: ++samplers; break;
      case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: ++sampledImages; break;
      case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: ++uniformBuffers; break;
      case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: ++storageBuffers; break;
      case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: ++storageImages; break;
      default: break;
    }
  }
};

struct Limit {
  const char* what;
  uint32_t Counts::*count;  // nullptr: resources()
  uint32_t VkPhysicalDeviceLimits::*limit;
  const char* name;  // the member's name, for the message
};

uint32_t countOf(const Counts& counts, const Limit& limit) {
  return limit.count ? counts.*limit.count : counts.resources();
}

}  // namespace

// A limit's member and its name, written once.
#define MXC_LIMIT(member) &VkPhysicalDeviceLimits::member, #member

std::optional<std::string> descriptorLimitProblem(const VkPhysicalDeviceLimits& limits, const std::string& device,
                                                  const std::vector<const DescriptorSet*>& sets) {
  static const Limit perStage[] = {
      {"samplers (one per texture)", &Counts::samplers, MXC_LIMIT(maxPerStageDescriptorSamplers)},
      {"sampled images (one per texture)", &Counts::sampledImages, MXC_LIMIT(maxPerStageDescriptorSampledImages)},
      {"uniform buffers", &Counts::uniformBuffers, MXC_LIMIT(maxPerStageDescriptorUniformBuffers)},
      {"storage buffers", &Counts::storageBuffers, MXC_LIMIT(maxPerStageDescriptorStorageBuffers)},
      {"storage images", &Counts::storageImages, MXC_LIMIT(maxPerStageDescriptorStorageImages)},
      {"resources", nullptr, MXC_LIMIT(maxPerStageResources)}};
  static const Limit perLayout[] = {
      {"samplers (one per texture)", &Counts::samplers, MXC_LIMIT(maxDescriptorSetSamplers)},
      {"sampled images (one per texture)", &Counts::sampledImages, MXC_LIMIT(maxDescriptorSetSampledImages)},
      {"uniform buffers", &Counts::uniformBuffers, MXC_LIMIT(maxDescriptorSetUniformBuffers)},
      {"storage buffers", &Counts::storageBuffers, MXC_LIMIT(maxDescriptorSetStorageBuffers)},
      {"storage images", &Counts::storageImages, MXC_LIMIT(maxDescriptorSetStorageImages)}};
#undef MXC_LIMIT
  static const std::pair<VkShaderStageFlagBits, const char*> stages[] = {
      {VK_SHADER_STAGE_VERTEX_BIT, "vertex"}, {VK_SHADER_STAGE_FRAGMENT_BIT, "fragment"}, {VK_SHADER_STAGE_COMPUTE_BIT, "compute"}};
  // Textures are the descriptors a material adds: their count is what a message can tell the
  // user to change.
  uint32_t textures = 0;
  for (const DescriptorSet* set : sets) {
    for (VkDescriptorType type : set->types()) textures += type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  }
  for (const auto& [stage, stageName] : stages) {
    Counts counts;
    for (const DescriptorSet* set : sets) {
      if (!(set->stages() & stage)) continue;
      for (VkDescriptorType type : set->types()) counts.add(type);
    }
    for (size_t k = 0; k < std::size(perStage); ++k) {
      const uint32_t need = countOf(counts, perStage[k]), limit = limits.*perStage[k].limit;
      if (need > limit) {
        return fmt::format("the {} stage binds {} {}, and this device ({}) takes at most {} per stage ({}): the "
                           "material reads too many textures (the pipeline binds {}, mxc's own among them)",
                           stageName, need, perStage[k].what, device, limit, perStage[k].name, textures);
      }
    }
  }
  Counts all;
  for (const DescriptorSet* set : sets) {
    for (VkDescriptorType type : set->types()) all.add(type);
  }
  for (size_t k = 0; k < std::size(perLayout); ++k) {
    const uint32_t need = countOf(all, perLayout[k]), limit = limits.*perLayout[k].limit;
    if (need > limit) {
      return fmt::format("the pipeline binds {} {}, and this device ({}) takes at most {} ({})", need, perLayout[k].what,
                         device, limit, perLayout[k].name);
    }
  }
  return std::nullopt;
}

void checkDescriptorLimits(const VulkanContext& context, const std::vector<const DescriptorSet*>& sets) {
  if (auto problem = descriptorLimitProblem(context.limits(), context.deviceName(), sets)) throw VulkanError(*problem);
}

}  // namespace mxc::rt
