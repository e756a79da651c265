#include "runtime/Descriptors.h"

#include <map>

namespace mxc::rt {

DescriptorSet::DescriptorSet(VulkanContext& context, const std::vector<VkDescriptorType>& types,
                             VkShaderStageFlags stages)
    : context_(context), types_(types), stages_(stages) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  std::map<VkDescriptorType, uint32_t> counts;
  for (uint32_t i = 0; i < types.size(); ++i) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = i;
    b.descriptorType = types[i];
    b.descriptorCount = 1;
    b.stageFlags = stages;
    bindings.push_back(b);
    ++counts[types[i]];
  }
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(context.device(), &info, nullptr, &layout_), "vkCreateDescriptorSetLayout");
  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : counts) sizes.push_back({type, count});
  if (sizes.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1});
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.maxSets = 1;
  pool.poolSizeCount = static_cast<uint32_t>(sizes.size());
  pool.pPoolSizes = sizes.data();
  check(vkCreateDescriptorPool(context.device(), &pool, nullptr, &pool_), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout_;
  check(vkAllocateDescriptorSets(context.device(), &alloc, &set_), "vkAllocateDescriptorSets");
}

DescriptorSet::~DescriptorSet() {
  vkDestroyDescriptorPool(context_.device(), pool_, nullptr);
  vkDestroyDescriptorSetLayout(context_.device(), layout_, nullptr);
}

void DescriptorSet::bind(uint32_t binding, const Buffer& buffer) {
  VkDescriptorBufferInfo info{buffer.buffer, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set_;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = types_.at(binding);
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
}

void DescriptorSet::bind(uint32_t binding, const Image& image) {
  VkDescriptorImageInfo info{image.sampler, image.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  if (types_.at(binding) == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE) info.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set_;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = types_.at(binding);
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(context_.device(), 1, &write, 0, nullptr);
}

ShaderModule::ShaderModule(VulkanContext& context, const std::vector<uint32_t>& words) : context_(context) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = words.size() * sizeof(uint32_t);
  info.pCode = words.data();
  check(vkCreateShaderModule(context.device(), &info, nullptr, &module_), "vkCreateShaderModule");
}

ShaderModule::~ShaderModule() { vkDestroyShaderModule(context_.device(), module_, nullptr); }

}  // namespace mxc::rt
