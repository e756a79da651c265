#include "compiler/common/ColorSpace.h"

#include <algorithm>

#include <glm/glm.hpp>

namespace mxc {

namespace {

struct Chromaticity {
  float x, y;
};

/// Primaries and white point as CIE 1931 xy chromaticities.
struct PrimariesDefinition {
  Chromaticity red, green, blue, white;
};

constexpr Chromaticity kD65{0.3127f, 0.3290f};     // CIE standard illuminant D65
constexpr Chromaticity kAcesWhite{0.32168f, 0.33767f};  // ACES white (about D60), SMPTE ST 2065-1

/// ITU-R BT.709; ACES AP1 and AP0 (SMPTE ST 2065-1, Academy S-2014-004); Adobe RGB (1998);
/// Display P3 (DCI-P3 primaries, D65 white); ITU-R BT.2020. XYZ is handled apart (its own axes).
PrimariesDefinition definition(Primaries p) {
  switch (p) {
    case Primaries::Rec709: return {{0.64f, 0.33f}, {0.30f, 0.60f}, {0.15f, 0.06f}, kD65};
    case Primaries::AP1: return {{0.713f, 0.293f}, {0.165f, 0.830f}, {0.128f, 0.044f}, kAcesWhite};
    case Primaries::AP0: return {{0.7347f, 0.2653f}, {0.0f, 1.0f}, {0.0001f, -0.0770f}, kAcesWhite};
    case Primaries::AdobeRgb: return {{0.64f, 0.33f}, {0.21f, 0.71f}, {0.15f, 0.06f}, kD65};
    case Primaries::P3D65: return {{0.680f, 0.320f}, {0.265f, 0.690f}, {0.150f, 0.060f}, kD65};
    case Primaries::Rec2020: return {{0.708f, 0.292f}, {0.170f, 0.797f}, {0.131f, 0.046f}, kD65};
    case Primaries::XyzD65: break;
  }
  return {{1, 0}, {0, 1}, {0, 0}, kD65};  // not used: XYZ has no RGB primaries
}

/// XYZ (Y = 1) of a chromaticity. Every y in the table is non-zero (the blue of AP0 is
/// negative, not zero), so the division is safe.
glm::dvec3 xyzOf(Chromaticity c) { return {c.x / c.y, 1.0, (1.0 - c.x - c.y) / c.y}; }

/// RGB to XYZ for a set of primaries: the columns are the primaries' XYZ, scaled so that
/// RGB (1, 1, 1) is the white point (SMPTE RP 177-1993). The primaries of every table entry are
/// linearly independent, so the matrix is invertible.
glm::dmat3 rgbToXyz(Primaries p) {
  if (p == Primaries::XyzD65) return glm::dmat3(1.0);
  const PrimariesDefinition d = definition(p);
  const glm::dmat3 columns(xyzOf(d.red), xyzOf(d.green), xyzOf(d.blue));
  const glm::dvec3 scale = glm::inverse(columns) * xyzOf(d.white);
  return glm::dmat3(columns[0] * scale.x, columns[1] * scale.y, columns[2] * scale.z);
}

Chromaticity whiteOf(Primaries p) { return p == Primaries::XyzD65 ? kD65 : definition(p).white; }

/// Bradford chromatic adaptation from one white to another (Lam 1985; the transform ACES uses
/// between its white and D65). Written in rows; glm takes columns, hence the transpose.
glm::dmat3 bradford(Chromaticity from, Chromaticity to) {
  const glm::dmat3 cone = glm::transpose(glm::dmat3(0.8951, 0.2664, -0.1614,  //
                                                    -0.7502, 1.7135, 0.0367,  //
                                                    0.0389, -0.0685, 1.0296));
  const glm::dvec3 a = cone * xyzOf(from);
  const glm::dvec3 b = cone * xyzOf(to);
  // Cone responses of real whites are positive: the divisions are safe.
  const glm::dmat3 gain(glm::dvec3(b.x / a.x, 0, 0), glm::dvec3(0, b.y / a.y, 0), glm::dvec3(0, 0, b.z / a.z));
  return glm::inverse(cone) * gain * cone;
}

struct Entry {
  ColorSpace space;
  std::vector<std::string_view> aliases;
};

const std::vector<Entry>& table() {
  // MaterialX's cmlib names first (their transforms are MaterialX's cmlib_ng.mtlx: the gamma
  // spaces clamp at 0 then raise to the power; adobergb's exponent is 563/256), then spaces of
  // OpenColorIO's built-in configurations, with the names MaterialX's test suite writes.
  static const std::vector<Entry> entries = {
      {{"lin_rec709", Encoding::Linear, 1.0f, Primaries::Rec709},
       {"lin_srgb", "Linear Rec.709 (sRGB)", "lin_rec709_scene", "Utility - Linear - sRGB"}},
      {{"srgb_texture", Encoding::Srgb, 1.0f, Primaries::Rec709},
       {"sRGB Encoded Rec.709 (sRGB)", "srgb_rec709_scene", "Utility - sRGB - Texture", "sRGB - Texture"}},
      {{"g18_rec709", Encoding::Gamma, 1.8f, Primaries::Rec709}, {"gamma18", "Gamma 1.8 Encoded Rec.709"}},
      {{"g22_rec709", Encoding::Gamma, 2.2f, Primaries::Rec709},
       {"gamma22", "Gamma 2.2 Encoded Rec.709", "g22_rec709_scene"}},
      {{"rec709_display", Encoding::Gamma, 2.4f, Primaries::Rec709},
       {"gamma24", "Gamma 2.4 Encoded Rec.709", "g24_rec709_scene"}},
      {{"acescg", Encoding::Linear, 1.0f, Primaries::AP1}, {"lin_ap1", "ACEScg", "lin_ap1_scene"}},
      {{"g22_ap1", Encoding::Gamma, 2.2f, Primaries::AP1}, {"Gamma 2.2 Encoded AP1", "g22_ap1_scene"}},
      {{"lin_adobergb", Encoding::Linear, 1.0f, Primaries::AdobeRgb}, {"Linear AdobeRGB", "lin_adobergb_scene"}},
      {{"adobergb", Encoding::Gamma, 563.0f / 256.0f, Primaries::AdobeRgb},
       {"Gamma 2.2 Encoded AdobeRGB", "g22_adobergb_scene"}},
      {{"srgb_displayp3", Encoding::Srgb, 1.0f, Primaries::P3D65}, {"sRGB Encoded P3-D65", "srgb_p3d65_scene"}},
      {{"lin_displayp3", Encoding::Linear, 1.0f, Primaries::P3D65}, {"Linear P3-D65", "lin_p3d65_scene"}},
      {{"lin_rec2020", Encoding::Linear, 1.0f, Primaries::Rec2020}, {"Linear Rec.2020", "lin_rec2020_scene"}},
      {{"lin_ap0", Encoding::Linear, 1.0f, Primaries::AP0}, {"ACES2065-1", "aces2065_1", "lin_ap0_scene"}},
      {{"lin_ciexyzd65", Encoding::Linear, 1.0f, Primaries::XyzD65},
       {"CIE XYZ-D65 - Scene-referred", "lin_ciexyzd65_scene"}},
  };
  return entries;
}

}  // namespace

const ColorSpace* findColorSpace(std::string_view name) {
  for (const Entry& e : table()) {
    if (e.space.name == name) return &e.space;
    if (std::find(e.aliases.begin(), e.aliases.end(), name) != e.aliases.end()) return &e.space;
  }
  return nullptr;
}

bool isDataSpace(std::string_view name) { return name.empty() || name == "none" || name == "raw"; }

std::vector<std::string_view> colorSpaceNames() {
  std::vector<std::string_view> names;
  for (const Entry& e : table()) names.push_back(e.space.name);
  return names;
}

std::vector<std::string_view> linearColorSpaceNames() {
  std::vector<std::string_view> names;
  for (const Entry& e : table()) {
    if (e.space.encoding == Encoding::Linear) names.push_back(e.space.name);
  }
  return names;
}

glm::mat3 primariesConversion(Primaries from, Primaries to) {
  if (from == to) return glm::mat3(1.0f);
  glm::dmat3 toXyz = rgbToXyz(from);
  if (whiteOf(from).x != whiteOf(to).x || whiteOf(from).y != whiteOf(to).y) {
    toXyz = bradford(whiteOf(from), whiteOf(to)) * toXyz;
  }
  return glm::mat3(glm::inverse(rgbToXyz(to)) * toXyz);
}

bool deviceDecodes(std::string_view name) {
  const ColorSpace* space = findColorSpace(name);
  return space && space->encoding == Encoding::Srgb;
}

}  // namespace mxc
