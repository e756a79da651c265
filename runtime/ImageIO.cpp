#include "runtime/ImageIO.h"

#include <algorithm>
#include <cctype>

#include <dlfcn.h>

#include <fmt/format.h>

#include "compiler/common/InputFile.h"
#include "compiler/common/OutputFile.h"

namespace mxc::rt {

namespace {

/// The module's file name; runtime/CMakeLists.txt names the target so.
constexpr const char* kImageModuleName = "libmxc_imageio.so";

/// Image files larger than this are refused before they are read: 2 GiB.
constexpr size_t kMaxImageFileBytes = size_t{2} << 30;

/// The codec of the OpenImageIO module, loaded once; null with `error` set when it cannot be.
const ImageCodec* codec(std::string& error) {
  static std::string loadError;
  static const ImageCodec* loaded = []() -> const ImageCodec* {
    // By name, not by path: the dynamic loader searches the executable's RUNPATH, which is
    // $ORIGIN in the build tree (the module sits beside mxc) and $ORIGIN/../lib/mxc in an
    // install (runtime/CMakeLists.txt), so a moved or installed mxc finds its own module.
    void* module = dlopen(kImageModuleName, RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      const char* why = dlerror();
      loadError = fmt::format(
          "cannot load the image I/O module {} (looked for beside the executable and in ../lib/mxc): {}",
          kImageModuleName, why ? why : "unknown error");
      return nullptr;
    }
    auto entry = reinterpret_cast<const ImageCodec* (*)()>(dlsym(module, "mxc_image_codec"));
    if (!entry) {
      loadError = fmt::format("{} has no mxc_image_codec", kImageModuleName);
      return nullptr;
    }
    return entry();
  }();
  error = loadError;
  return loaded;
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

std::variant<RgbaImage, std::string> readImage(const std::filesystem::path& path, const ImageReadOptions& options,
                                               std::vector<std::string>* warnings) {
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return fmt::format("cannot read image '{}': {}", path.string(), error);
  // Read here, as a regular file of bounded size: OpenImageIO given /dev/zero spins forever and
  // given a FIFO blocks forever.
  auto bytes = readInputFile(path, kMaxImageFileBytes);
  if (auto* why = std::get_if<1>(&bytes)) return fmt::format("cannot read image '{}': {}", path.string(), *why);
  std::vector<std::string> ignored;
  return c->read(path, std::get<0>(bytes), options, warnings ? *warnings : ignored);
}

std::variant<std::string, std::string> encodeImage(const std::filesystem::path& path, const RgbaImage& image,
                                                   float exposure) {
  using Result = std::variant<std::string, std::string>;
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return Result(std::in_place_index<1>, fmt::format("cannot write '{}': {}", path.string(), error));
  auto encoded = c->encode(lowerExtension(path), image, exposure);
  if (auto* why = std::get_if<1>(&encoded)) {
    return Result(std::in_place_index<1>, fmt::format("cannot write '{}': {}", path.string(), *why));
  }
  return encoded;
}

std::optional<std::string> loadImageModule() {
  std::string error;
  if (!codec(error)) return error;
  return std::nullopt;
}

std::optional<std::string> checkImageFormat(const std::filesystem::path& path) {
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return error;
  if (auto why = c->writable(lowerExtension(path))) return fmt::format("'{}': {}", path.string(), *why);
  return std::nullopt;
}

std::optional<std::string> writeImage(const std::filesystem::path& path, const RgbaImage& image, float exposure) {
  auto encoded = encodeImage(path, image, exposure);
  if (auto* why = std::get_if<1>(&encoded)) return *why;
  return writeOutputFile(path, std::get<0>(encoded));
}

}  // namespace mxc::rt
