#pragma once
/// \file
/// One descriptor set of buffers and sampled images, with its layout and pool.

#include <vector>

#include "runtime/VulkanContext.h"

namespace mxc::rt {

/// Bindings 0..n-1 of set 0, each of the given type, visible to `stages`.
class DescriptorSet {
 public:
  DescriptorSet(VulkanContext& context, const std::vector<VkDescriptorType>& types, VkShaderStageFlags stages);
  ~DescriptorSet();
  DescriptorSet(const DescriptorSet&) = delete;
  DescriptorSet& operator=(const DescriptorSet&) = delete;

  void bind(uint32_t binding, const Buffer& buffer);
  void bind(uint32_t binding, const Image& image);
  VkDescriptorSetLayout layout() const { return layout_; }
  /// What the layout was made of (two sets with equal types and stages have compatible layouts).
  const std::vector<VkDescriptorType>& types() const { return types_; }
  VkShaderStageFlags stages() const { return stages_; }
  VkDescriptorSet set() const { return set_; }

 private:
  VulkanContext& context_;
  std::vector<VkDescriptorType> types_;
  VkShaderStageFlags stages_ = 0;
  VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

/// A shader module from SPIR-V words (destroyed with the object).
class ShaderModule {
 public:
  ShaderModule(VulkanContext& context, const std::vector<uint32_t>& words);
  ~ShaderModule();
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;
  VkShaderModule get() const { return module_; }

 private:
  VulkanContext& context_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace mxc::rt
