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
};

uint32_t countOf(const Counts& counts, const Limit& limit) {
  return limit.count ? counts.*limit.count : counts.resources();
}

}  // namespace

std::optional<std::string> descriptorLimitProblem(const VkPhysicalDeviceLimits& limits, const std::string& device,
                                                  const std::vector<const DescriptorSet*>& sets) {
  static const Limit perStage[] = {
      {"samplers (one per texture)", &Counts::samplers, &VkPhysicalDeviceLimits::maxPerStageDescriptorSamplers},
      {"sampled images (one per texture)", &Counts::sampledImages, &VkPhysicalDeviceLimits::maxPerStageDescriptorSampledImages},
      {"uniform buffers", &Counts::uniformBuffers, &VkPhysicalDeviceLimits::maxPerStageDescriptorUniformBuffers},
      {"storage buffers", &Counts::storageBuffers, &VkPhysicalDeviceLimits::maxPerStageDescriptorStorageBuffers},
      {"storage images", &Counts::storageImages, &VkPhysicalDeviceLimits::maxPerStageDescriptorStorageImages},
      {"resources", nullptr, &VkPhysicalDeviceLimits::maxPerStageResources}};
  static const Limit perLayout[] = {
      {"samplers (one per texture)", &Counts::samplers, &VkPhysicalDeviceLimits::maxDescriptorSetSamplers},
      {"sampled images (one per texture)", &Counts::sampledImages, &VkPhysicalDeviceLimits::maxDescriptorSetSampledImages},
      {"uniform buffers", &Counts::uniformBuffers, &VkPhysicalDeviceLimits::maxDescriptorSetUniformBuffers},
      {"storage buffers", &Counts::storageBuffers, &VkPhysicalDeviceLimits::maxDescriptorSetStorageBuffers},
      {"storage images", &Counts::storageImages, &VkPhysicalDeviceLimits::maxDescriptorSetStorageImages}};
  static const std::pair<VkShaderStageFlagBits, const char*> stages[] = {
      {VK_SHADER_STAGE_VERTEX_BIT, "vertex"}, {VK_SHADER_STAGE_FRAGMENT_BIT, "fragment"}, {VK_SHADER_STAGE_COMPUTE_BIT, "compute"}};
  static const char* const names[] = {"maxPerStageDescriptorSamplers", "maxPerStageDescriptorSampledImages",
                                      "maxPerStageDescriptorUniformBuffers", "maxPerStageDescriptorStorageBuffers",
                                      "maxPerStageDescriptorStorageImages", "maxPerStageResources"};
  static const char* const layoutNames[] = {"maxDescriptorSetSamplers", "maxDescriptorSetSampledImages",
                                            "maxDescriptorSetUniformBuffers", "maxDescriptorSetStorageBuffers",
                                            "maxDescriptorSetStorageImages"};
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
                           stageName, need, perStage[k].what, device, limit, names[k], textures);
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
                         device, limit, layoutNames[k]);
    }
  }
  return std::nullopt;
}

void checkDescriptorLimits(const VulkanContext& context, const std::vector<const DescriptorSet*>& sets) {
  if (auto problem = descriptorLimitProblem(context.limits(), context.deviceName(), sets)) throw VulkanError(*problem);
}

}  // namespace mxc::rt
