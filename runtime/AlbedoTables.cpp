#include "runtime/AlbedoTables.h"

#include <cstring>

#include "compiler/glsl/Contract.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "runtime/ComputeKernel.h"

namespace mxc::rt {

AlbedoTables::AlbedoTables(VulkanContext& context) : context_(context) {
  Diagnostics diagnostics;
  auto words = spirv::compile(glsl::buildTablesShader(), {}, diagnostics);
  if (!words) throw VulkanError("the albedo tables shader does not compile:\n" + diagnostics.format());
  const uint32_t n = glsl::kTableSize;
  const uint32_t rows = glsl::kTableHeight;
  Buffer out = context.createBuffer(VkDeviceSize{n} * rows * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  {
    ComputeKernel kernel(context, *words, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, 0);
    kernel.descriptors().bind(glsl::kTablesOutputBinding, out);
    const uint32_t g = glsl::kTablesGroupSize;
    kernel.dispatch((n + g - 1) / g, (rows + g - 1) / g, nullptr);
  }
  values_.resize(size_t{n} * rows * 4);
  std::memcpy(values_.data(), out.mapped, values_.size() * sizeof(float));
  context.destroy(out);
  image_ = context.createImage(n, rows, VK_FORMAT_R32G32B32A32_SFLOAT,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  context.upload(image_, values_.data());
}

AlbedoTables::~AlbedoTables() { context_.destroy(image_); }

}  // namespace mxc::rt
