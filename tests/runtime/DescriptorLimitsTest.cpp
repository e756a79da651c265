// A pipeline layout beyond the device's descriptor limits is refused with the limit's name
// before Vulkan sees it: lavapipe (32 samplers per stage) crashed on a material of 40 textures.

#include "runtime/DescriptorLimits.h"

#include <gtest/gtest.h>

#include "runtime/ComputeKernel.h"

namespace mxc::rt {
namespace {

std::vector<VkDescriptorType> samplers(size_t n) { return std::vector<VkDescriptorType>(n, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER); }

TEST(DescriptorLimits, CountsEachStageAcrossTheSetsItSees) {
  VulkanContext context({"", true});
  VkPhysicalDeviceLimits limits = context.limits();
  limits.maxPerStageDescriptorSamplers = 8;
  limits.maxPerStageDescriptorSampledImages = 100;
  DescriptorSet material(context, samplers(5), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  DescriptorSet fragmentOnly(context, samplers(3), VK_SHADER_STAGE_FRAGMENT_BIT);
  EXPECT_FALSE(descriptorLimitProblem(limits, "dev", {&material, &fragmentOnly})) << "5 + 3 = 8 in the fragment stage fits";
  DescriptorSet more(context, samplers(4), VK_SHADER_STAGE_FRAGMENT_BIT);
  const auto problem = descriptorLimitProblem(limits, "dev", {&material, &more});
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->find("the fragment stage binds 9 samplers"), std::string::npos) << *problem;
  EXPECT_NE(problem->find("this device (dev) takes at most 8 per stage (maxPerStageDescriptorSamplers)"), std::string::npos)
      << *problem;

  limits.maxPerStageDescriptorSamplers = 100;
  limits.maxPerStageDescriptorSampledImages = 4;
  const auto images = descriptorLimitProblem(limits, "dev", {&material});
  ASSERT_TRUE(images);
  EXPECT_NE(images->find("5 sampled images"), std::string::npos) << *images;
  EXPECT_NE(images->find("maxPerStageDescriptorSampledImages"), std::string::npos) << *images;
}

TEST(DescriptorLimits, AComputeKernelBeyondTheDeviceIsRefusedNotCrashed) {
  VulkanContext context({"", true});
  const uint32_t limit = context.limits().maxPerStageDescriptorSamplers;
  ASSERT_LT(limit, 100000u) << "a device with a limit this test can reach";
  // The module is never made: the layout is checked first.
  EXPECT_THROW(
      {
        try {
          ComputeKernel kernel(context, {}, samplers(limit + 1), 0);
        } catch (const VulkanError& e) {
          EXPECT_NE(std::string(e.what()).find("maxPerStageDescriptorSamplers"), std::string::npos) << e.what();
          throw;
        }
      },
      VulkanError);
  EXPECT_TRUE(context.validationMessages().empty()) << context.validationMessages().front();
}

}  // namespace
}  // namespace mxc::rt
