#pragma once
/// \file
/// A compute pipeline with one descriptor set and push constants.

#include <memory>
#include <vector>

#include "runtime/Descriptors.h"

namespace mxc::rt {

class ComputeKernel {
 public:
  ComputeKernel(VulkanContext& context, const std::vector<uint32_t>& spirv, const std::vector<VkDescriptorType>& bindings,
                uint32_t pushConstantBytes);
  ~ComputeKernel();
  ComputeKernel(const ComputeKernel&) = delete;
  ComputeKernel& operator=(const ComputeKernel&) = delete;

  DescriptorSet& descriptors() { return *descriptors_; }
  /// Dispatches `groups` work groups and waits for them; `push` holds the push constants.
  void dispatch(uint32_t groupsX, uint32_t groupsY, const void* push);

 private:
  VulkanContext& context_;
  std::unique_ptr<DescriptorSet> descriptors_;
  std::unique_ptr<ShaderModule> module_;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  uint32_t pushBytes_ = 0;
};

}  // namespace mxc::rt
