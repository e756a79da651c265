#pragma once
/// \file
/// Image files through OpenImageIO: textures in, rendered images out. EXR keeps linear floats;
/// 8-bit formats (PNG, JPEG, ...) get a tone-mapped, sRGB-encoded image.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace mxc::rt {

/// RGBA floats, top row first.
struct RgbaImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> pixels;
  float* at(uint32_t x, uint32_t y) { return &pixels[(size_t{y} * width + x) * 4]; }
  const float* at(uint32_t x, uint32_t y) const { return &pixels[(size_t{y} * width + x) * 4]; }
};

/// Reads any format OpenImageIO reads, as RGBA: one channel becomes grey, two are grey and
/// alpha, a missing alpha is 1. Returns an error message instead when the file cannot be read.
std::variant<RgbaImage, std::string> readImage(const std::filesystem::path& path);

/// Writes `image` (linear) to `path`, atomically (a temporary file renamed when complete).
/// `.exr`: linear half floats with alpha. Other formats: RGB tone-mapped with `exposure` (in
/// stops) and encoded as sRGB, 8 bits. Returns an error message on failure.
std::optional<std::string> writeImage(const std::filesystem::path& path, const RgbaImage& image, float exposure = 0.0f);

/// The sRGB transfer function, decoded (IEC 61966-2-1): texture values to linear.
float srgbToLinear(float v);
float linearToSrgb(float v);
/// The tone curve of 8-bit outputs: Narkowicz's fit of the ACES filmic curve (2015), which maps
/// [0, inf) to [0, 1) smoothly. Exposed for tests and the difference images.
float tonemap(float v);

}  // namespace mxc::rt
