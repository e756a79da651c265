#include "runtime/AlbedoTables.h"

#include <cstring>
#include <stdexcept>

#include "compiler/glsl/AlbedoTableFile.h"
#include "compiler/glsl/Contract.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "runtime/ComputeKernel.h"

namespace mxc::rt {

AlbedoTables::AlbedoTables(VulkanContext& context) : context_(context) {
  values_ = glsl::committedAlbedoTables().texels;  // throws when the committed file is unusable
  image_ = context.createImage(glsl::kTableSize, glsl::kTableHeight, VK_FORMAT_R32G32B32A32_SFLOAT,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  context.upload(image_, values_.data());
}

AlbedoTables::AlbedoTables(VulkanContext& context, std::vector<float> texels) : context_(context), values_(std::move(texels)) {
  if (values_.size() != size_t{glsl::kTableSize} * glsl::kTableHeight * 4) {
    throw std::invalid_argument("the albedo tables are not kTableSize x kTableHeight RGBA");
  }
  image_ = context.createImage(glsl::kTableSize, glsl::kTableHeight, VK_FORMAT_R32G32B32A32_SFLOAT,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  context.upload(image_, values_.data());
}

AlbedoTables::~AlbedoTables() { context_.destroy(image_); }

std::vector<float> AlbedoTables::compute(VulkanContext& context) {
  Diagnostics diagnostics;
  auto words = spirv::compile(glsl::buildTablesShader(), {}, diagnostics);
  if (!words) throw VulkanError("the albedo tables shader does not compile:\n" + diagnostics.format());
  const uint32_t n = glsl::kTableSize;
  const uint32_t rows = glsl::kComputedTableHeight;  // the walk's rows are measured, not computed here
  Buffer out = context.createBuffer(VkDeviceSize{n} * rows * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::vector<float> values(size_t{n} * rows * 4);
  {
    ComputeKernel kernel(context, *words, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, 0);
    kernel.descriptors().bind(glsl::kTablesOutputBinding, out);
    const uint32_t g = glsl::kTablesGroupSize;
    kernel.dispatch((n + g - 1) / g, (rows + g - 1) / g, nullptr);
  }
  std::memcpy(values.data(), out.mapped, values.size() * sizeof(float));
  context.destroy(out);
  return values;
}

}  // namespace mxc::rt
