#pragma once
/// \file
/// From a render to its image files: the background under what the render does not cover, the
/// exposure and tone curve of 8-bit formats, the metadata. Shared by `mxc render` of a document
/// and of a scene.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "cli/OutputSet.h"
#include "runtime/ImageIO.h"

namespace mxc::cli {

struct ImageFinish {
  /// The environment image as the camera sees it (rt::renderBackground), or null: then 8-bit
  /// formats get `background` and linear ones stay transparent.
  const rt::RgbaImage* behind = nullptr;
  glm::vec3 background{0.05f};  ///< linear, under 8-bit formats when there is no image behind
  float exposure = 0.0f;        ///< stops, in [-64, 64]: 8-bit formats only
  rt::ToneMapping tone = rt::ToneMapping::AcesFit;
  rt::ImageAttributes attributes;
  std::string format;  ///< the extension standard output (`-`) is encoded as (--format)
};

/// The path whose extension gives `output`'s image format: `output` itself, or for `-`
/// (standard output) one with the extension `format`.
std::filesystem::path formatPath(const std::filesystem::path& output, const std::string& format);

/// A usage error for `-o -` without --format, or --format without `-o -`.
std::optional<std::string> checkFormatOption(const std::vector<std::string>& outputs, const std::string& format);

/// What a reader of an image needs to know of how its values were made: "ImageDescription" and
/// "mxc:exposure" (encodeImage adds "mxc:tonemap" to 8-bit formats).
rt::ImageAttributes renderAttributes(const std::string& input, uint32_t spp, float exposure, rt::ToneMapping tone);

/// Loads the image module (waiting for an rt::ImageModulePreload) and checks that every output's
/// format can be written, before the render: kOk, or the exit code after printing why not
/// (kOutputFailed without the module, kUsage for a format).
int checkOutputFormats(const std::vector<std::string>& outputs, const std::string& format);

/// What a render's callbacks throw to stop it when an output is refused: checkOutputFormats in
/// the renderer's `beforeFrames` (which runs once the pipelines are compiled, while the image
/// module loads), or an image that cannot be staged. The command's exit code (the reason is
/// printed).
struct OutputsRefused {
  int code;
};

/// Finishes `render` for the format of `path` and stages it in `outputs` (written by its
/// commit). Returns why it cannot be encoded or staged instead.
std::optional<std::string> stageRender(const std::filesystem::path& path, const rt::RgbaImage& render,
                                       const ImageFinish& finish, OutputSet& outputs);

}  // namespace mxc::cli
