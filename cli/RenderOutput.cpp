#include "cli/RenderOutput.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cli/ExitCode.h"

namespace mxc::cli {

std::filesystem::path formatPath(const std::filesystem::path& output, const std::string& format) {
  return output == "-" ? std::filesystem::path("standard-output." + format) : output;
}

std::optional<std::string> checkFormatOption(const std::vector<std::string>& outputs, const std::string& format) {
  const bool toStdout = std::find(outputs.begin(), outputs.end(), "-") != outputs.end();
  if (toStdout && format.empty()) {
    return "-o -: standard output has no file extension to choose the image format by: give it with --format "
           "(png, exr, ...)";
  }
  if (!toStdout && !format.empty()) return "--format is the format of -o - (standard output); a file's extension gives its own";
  return std::nullopt;
}

int checkOutputFormats(const std::vector<std::string>& outputs, const std::string& format) {
  if (auto why = rt::loadImageModule()) {
    std::fprintf(stderr, "error: %s\n", why->c_str());
    return kOutputFailed;
  }
  for (const std::string& output : outputs) {
    if (auto why = rt::checkImageFormat(formatPath(output, format))) {
      std::fprintf(stderr, "error: -o %s\n", why->c_str());
      return kUsage;
    }
  }
  return kOk;
}

rt::ImageAttributes renderAttributes(const std::string& input, uint32_t spp, float exposure, rt::ToneMapping tone) {
  return {{"ImageDescription", fmt::format("mxc render of {}: {} spp, exposure {} stops; 8-bit formats: {}", input, spp,
                                           exposure, rt::toneMappingDescription(tone))},
          {"mxc:exposure", fmt::format("{}", exposure)}};
}

std::optional<std::string> stageRender(const std::filesystem::path& path, const rt::RgbaImage& render,
                                       const ImageFinish& finish, OutputSet& outputs) {
  rt::RgbaImage pixels = render;
  // Linear formats hold radiance as rendered; 8-bit ones get the exposure, which scales the
  // rendered radiance (a camera's). Under what the surface does not cover goes the environment
  // image (radiance too: scaled with it, in every format; alpha stays the coverage) or, in
  // 8-bit formats only, the constant background colour (not scaled).
  const std::filesystem::path encodeAs = formatPath(path, finish.format);
  const bool linear = rt::holdsRadiance(encodeAs);
  if (finish.behind || !linear) {
    const float scale = linear ? 1.0f : std::exp2(finish.exposure);  // |exposure| <= 64: finite, > 0
    for (size_t i = 0; i + 3 < pixels.pixels.size(); i += 4) {
      const float uncovered = 1.0f - std::clamp(pixels.pixels[i + 3], 0.0f, 1.0f);
      for (size_t c = 0; c < 3; ++c) {
        const float under = finish.behind ? scale * finish.behind->pixels[i + c] : finish.background[int(c)];
        pixels.pixels[i + c] = scale * pixels.pixels[i + c] + uncovered * under;
      }
    }
  }
  auto encoded = rt::encodeImage(encodeAs, pixels, finish.tone, finish.attributes);
  if (auto* why = std::get_if<1>(&encoded)) return *why;
  return outputs.stage(path, std::move(std::get<0>(encoded)));
}

}  // namespace mxc::cli
