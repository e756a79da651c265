#pragma once
/// \file
/// Image files through OpenImageIO: textures in, rendered images out. EXR keeps linear floats;
/// 8-bit formats (PNG, JPEG, ...) get a tone-mapped, sRGB-encoded image.

#include <algorithm>
#include <cmath>
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

/// What the OpenImageIO module (runtime/ImageIOPlugin.cpp) provides; readImage and writeImage
/// load it on first use.
struct ImageCodec {
  std::variant<RgbaImage, std::string> (*read)(const std::filesystem::path& path);
  std::optional<std::string> (*write)(const std::filesystem::path& path, const RgbaImage& image, float exposure);
};

/// The sRGB transfer function, decoded (IEC 61966-2-1): texture values to linear.
inline float srgbToLinear(float v) {
  // pow of a value >= 0.04045 > 0
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}
inline float linearToSrgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;  // pow of v > 0
}
/// The tone curve of 8-bit outputs: Narkowicz's fit of the ACES filmic curve (2015), which maps
/// [0, inf) to [0, 1) smoothly.
inline float tonemap(float v) {
  // Narkowicz 2015, "ACES Filmic Tone Mapping Curve": x (a x + b) / (x (c x + d) + e). The
  // denominator is >= e > 0 for x >= 0.
  const float x = std::max(v, 0.0f);
  return std::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

}  // namespace mxc::rt
