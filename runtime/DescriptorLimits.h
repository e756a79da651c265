#pragma once
/// \file
/// Whether a pipeline's descriptor sets fit the device: a layout beyond
/// maxPerStageDescriptorSamplers and its kin is invalid (Vulkan 1.3, s. 14.2.2, "Pipeline
/// Layouts"), and lavapipe crashes on one rather than failing, so every pipeline is checked
/// before it is made.

#include <optional>
#include <string>
#include <vector>

#include "runtime/Descriptors.h"

namespace mxc::rt {

/// What a pipeline of `sets` needs beyond the device's per-stage and per-layout descriptor
/// limits, naming the stage, the count, the limit and its value; nothing when it fits.
std::optional<std::string> descriptorLimitProblem(const VkPhysicalDeviceLimits& limits, const std::string& device,
                                                  const std::vector<const DescriptorSet*>& sets);

/// Throws VulkanError with descriptorLimitProblem's message when there is one.
void checkDescriptorLimits(const VulkanContext& context, const std::vector<const DescriptorSet*>& sets);

}  // namespace mxc::rt
