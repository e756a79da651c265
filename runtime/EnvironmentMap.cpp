#include "runtime/EnvironmentMap.h"

#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "compiler/common/Diagnostic.h"
#include "compiler/glsl/Contract.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "runtime/ComputeKernel.h"

namespace mxc::rt {

std::variant<RgbaImage, std::string> EnvironmentMap::read(const std::filesystem::path& path, uint32_t maxDimension,
                                                          std::vector<std::string>& warnings) {
  ImageReadOptions options;
  options.maxDimension = maxDimension;
  auto read = readImage(path, options, &warnings);
  if (auto* error = std::get_if<std::string>(&read)) return *error;
  RgbaImage image = std::move(std::get<RgbaImage>(read));
  const double aspect = double(image.width) / double(image.height);  // readImage gives >= 1 x 1
  if (aspect < 1.8 || aspect > 2.2) {  // cube crosses (4:3, 3:4) and mirror balls (1:1) are refused
    return fmt::format("{}: {}x{} is not an equirectangular (latitude-longitude) image, which is twice as wide as high",
                       path.string(), image.width, image.height);
  }
  size_t bad = 0;
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    for (int c = 0; c < 3; ++c) {
      float& v = image.pixels[i + c];
      if (!std::isfinite(v)) ++bad;
      else if (v < 0.0f) v = 0.0f;
    }
    image.pixels[i + 3] = 1.0f;  // the environment is opaque; its alpha is not light
  }
  if (bad > 0) return fmt::format("{}: {} values are NaN or infinite", path.string(), bad);
  return image;
}

EnvironmentMap::EnvironmentMap(VulkanContext& context, RgbaImage radiance)
    : context_(context), radiance_(std::move(radiance)) {
  if (radiance_.width == 0 || radiance_.height == 0) radiance_ = RgbaImage{1, 1, {0.0f, 0.0f, 0.0f, 1.0f}};
  distribution_ = EnvironmentDistribution::build(radiance_);
  // Across, the image wraps around (u = 0 and 1 are the same longitude); down it ends at the poles.
  image_ = context.createImage(radiance_.width, radiance_.height, VK_FORMAT_R32G32B32A32_SFLOAT,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               VK_SAMPLER_ADDRESS_MODE_REPEAT, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
  context.upload(image_, radiance_.pixels.data());
  const std::vector<uint8_t> bytes = distribution_.bufferBytes();
  buffer_ = context.createBuffer(bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::memcpy(buffer_.mapped, bytes.data(), bytes.size());
  set_ = std::make_unique<DescriptorSet>(
      context, std::vector<VkDescriptorType>{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
      VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT);
  static_assert(glsl::kEnvironmentRadianceBinding == 0 && glsl::kEnvironmentDistributionBinding == 1,
                "the set's types above are in binding order");
  set_->bind(glsl::kEnvironmentRadianceBinding, image_);
  set_->bind(glsl::kEnvironmentDistributionBinding, buffer_);
}

EnvironmentMap::~EnvironmentMap() {
  set_.reset();
  context_.destroy(buffer_);
  context_.destroy(image_);
}

std::vector<EnvironmentMap::Drawn> EnvironmentMap::sample(uint32_t count, uint32_t seed) const {
  Diagnostics diagnostics;
  auto words = spirv::compile(glsl::buildEnvironmentSampleShader(), {}, diagnostics);
  if (!words) throw VulkanError("the environment sampling shader does not compile:\n" + diagnostics.format());
  static_assert(glsl::kEnvironmentSampleOutputBinding == 2, "the kernel's bindings are radiance, distribution, output");
  ComputeKernel kernel(context_, *words,
                       {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                        VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                       8);
  Buffer out = context_.createBuffer(VkDeviceSize{count} * 2 * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  kernel.descriptors().bind(glsl::kEnvironmentRadianceBinding, image_);
  kernel.descriptors().bind(glsl::kEnvironmentDistributionBinding, buffer_);
  kernel.descriptors().bind(glsl::kEnvironmentSampleOutputBinding, out);
  const uint32_t push[2] = {count, seed};
  kernel.dispatch((count + 63) / 64, 1, push);  // local_size_x = 64
  std::vector<Drawn> drawn(count);
  const auto* values = static_cast<const glm::vec4*>(out.mapped);
  for (uint32_t i = 0; i < count; ++i) drawn[i] = {values[i], values[count + i].x};
  context_.destroy(out);
  return drawn;
}

}  // namespace mxc::rt
