#pragma once
/// \file
/// The colour spaces a document can name (MaterialX 1.39 "Color Spaces and Color Management
/// Systems", the cmlib set, and the names of OpenColorIO's built-in configurations that
/// MaterialX's test suite uses), each as an encoding and a set of RGB primaries. One table,
/// read by the lowering (which converts values and texels into the working space) and by the
/// runtime (which lets the device decode sRGB-encoded 8-bit textures).

#include <string>
#include <string_view>
#include <vector>

#include <glm/mat3x3.hpp>

namespace mxc {

/// How stored values relate to linear light.
enum class Encoding {
  Linear,  ///< stored linear
  Srgb,    ///< the sRGB piecewise curve (IEC 61966-2-1)
  Gamma,   ///< a pure power: linear = max(v, 0)^gamma
};

/// RGB primaries with their white point (chromaticities in ColorSpace.cpp).
enum class Primaries { Rec709, AP1, AP0, AdobeRgb, P3D65, Rec2020, XyzD65 };

struct ColorSpace {
  std::string_view name;  ///< the canonical (MaterialX) name
  Encoding encoding = Encoding::Linear;
  float gamma = 1.0f;  ///< for Encoding::Gamma
  Primaries primaries = Primaries::Rec709;
};

/// The space a `colorspace` attribute names (canonical names and aliases), or null when it is
/// none mxc knows. "none" and "raw" (data, never converted) are not colour spaces: see isDataSpace.
const ColorSpace* findColorSpace(std::string_view name);
/// True for the names that mark data rather than colour ("", "none", "raw"): never converted.
bool isDataSpace(std::string_view name);
/// The canonical names, for messages and --help.
std::vector<std::string_view> colorSpaceNames();
/// The canonical names of the linear spaces (the possible working spaces), for messages.
std::vector<std::string_view> linearColorSpaceNames();

/// The matrix taking linear RGB of `from`'s primaries to linear RGB of `to`'s (column vectors:
/// rgb_to = M * rgb_from), through CIE XYZ, with Bradford chromatic adaptation when the white
/// points differ (as ACES and MaterialX's cmlib convert between D60 and D65).
glm::mat3 primariesConversion(Primaries from, Primaries to);

/// True when the texels of a colour texture in the space named `name` are decoded by the device
/// (an sRGB-encoded space, read through an sRGB format): the renderer picks the format and the
/// lowering leaves the decoding out of the shader by this one rule.
bool deviceDecodes(std::string_view name);

}  // namespace mxc
