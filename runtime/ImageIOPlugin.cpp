// The OpenImageIO side of runtime/ImageIO: built as a module that the runtime loads on first
// use, so that commands which read and write no image (compile, inspect) do not load
// OpenImageIO and the 260 libraries it depends on (about 130 MB of resident memory).

#include <algorithm>
#include <cmath>
#include <memory>
#include <system_error>

#include <fmt/format.h>
#include <OpenImageIO/imageio.h>

#include "runtime/ImageIO.h"

namespace mxc::rt {
namespace {

std::variant<RgbaImage, std::string> read(const std::filesystem::path& path) {
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) {
    std::string why = OIIO::geterror();
    return fmt::format("cannot read image {}: {}", path.string(), why.empty() ? "unknown error" : why);
  }
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1) {
    return fmt::format("cannot read image {}: unsupported size or channels", path.string());
  }
  const int channels = std::min(spec.nchannels, 4);
  std::vector<float> data(size_t(spec.width) * spec.height * channels);
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
    return fmt::format("cannot read image {}: {}", path.string(), input->geterror());
  }
  RgbaImage image;
  image.width = static_cast<uint32_t>(spec.width);
  image.height = static_cast<uint32_t>(spec.height);
  image.pixels.resize(size_t(image.width) * image.height * 4);
  for (size_t i = 0; i < size_t(image.width) * image.height; ++i) {
    const float* s = &data[i * channels];
    float* d = &image.pixels[i * 4];
    if (channels <= 2) {
      d[0] = d[1] = d[2] = s[0];
      d[3] = channels == 2 ? s[1] : 1.0f;
    } else {
      d[0] = s[0];
      d[1] = s[1];
      d[2] = s[2];
      d[3] = channels == 4 ? s[3] : 1.0f;
    }
  }
  return image;
}

std::optional<std::string> write(const std::filesystem::path& path, const RgbaImage& image, float exposure) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const bool linear = ext == ".exr";
  // The temporary keeps the extension: OpenImageIO chooses the format by it.
  std::filesystem::path temp = path;
  temp.replace_filename(fmt::format(".{}.tmp{}", path.stem().string(), path.extension().string()));
  auto output = OIIO::ImageOutput::create(temp.string());
  if (!output) return fmt::format("cannot write {}: no image format for '{}'", path.string(), ext);
  const size_t count = size_t(image.width) * image.height;
  bool ok = false;
  if (linear) {
    OIIO::ImageSpec spec(int(image.width), int(image.height), 4, OIIO::TypeDesc::HALF);
    spec.attribute("compression", "zip");
    ok = output->open(temp.string(), spec) && output->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else {
    const float scale = std::exp2(exposure);
    std::vector<uint8_t> bytes(count * 3);
    for (size_t i = 0; i < count; ++i) {
      for (int c = 0; c < 3; ++c) {
        const float v = linearToSrgb(tonemap(image.pixels[i * 4 + c] * scale));
        bytes[i * 3 + c] = static_cast<uint8_t>(std::lround(v * 255.0f));
      }
    }
    OIIO::ImageSpec spec(int(image.width), int(image.height), 3, OIIO::TypeDesc::UINT8);
    ok = output->open(temp.string(), spec) && output->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  std::string why = ok ? "" : output->geterror();
  ok = output->close() && ok;
  output.reset();
  std::error_code ec;
  if (ok) std::filesystem::rename(temp, path, ec);
  if (!ok || ec) {
    std::filesystem::remove(temp, ec);
    return fmt::format("cannot write {}: {}", path.string(), why.empty() ? ec.message() : why);
  }
  return std::nullopt;
}

const ImageCodec kCodec{read, write};

}  // namespace
}  // namespace mxc::rt

extern "C" const mxc::rt::ImageCodec* mxc_image_codec() { return &mxc::rt::kCodec; }
