#include "runtime/ComputeKernel.h"

#include "runtime/DescriptorLimits.h"

namespace mxc::rt {

ComputeKernel::ComputeKernel(VulkanContext& context, const std::vector<uint32_t>& spirv,
                             const std::vector<VkDescriptorType>& bindings, uint32_t pushConstantBytes)
    : context_(context), pushBytes_(pushConstantBytes) {
  descriptors_ = std::make_unique<DescriptorSet>(context, bindings, VK_SHADER_STAGE_COMPUTE_BIT);
  checkDescriptorLimits(context, {descriptors_.get()});  // lavapipe crashes on a layout beyond them
  module_ = std::make_unique<ShaderModule>(context, spirv);
  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
  VkDescriptorSetLayout setLayout = descriptors_->layout();
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = pushConstantBytes ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(context.device(), &layoutInfo, nullptr, &layout_), "vkCreatePipelineLayout");
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module_->get();
  info.stage.pName = "main";
  info.layout = layout_;
  check(vkCreateComputePipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline_),
        "vkCreateComputePipelines");
}

ComputeKernel::~ComputeKernel() {
  vkDestroyPipeline(context_.device(), pipeline_, nullptr);
  vkDestroyPipelineLayout(context_.device(), layout_, nullptr);
}

void ComputeKernel::dispatch(uint32_t groupsX, uint32_t groupsY, const void* push) {
  context_.submit([&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    VkDescriptorSet set = descriptors_->set();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
    if (pushBytes_ && push) vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_, push);
    vkCmdDispatch(cmd, groupsX, groupsY, 1);
  });
}

}  // namespace mxc::rt
