// The OpenImageIO side of runtime/ImageIO: built as a module that the runtime loads on first
// use, so that commands which read and write no image (compile, inspect) do not load
// OpenImageIO and the 260 libraries it depends on (about 130 MB of resident memory).
//
// Images are decoded from and encoded to memory (OpenImageIO's IOProxy): the file itself is
// read and written by mxc's own checked code (compiler/common/InputFile.h, OutputFile.h), so a
// full disk or a special file is never OpenImageIO's to get wrong.

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "compiler/common/Quote.h"
#include "runtime/ImageIO.h"

namespace mxc::rt {
namespace {

/// Formats mxc writes: those of OpenImageIO that can encode to memory. Probed, not assumed.
const std::vector<std::string>& writableExtensions() {
  static const std::vector<std::string> list = [] {
    std::vector<std::string> found;
    for (const char* ext : {".png", ".jpg", ".exr", ".tif", ".bmp", ".tga", ".hdr", ".ppm", ".dpx", ".webp", ".gif", ".jp2"}) {
      auto out = OIIO::ImageOutput::create(std::string("x") + ext);
      if (out && out->supports("ioproxy")) found.push_back(ext);
    }
    return found;
  }();
  return list;
}

/// One pixel of `channels` values to RGBA (one channel is grey, two are grey and alpha, a
/// missing alpha is 1), decoded from sRGB when asked.
void toRgba(const float* s, int channels, bool srgb, float* d) {
  if (channels <= 2) {
    d[0] = d[1] = d[2] = s[0];
    d[3] = channels == 2 ? s[1] : 1.0f;
  } else {
    d[0] = s[0];
    d[1] = s[1];
    d[2] = s[2];
    d[3] = channels >= 4 ? s[3] : 1.0f;
  }
  if (srgb) {
    for (int c = 0; c < 3; ++c) d[c] = srgbToLinear(d[c]);
  }
}

std::variant<RgbaImage, std::string> read(const std::filesystem::path& path, const std::string& bytes,
                                          const ImageReadOptions& options, std::vector<std::string>& warnings) {
  const std::string name = path.string();
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
  // The format by the extension; from memory where the format can, else from the path (the
  // caller checked it is a regular file).
  auto probe = OIIO::ImageInput::create(name);
  const bool fromMemory = probe && probe->supports("ioproxy");
  probe.reset();
  auto input = OIIO::ImageInput::open(name, nullptr, fromMemory ? &memory : nullptr);
  if (!input) {
    std::string why = OIIO::geterror();
    return fmt::format("cannot read image {}: {}", quotedValue(name), why.empty() ? "not an image file OpenImageIO reads" : why);
  }
  const OIIO::ImageSpec spec = input->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1) {
    return fmt::format("cannot read image {}: unsupported size or channels", quotedValue(name));
  }
  const uint64_t width = static_cast<uint64_t>(spec.width), height = static_cast<uint64_t>(spec.height);
  const int channels = spec.nchannels;
  // The smallest integer box-filter factor k that fits the device and the texel budget. k grows
  // by one per step and ends by max(width, height) at the latest (a 1x1 result fits any limit).
  auto fits = [&](uint64_t k) {
    const uint64_t w = (width + k - 1) / k, h = (height + k - 1) / k;
    const bool side = options.maxDimension == 0 || (w <= options.maxDimension && h <= options.maxDimension);
    return side && w * h <= std::max<uint64_t>(options.maxTexels, 1);
  };
  uint64_t k = 1;
  while (!fits(k)) ++k;
  RgbaImage image;
  image.eightBit = spec.format.size() == 1;  // UINT8 or INT8 channels
  image.width = static_cast<uint32_t>((width + k - 1) / k);
  image.height = static_cast<uint32_t>((height + k - 1) / k);
  const bool codes = k == 1 && options.eightBitTexels && spec.format == OIIO::TypeDesc::UINT8;
  if (!codes) image.pixels.assign(size_t{image.width} * image.height * 4, 0.0f);
  if (codes) {
    // The code values as they are, straight into the RGBA layout (x stride of 4 bytes), then
    // widened in place as toRgba does; no sRGB decoding (the texture's format does it).
    image.texels.assign(size_t{image.width} * image.height * 4, 0);
    const int read = std::min(channels, 4);
    if (!input->read_image(0, 0, 0, read, OIIO::TypeDesc::UINT8, image.texels.data(), 4)) {
      return fmt::format("cannot read image {}: {}", quotedValue(name), input->geterror());
    }
    for (size_t i = 0; i < size_t{image.width} * image.height; ++i) {
      uint8_t* p = &image.texels[i * 4];
      if (read <= 2) {
        const uint8_t grey = p[0], alpha = read == 2 ? p[1] : 255;
        p[0] = p[1] = p[2] = grey;
        p[3] = alpha;
      } else if (read == 3) {
        p[3] = 255;
      }
    }
  } else if (k == 1) {
    // Straight into the RGBA layout (x stride of 4 floats), then widened in place.
    const int read = std::min(channels, 4);
    if (!input->read_image(0, 0, 0, read, OIIO::TypeDesc::FLOAT, image.pixels.data(), 4 * sizeof(float))) {
      return fmt::format("cannot read image {}: {}", quotedValue(name), input->geterror());
    }
    for (size_t i = 0; i < size_t{image.width} * image.height; ++i) {
      float* p = &image.pixels[i * 4];
      const float s[4] = {p[0], p[1], p[2], p[3]};
      toRgba(s, read, options.srgbDecode, p);
    }
  } else {
    // Row by row: memory is one input row plus one output row of sums, whatever the input size.
    std::vector<float> row(width * static_cast<uint64_t>(channels));
    std::vector<double> sums(size_t{image.width} * 4, 0.0);
    for (uint64_t y = 0; y < height; ++y) {
      if (!input->read_scanline(static_cast<int>(y), 0, OIIO::TypeDesc::FLOAT, row.data())) {
        return fmt::format("cannot read image {}: {}", quotedValue(name), input->geterror());
      }
      for (uint64_t x = 0; x < width; ++x) {
        float rgba[4];
        toRgba(&row[x * static_cast<uint64_t>(channels)], channels, options.srgbDecode, rgba);
        for (int c = 0; c < 4; ++c) sums[(x / k) * 4 + static_cast<uint64_t>(c)] += rgba[c];
      }
      if ((y + 1) % k != 0 && y + 1 != height) continue;
      // The block rows are complete: each output texel is the mean of the input texels it
      // covers (fewer at the right and bottom edges; at least one, so the division is safe).
      const uint64_t outY = y / k, rows = y + 1 - outY * k;
      for (uint64_t X = 0; X < image.width; ++X) {
        const uint64_t columns = std::min(k, width - X * k);
        const double count = static_cast<double>(rows * columns);
        for (int c = 0; c < 4; ++c) {
          image.pixels[(outY * image.width + X) * 4 + static_cast<uint64_t>(c)] = static_cast<float>(sums[X * 4 + static_cast<uint64_t>(c)] / count);
        }
      }
      std::fill(sums.begin(), sums.end(), 0.0);
    }
    warnings.push_back(fmt::format(
        "image '{}' is {}x{}, more than the device ({} per side) or mxc's budget ({} texels) takes: box-filtered "
        "by {} to {}x{}",
        name, width, height, options.maxDimension, options.maxTexels, k, image.width, image.height));
  }
  // A damaged file can decode "successfully" with a message: libjpeg fills a truncated JPEG
  // with grey and says "Premature end of JPEG file".
  if (std::string why = input->geterror(); !why.empty()) {
    warnings.push_back(fmt::format("image '{}' is damaged and may be incomplete: {}", name, why));
  }
  input->close();
  return image;
}

std::optional<std::string> writable(const std::string& extension) {
  const auto& list = writableExtensions();
  const std::string known = fmt::format("{}", fmt::join(list, ", "));
  if (extension.empty()) return fmt::format("no file extension to choose the image format by ({})", known);
  if (std::find(list.begin(), list.end(), extension) != list.end()) return std::nullopt;
  if (auto out = OIIO::ImageOutput::create("x" + extension); !out) {
    return fmt::format("no image format has the extension '{}' (mxc writes {})", extension, known);
  }
  return fmt::format("mxc does not write the '{}' format (it writes {})", extension, known);
}

std::variant<std::string, std::string> encode(const std::string& extension, const RgbaImage& image,
                                              const ImageAttributes& attributes) {
  using Result = std::variant<std::string, std::string>;
  if (auto why = writable(extension)) return Result(std::in_place_index<1>, *why);
  std::vector<unsigned char> buffer;
  OIIO::Filesystem::IOVecOutput memory(buffer);
  const std::string name = "image" + extension;
  auto output = OIIO::ImageOutput::create(name, &memory);
  if (!output) return Result(std::in_place_index<1>, OIIO::geterror());
  const size_t count = size_t(image.width) * image.height;
  auto withAttributes = [&](OIIO::ImageSpec spec) {
    for (const auto& [key, value] : attributes) spec.attribute(key, value);
    return spec;
  };
  bool ok = false;
  if (extension == ".exr") {
    // 32-bit float: half's largest value, 65504, is below what a render can hold (a light
    // bulb's emission, a firefly), and a half file would turn it into Inf.
    OIIO::ImageSpec spec(int(image.width), int(image.height), 4, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    ok = output->open(name, withAttributes(spec)) && output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else if (extension == ".hdr") {
    // Radiance RGBE: linear RGB, no alpha.
    std::vector<float> rgb(count * 3);
    for (size_t i = 0; i < count; ++i) {
      for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = image.pixels[i * 4 + c];
    }
    OIIO::ImageSpec spec(int(image.width), int(image.height), 3, OIIO::TypeDesc::FLOAT);
    ok = output->open(name, withAttributes(spec)) && output->write_image(OIIO::TypeDesc::FLOAT, rgb.data());
  } else {
    // Display values in [0, 1] (tone-mapped by encodeImage): sRGB, 8 bits.
    std::vector<uint8_t> bytes(count * 3);
    for (size_t i = 0; i < count; ++i) {
      for (int c = 0; c < 3; ++c) {
        const float v = linearToSrgb(image.pixels[i * 4 + c]);  // clamps to [0, 1]
        bytes[i * 3 + c] = static_cast<uint8_t>(std::lround(v * 255.0f));
      }
    }
    OIIO::ImageSpec spec(int(image.width), int(image.height), 3, OIIO::TypeDesc::UINT8);
    ok = output->open(name, withAttributes(spec)) && output->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  std::string why = ok ? "" : output->geterror();
  ok = output->close() && ok;
  if (why.empty()) why = output->geterror();
  if (!ok || buffer.empty()) return Result(std::in_place_index<1>, why.empty() ? "the encoder failed" : why);
  return Result(std::in_place_index<0>, std::string(buffer.begin(), buffer.end()));
}

std::optional<std::string> drawText(RgbaImage& image, int x, int y, const std::string& text, int size,
                                    const float rgb[3], bool centred) {
  // The image's own pixels, wrapped: OpenImageIO draws into them in place.
  OIIO::ImageSpec spec(int(image.width), int(image.height), 4, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec, image.pixels.data());
  const float color[4] = {rgb[0], rgb[1], rgb[2], 1.0f};
  // By name, found on OpenImageIO's font path (/usr/share/fonts/truetype/...); its default font
  // is not installed by Debian.
  if (!OIIO::ImageBufAlgo::render_text(buffer, x, y, text, size, "DejaVuSans", color,
                                       centred ? OIIO::ImageBufAlgo::TextAlignX::Center
                                               : OIIO::ImageBufAlgo::TextAlignX::Left)) {
    const std::string why = buffer.geterror();
    return fmt::format("cannot draw text with the font DejaVuSans (Debian's fonts-dejavu-core): {}",
                       why.empty() ? "no reason given" : why);
  }
  return std::nullopt;
}

std::string libraryVersion() {
  // openimageio_version() is 10000 major + 100 minor + patch, of the library loaded at run time.
  const int v = OIIO::openimageio_version();
  return fmt::format("{}.{}.{}", v / 10000, v / 100 % 100, v % 100);
}

const ImageCodec kCodec{read, encode, writable, drawText, libraryVersion};

}  // namespace
}  // namespace mxc::rt

extern "C" const mxc::rt::ImageCodec* mxc_image_codec() { return &mxc::rt::kCodec; }
