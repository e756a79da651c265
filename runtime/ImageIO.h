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
#include <thread>
#include <variant>
#include <utility>
#include <vector>

#include "runtime/ToneMapping.h"

namespace mxc::rt {

/// RGBA floats, top row first.
struct RgbaImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> pixels;
  /// Read from a file of 8 bits per channel (readImage): 8 bits, sRGB-encoded where the read
  /// decoded sRGB, hold its values, so a texture of it needs a quarter of the memory of floats.
  bool eightBit = false;
  /// Instead of `pixels` (then empty), when the read was asked for them (ImageReadOptions::
  /// eightBitTexels): the file's own 8-bit code values as RGBA, still sRGB-encoded where the read
  /// was to decode sRGB (the texture's format decodes them).
  std::vector<uint8_t> texels{};
  float* at(uint32_t x, uint32_t y) { return &pixels[(size_t{y} * width + x) * 4]; }
  const float* at(uint32_t x, uint32_t y) const { return &pixels[(size_t{y} * width + x) * 4]; }
};

/// How a texture is read.
struct ImageReadOptions {
  /// The largest width or height kept (the device's maxImageDimension2D); 0: no limit.
  uint32_t maxDimension = 0;
  /// The most texels kept: 2^26 (8192 x 8192, 1 GiB as RGBA32F) by default.
  uint64_t maxTexels = uint64_t{1} << 26;
  /// Decode sRGB-encoded values to linear (MaterialX "srgb_texture") before any downsampling,
  /// so that texels are averaged as light, not as code values.
  bool srgbDecode = false;
  /// An 8-bit file read at its size keeps its code values (RgbaImage::texels) rather than
  /// becoming floats: a texture uploads them as they are, with no conversion either way.
  bool eightBitTexels = false;
};

/// Reads any format OpenImageIO reads, as RGBA: one channel becomes grey, two are grey and
/// alpha, a missing alpha is 1. The file must be a regular file (compiler/common/InputFile.h).
/// An image larger than the options allow is box-filtered down by the smallest integer factor
/// that fits, row by row, so memory stays bounded by the result; this and a damaged file that
/// still decoded (a truncated JPEG) are reported in `warnings`. Returns an error message instead
/// when the file cannot be read.
std::variant<RgbaImage, std::string> readImage(const std::filesystem::path& path, const ImageReadOptions& options = {},
                                               std::vector<std::string>* warnings = nullptr);

/// Whether the format of `path`'s extension holds linear radiance as rendered (`.exr`, `.hdr`),
/// rather than tone-mapped 8-bit display values.
bool holdsRadiance(const std::filesystem::path& path);

/// Metadata written into an image file: name and string value (OpenImageIO attribute names:
/// "ImageDescription", or "mxc:..." kept as text chunks in PNG and as attributes in EXR).
using ImageAttributes = std::vector<std::pair<std::string, std::string>>;

/// The bytes of an image file in the format of `path`'s extension. `.exr`: linear 32-bit floats
/// with alpha (ZIP-compressed), every finite value kept as it is; `.hdr`: linear RGB. Other
/// formats: RGB through `tone` (runtime/ToneMapping.h), then sRGB, 8 bits; the curve's name
/// is added to the metadata as "mxc:tonemap". Returns an error message instead.
std::variant<std::string, std::string> encodeImage(const std::filesystem::path& path, const RgbaImage& image,
                                                   ToneMapping tone = ToneMapping::AcesFit,
                                                   const ImageAttributes& attributes = {});

/// Text drawn into `image` with OpenImageIO's renderer and the DejaVu Sans font (Debian's
/// fonts-dejavu-core): `x` is the left edge, or the centre when `centred`; `y` the baseline;
/// `size` the font size in pixels; `rgb` linear. Returns why it could not be drawn instead.
std::optional<std::string> drawText(RgbaImage& image, int x, int y, const std::string& text, int size,
                                    const float rgb[3], bool centred = false);

/// "OpenImageIO 2.4.7" (the library the image module loaded), or why the module cannot be loaded.
std::string imageLibraryVersion();

/// Loads the image module (OpenImageIO) now: nullopt, or why it cannot be loaded. A command
/// that writes images calls it before long work, so a missing module is known at once.
std::optional<std::string> loadImageModule();

/// Starts loading the image module on a thread of its own, and joins it when destroyed. The
/// module's OpenImageIO brings about 260 shared libraries, 0.2-0.4 s of mapping and relocation
/// that the compilation of a material can hide; the first call that needs the module (any of
/// the functions above and below) waits for the thread instead of loading it again.
class ImageModulePreload {
 public:
  ImageModulePreload();
  ~ImageModulePreload();
  ImageModulePreload(const ImageModulePreload&) = delete;
  ImageModulePreload& operator=(const ImageModulePreload&) = delete;

 private:
  std::thread thread_;
};

/// Whether images can be written in the format of `path`'s extension: nullopt, or why not (no
/// extension, an unknown format, a format OpenImageIO cannot write to memory), listing the
/// formats that can be.
std::optional<std::string> checkImageFormat(const std::filesystem::path& path);

/// encodeImage, then writes the file atomically (compiler/common/OutputFile.h). Returns an
/// error message on failure.
std::optional<std::string> writeImage(const std::filesystem::path& path, const RgbaImage& image,
                                      ToneMapping tone = ToneMapping::AcesFit);

/// What the OpenImageIO module (runtime/ImageIOPlugin.cpp) provides. readImage, encodeImage and
/// checkImageFormat load it on first use.
struct ImageCodec {
  /// `bytes`: the file's content, read by the caller (a format that cannot read from memory is
  /// opened by `path`, which the caller has checked is a regular file).
  std::variant<RgbaImage, std::string> (*read)(const std::filesystem::path& path, const std::string& bytes,
                                               const ImageReadOptions& options, std::vector<std::string>& warnings);
  /// `image` holds radiance for .exr and .hdr, and display values in [0, 1] (before sRGB) for
  /// the other formats.
  std::variant<std::string, std::string> (*encode)(const std::string& extension, const RgbaImage& image,
                                                   const ImageAttributes& attributes);
  /// nullopt when `extension` (".png") can be encoded, else why not.
  std::optional<std::string> (*writable)(const std::string& extension);
  /// drawText above.
  std::optional<std::string> (*drawText)(RgbaImage& image, int x, int y, const std::string& text, int size,
                                         const float rgb[3], bool centred);
  /// The version of the OpenImageIO library loaded ("2.4.7").
  std::string (*libraryVersion)();
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
}  // namespace mxc::rt
