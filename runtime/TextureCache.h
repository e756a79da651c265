#pragma once
/// \file
/// Textures on the device, read once per process: materials that read the same file the same
/// way (a document's materials sharing a wood grain, a scene's many materials) share one image.
/// An 8-bit file stays 8 bits on the device (sRGB-encoded ones in an sRGB format, decoded to
/// linear by the sampler before filtering): a quarter of the memory of floats.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "runtime/ImageIO.h"
#include "runtime/VulkanContext.h"

namespace mxc::rt {

/// One texture file as read: its image on the device, or why it could not be read.
class Texture {
 public:
  Texture(VulkanContext& context, Image image, std::vector<std::string> warnings, std::string error);
  ~Texture();
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  /// The image: the file's texels, or one black texel when the file could not be read.
  const Image& image() const { return image_; }
  /// What reading it reported (downsampled, damaged); every material using it reports them.
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// Why it could not be read; empty when it was.
  const std::string& error() const { return error_; }

 private:
  VulkanContext& context_;
  Image image_;
  std::vector<std::string> warnings_;
  std::string error_;
};

/// The textures in use, by file and colour decoding. Holds them weakly: a texture lives while a
/// material holds it, and a later request for the same file after that reads it again.
class TextureCache {
 public:
  explicit TextureCache(VulkanContext& context) : context_(context) {}

  /// The texture of `path` (a regular file or a missing one: the caller checks), decoded from
  /// sRGB to linear when `srgbDecode`, read now unless a live texture has it already.
  std::shared_ptr<const Texture> get(const std::filesystem::path& path, bool srgbDecode);

  /// One black texel, what an image node without a readable file samples (the shader then
  /// uses the node's default: MaterialResources' missing_textures); made once per cache.
  std::shared_ptr<const Texture> placeholder();

  /// How many files were read (not found in the cache).
  size_t reads() const { return reads_; }

 private:
  VulkanContext& context_;
  std::shared_ptr<const Texture> placeholder_;
  std::map<std::pair<std::string, bool>, std::weak_ptr<const Texture>> textures_;
  size_t reads_ = 0;
};

/// The 8-bit texels of `pixels` (RGBA, values clamped to [0, 1]), sRGB-encoded when `srgb`
/// (alpha stays linear).
std::vector<uint8_t> eightBitTexels(const RgbaImage& pixels, bool srgb);

/// RGBA floats of 8-bit texels, decoded from sRGB when `srgb` (alpha stays linear): for a
/// device that cannot sample an 8-bit format.
std::vector<float> floatTexels(const std::vector<uint8_t>& texels, bool srgb);

/// The device image of `pixels`: 8 bits per channel when they came from an 8-bit file (as its
/// code values, RgbaImage::texels, or as floats holding them) and the device samples such
/// images (sRGB-encoded when `srgb`), otherwise 32-bit floats.
Image uploadTexture(VulkanContext& context, const RgbaImage& pixels, bool srgb);

}  // namespace mxc::rt
