#include "runtime/TextureCache.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mxc::rt {

Texture::Texture(VulkanContext& context, Image image, std::vector<std::string> warnings, std::string error)
    : context_(context), image_(image), warnings_(std::move(warnings)), error_(std::move(error)) {}

Texture::~Texture() { context_.destroy(image_); }

std::vector<uint8_t> eightBitTexels(const RgbaImage& pixels, bool srgb) {
  // Back to the file's 8-bit code values: decoding and re-encoding sRGB round-trips each of
  // the 256 values (tests/runtime/TextureCacheTest.cpp). Alpha is never sRGB-encoded.
  std::vector<uint8_t> texels(pixels.pixels.size());
  for (size_t i = 0; i < texels.size(); ++i) {
    float v = std::clamp(pixels.pixels[i], 0.0f, 1.0f);
    if (srgb && i % 4 != 3) v = linearToSrgb(v);
    texels[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
  }
  return texels;
}

std::vector<float> floatTexels(const std::vector<uint8_t>& texels, bool srgb) {
  std::vector<float> pixels(texels.size());
  for (size_t i = 0; i < texels.size(); ++i) {
    const float v = float(texels[i]) / 255.0f;
    pixels[i] = srgb && i % 4 != 3 ? srgbToLinear(v) : v;
  }
  return pixels;
}

Image uploadTexture(VulkanContext& context, const RgbaImage& pixels, bool srgb) {
  // Textures carry their mip chain (VulkanContext::createTexture): the fragment shader samples
  // with the texture coordinate's screen derivatives, so a minified texture is filtered.
  const VkFormat eightBit = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  if (!pixels.texels.empty()) {
    Image image = context.createTexture(pixels.width, pixels.height,
                                        context.canSampleLinear(eightBit) ? eightBit : VK_FORMAT_R32G32B32A32_SFLOAT);
    if (image.format == eightBit) {
      context.upload(image, pixels.texels.data(), 4);
    } else {
      context.upload(image, floatTexels(pixels.texels, srgb).data());
    }
    return image;
  }
  if (pixels.eightBit && context.canSampleLinear(eightBit)) {
    const std::vector<uint8_t> texels = eightBitTexels(pixels, srgb);
    Image image = context.createTexture(pixels.width, pixels.height, eightBit);
    context.upload(image, texels.data(), 4);
    return image;
  }
  Image image = context.createTexture(pixels.width, pixels.height, VK_FORMAT_R32G32B32A32_SFLOAT);
  context.upload(image, pixels.pixels.data());
  return image;
}

namespace {

RgbaImage blackTexel() { return RgbaImage{1, 1, {0.0f, 0.0f, 0.0f, 1.0f}}; }

}  // namespace

std::shared_ptr<const Texture> TextureCache::placeholder() {
  if (!placeholder_) {
    placeholder_ = std::make_shared<const Texture>(context_, uploadTexture(context_, blackTexel(), false),
                                                   std::vector<std::string>{}, std::string{});
  }
  return placeholder_;
}

std::shared_ptr<const Texture> TextureCache::get(const std::filesystem::path& path, bool srgbDecode) {
  const std::pair<std::string, bool> key{path.lexically_normal().string(), srgbDecode};
  if (auto live = textures_[key].lock()) return live;
  ++reads_;
  ImageReadOptions options;
  options.maxDimension = context_.maxImageDimension2D();
  options.srgbDecode = srgbDecode;
  options.eightBitTexels = true;
  std::vector<std::string> warnings;
  auto read = readImage(path, options, &warnings);
  std::string error;
  RgbaImage pixels;
  if (auto* why = std::get_if<std::string>(&read)) {
    error = *why;
    pixels = blackTexel();
  } else {
    pixels = std::move(std::get<RgbaImage>(read));
  }
  // The image is uploaded in the file's encoding: the sampler decodes sRGB (where the read did)
  // before filtering, as the read's linear values were filtered.
  auto texture = std::make_shared<const Texture>(context_, uploadTexture(context_, pixels, srgbDecode),
                                                 std::move(warnings), std::move(error));
  textures_[key] = texture;
  return texture;
}

}  // namespace mxc::rt
