#include "runtime/ToneMapping.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace mxc::rt {

const char* toneMappingName(ToneMapping tone) {
  switch (tone) {
    case ToneMapping::None: return "none";
    case ToneMapping::AcesFit: return "aces";
    case ToneMapping::PbrNeutral: return "neutral";
  }
  return "none";
}

std::optional<ToneMapping> parseToneMapping(const std::string& name) {
  for (ToneMapping tone : {ToneMapping::None, ToneMapping::AcesFit, ToneMapping::PbrNeutral}) {
    if (name == toneMappingName(tone)) return tone;
  }
  return std::nullopt;
}

const char* toneMappingDescription(ToneMapping tone) {
  switch (tone) {
    case ToneMapping::None: return "linear values clamped to [0, 1], then sRGB";
    case ToneMapping::AcesFit: return "ACES filmic curve fit (Narkowicz 2015) per channel, then sRGB";
    case ToneMapping::PbrNeutral: return "Khronos PBR Neutral (2024), then sRGB";
  }
  return "";
}

glm::vec3 pbrNeutral(glm::vec3 color) {
  // Khronos PBR Neutral specification: the toe subtracts an offset that fades in below 0.08 and
  // is 0.04 above; above startCompression = 0.8 - 0.04 the peak channel is compressed towards 1
  // as 1 - d^2 / (peak + d - start), d = 1 - start, the colour scaled with it (hue kept), then
  // mixed towards white by g = 1 - 1 / (desaturation (peak - newPeak) + 1), desaturation 0.15.
  constexpr float kStart = 0.8f - 0.04f, kDesaturation = 0.15f;
  color = glm::max(color, glm::vec3(0.0f));  // negative radiance is not a colour
  const float x = std::min(color.r, std::min(color.g, color.b));
  const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
  color -= offset;  // offset <= x: every channel stays >= 0
  const float peak = std::max(color.r, std::max(color.g, color.b));
  if (peak < kStart) return color;
  constexpr float d = 1.0f - kStart;
  const float newPeak = 1.0f - d * d / (peak + d - kStart);  // peak + d - start >= d > 0
  color *= newPeak / peak;                                      // peak >= start > 0
  const float g = 1.0f - 1.0f / (kDesaturation * (peak - newPeak) + 1.0f);  // peak >= newPeak: denominator >= 1
  return glm::clamp(glm::mix(color, glm::vec3(newPeak), g), 0.0f, 1.0f);
}

glm::vec3 applyToneMapping(ToneMapping tone, glm::vec3 color) {
  // A NaN channel (which `render` reports as an error) shows as 0 rather than as whatever its
  // conversion to 8 bits makes of it; one beyond 1e30 (an overflowed sum, inf included) is
  // 1e30, where every curve has long saturated and PBR Neutral's arithmetic stays finite.
  for (int c = 0; c < 3; ++c) color[c] = std::isnan(color[c]) ? 0.0f : std::min(color[c], 1e30f);
  switch (tone) {
    case ToneMapping::None: return glm::clamp(color, 0.0f, 1.0f);
    case ToneMapping::AcesFit: return {acesFit(color.r), acesFit(color.g), acesFit(color.b)};
    case ToneMapping::PbrNeutral: return pbrNeutral(color);
  }
  return glm::clamp(color, 0.0f, 1.0f);
}

}  // namespace mxc::rt
