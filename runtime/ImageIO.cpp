#include "runtime/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <system_error>

#include <dlfcn.h>

#include <fmt/format.h>

namespace mxc::rt {

namespace {

/// The codec of the OpenImageIO module, loaded once; null with `error` set when it cannot be.
const ImageCodec* codec(std::string& error) {
  static std::string loadError;
  static const ImageCodec* loaded = [] () -> const ImageCodec* {
    // The module sits in the build tree (no install step): its path is compiled in.
    void* module = dlopen(MXC_IMAGEIO_MODULE, RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      const char* why = dlerror();
      loadError = fmt::format("cannot load the image I/O module {}: {}", MXC_IMAGEIO_MODULE, why ? why : "unknown error");
      return nullptr;
    }
    auto entry = reinterpret_cast<const ImageCodec* (*)()>(dlsym(module, "mxc_image_codec"));
    if (!entry) {
      loadError = fmt::format("{} has no mxc_image_codec", MXC_IMAGEIO_MODULE);
      return nullptr;
    }
    return entry();
  }();
  error = loadError;
  return loaded;
}

}  // namespace

std::variant<RgbaImage, std::string> readImage(const std::filesystem::path& path) {
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return fmt::format("cannot read image {}: {}", path.string(), error);
  return c->read(path);
}

std::optional<std::string> writeImage(const std::filesystem::path& path, const RgbaImage& image, float exposure) {
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return fmt::format("cannot write {}: {}", path.string(), error);
  return c->write(path, image, exposure);
}

}  // namespace mxc::rt
