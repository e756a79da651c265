#pragma once
/// \file
/// How 8-bit image formats map linear values to display code values: a tone curve (or none),
/// then the sRGB transfer function. The curve's name is written into the file's metadata.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

namespace mxc::rt {

enum class ToneMapping : uint8_t {
  /// No curve: values clamped to [0, 1]. Display-referred values (a plot), or a render whose
  /// user wants radiance 1 at white.
  None,
  /// Narkowicz's fit of the ACES filmic curve (2015), per channel: maps [0, inf) to [0, 1)
  /// smoothly, with contrast and a shoulder that desaturates bright colours.
  AcesFit,
  /// Khronos PBR Neutral (Khronos 3D Commerce, 2024): identity below 0.76 apart from a small
  /// toe offset, a hue-preserving shoulder above, so base colours show as authored (a
  /// base_color of 0.5 under white light of radiance 1 reads 0.5).
  PbrNeutral,
};

/// The option's spelling: "none", "aces", "neutral".
const char* toneMappingName(ToneMapping tone);
/// The inverse of toneMappingName, or nullopt.
std::optional<ToneMapping> parseToneMapping(const std::string& name);
/// One sentence for an image's metadata ("ACES filmic fit (Narkowicz 2015), then sRGB").
const char* toneMappingDescription(ToneMapping tone);

/// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": x (a x + b) / (x (c x + d) + e).
inline float acesFit(float v) {
  const float x = std::max(v, 0.0f);
  // Above 1e4 the curve is past 1 (1.03 there, rising to 2.51 / 2.43) and clamps to 1, as it
  // does here without x * x overflowing to inf / inf = NaN (from 1.8e19 on); inf lands here too.
  if (x > 1e4f) return 1.0f;
  // The denominator is >= e = 0.14 > 0 for x >= 0.
  return std::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

/// Khronos PBR Neutral tone mapping, from its specification's reference formulas.
glm::vec3 pbrNeutral(glm::vec3 color);

/// `color` (linear, scene-referred) through the curve, in [0, 1] per channel (before sRGB).
glm::vec3 applyToneMapping(ToneMapping tone, glm::vec3 color);

}  // namespace mxc::rt
