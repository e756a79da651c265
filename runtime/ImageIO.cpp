#include "runtime/ImageIO.h"

#include <algorithm>
#include <cctype>
#include <system_error>
#include <vector>

#include <dlfcn.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compiler/common/InputFile.h"
#include "compiler/common/OutputFile.h"
#include "compiler/common/Parallel.h"
#include "compiler/common/Quote.h"

namespace mxc::rt {

namespace {

/// The module's file name; runtime/CMakeLists.txt names the target so.
constexpr const char* kImageModuleName = "libmxc_imageio.so";

/// Image files larger than this are refused before they are read: 2 GiB.
constexpr size_t kMaxImageFileBytes = size_t{2} << 30;

/// Where the module is looked for: beside the executable (the build tree; test programs get a
/// copy beside them), then in ../lib/mxc (an install, runtime/CMakeLists.txt). Relative to the
/// executable's real path, so a moved build tree or install works. (Not by the dynamic loader's
/// RUNPATH: under AddressSanitizer, dlopen is called from the sanitizer's runtime, whose RUNPATH
/// is not the executable's.)
std::vector<std::filesystem::path> moduleCandidates() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const std::filesystem::path folder = exe.parent_path();
  return {folder / kImageModuleName, (folder / ".." / "lib" / "mxc" / kImageModuleName).lexically_normal()};
}

/// The codec of the OpenImageIO module, loaded once; null with `error` set when it cannot be.
const ImageCodec* codec(std::string& error) {
  static std::string loadError;
  static const ImageCodec* loaded = []() -> const ImageCodec* {
    std::vector<std::string> tried;
    void* module = nullptr;
    for (const std::filesystem::path& candidate : moduleCandidates()) {
      std::error_code ec;
      if (!std::filesystem::exists(candidate, ec)) {
        tried.push_back(candidate.string());
        continue;
      }
      module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!module) {
        const char* why = dlerror();
        loadError = fmt::format("cannot load the image I/O module {}: {}", candidate.string(), why ? why : "unknown error");
        return nullptr;
      }
      break;
    }
    if (!module) {
      loadError = fmt::format("cannot load the image I/O module {}: it is neither beside the executable nor in "
                              "../lib/mxc (looked for {})",
                              kImageModuleName, fmt::join(tried, " and "));
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
  if (!c) return fmt::format("cannot read image {}: {}", quotedValue(path.string()), error);
  // Read here, as a regular file of bounded size: OpenImageIO given /dev/zero spins forever and
  // given a FIFO blocks forever.
  auto bytes = readInputFile(path, kMaxImageFileBytes);
  if (auto* why = std::get_if<1>(&bytes)) return fmt::format("cannot read image {}: {}", quotedValue(path.string()), *why);
  std::vector<std::string> ignored;
  return c->read(path, std::get<0>(bytes), options, warnings ? *warnings : ignored);
}

bool holdsRadiance(const std::filesystem::path& path) {
  const std::string extension = lowerExtension(path);
  return extension == ".exr" || extension == ".hdr";
}

std::variant<std::string, std::string> encodeImage(const std::filesystem::path& path, const RgbaImage& image,
                                                   ToneMapping tone, const ImageAttributes& attributes) {
  using Result = std::variant<std::string, std::string>;
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return Result(std::in_place_index<1>, fmt::format("cannot write '{}': {}", path.string(), error));
  ImageAttributes all = attributes;
  std::variant<std::string, std::string> encoded;
  if (holdsRadiance(path)) {
    encoded = c->encode(lowerExtension(path), image, all);
  } else {
    // Display values: the tone curve here, sRGB and quantisation in the codec.
    RgbaImage display = image;
    for (size_t i = 0; i + 3 < display.pixels.size(); i += 4) {
      const glm::vec3 v = applyToneMapping(tone, {display.pixels[i], display.pixels[i + 1], display.pixels[i + 2]});
      for (int k = 0; k < 3; ++k) display.pixels[i + size_t(k)] = v[k];
    }
    all.emplace_back("mxc:tonemap", toneMappingName(tone));
    encoded = c->encode(lowerExtension(path), display, all);
  }
  if (auto* why = std::get_if<1>(&encoded)) {
    return Result(std::in_place_index<1>, fmt::format("cannot write '{}': {}", path.string(), *why));
  }
  return encoded;
}

std::optional<std::string> drawText(RgbaImage& image, int x, int y, const std::string& text, int size,
                                    const float rgb[3], bool centred) {
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return fmt::format("cannot draw text: {}", error);
  return c->drawText(image, x, y, text, size, rgb, centred);
}

std::string imageLibraryVersion() {
  std::string error;
  const ImageCodec* c = codec(error);
  return c ? "OpenImageIO " + c->libraryVersion() : "OpenImageIO: " + error;
}

std::optional<std::string> loadImageModule() {
  std::string error;
  if (!codec(error)) return error;
  return std::nullopt;
}

ImageModulePreload::ImageModulePreload() {
  // A thread that cannot be started leaves the load to the first call that needs the module.
  // The pool's threads are made first: glibc holds its TLS lock through the whole dlopen, and a
  // thread created during it (a compile on every core) would wait for the load.
  startWorkers();
  try {
    thread_ = std::thread([] { loadImageModule(); });
  } catch (const std::system_error&) {
  }
}

ImageModulePreload::~ImageModulePreload() {
  if (thread_.joinable()) thread_.join();
}

std::optional<std::string> checkImageFormat(const std::filesystem::path& path) {
  std::string error;
  const ImageCodec* c = codec(error);
  if (!c) return error;
  if (auto why = c->writable(lowerExtension(path))) return fmt::format("'{}': {}", path.string(), *why);
  return std::nullopt;
}

std::optional<std::string> writeImage(const std::filesystem::path& path, const RgbaImage& image, ToneMapping tone) {
  auto encoded = encodeImage(path, image, tone);
  if (auto* why = std::get_if<1>(&encoded)) return *why;
  return writeOutputFile(path, std::get<0>(encoded));
}

}  // namespace mxc::rt
