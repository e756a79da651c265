#pragma once
/// \file
/// The accuracy tier of a compilation: how exactly the generated shader evaluates layering and
/// multiple scattering. One option of the compile request, read by the back end and visible to
/// the IR passes (PassContext); the IR itself does not change with it.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace mxc {

enum class Accuracy : uint8_t {
  /// The cheapest tier a real-time renderer ships, the class of MaterialX's generator: albedo
  /// scaling through the slabs with directional albedos from analytic fits (no table fetch),
  /// the split-sum (Schlick-shaped) Fresnel in every albedo, separable Smith masking for
  /// refraction, no multiple-scattering compensation.
  Fast,
  /// Albedo scaling through the slabs with tabulated albedos (exact Fresnel), coat darkening and
  /// view-dependent absorption (OpenPBR "Reduction to a mixture of lobes"), multiple-scattering
  /// energy compensation of every rough microfacet lobe (Turquin 2019) from tables of
  /// single-scattering albedos, and height-correlated masking for refraction (Heitz 2014).
  Balanced,
  /// The ground truth the others are measured against: a Monte Carlo random walk through the
  /// slab stacks, with multiple scattering on every rough microsurface (Heitz et al. 2016) and
  /// in every medium (Guo et al. 2018); eval is an unbiased estimate.
  Reference,
};

/// Every tier, cheapest first.
inline constexpr std::array<Accuracy, 3> kAccuracies = {Accuracy::Fast, Accuracy::Balanced, Accuracy::Reference};

inline std::string_view accuracyName(Accuracy accuracy) {
  switch (accuracy) {
    case Accuracy::Fast: return "fast";
    case Accuracy::Balanced: return "balanced";
    case Accuracy::Reference: return "reference";
  }
  return "?";
}

/// What a tier does, in one line (inspect shows it).
inline std::string_view accuracyDescription(Accuracy accuracy) {
  switch (accuracy) {
    case Accuracy::Fast:
      return "albedo scaling with fitted directional albedos, Schlick Fresnel for dielectrics, no "
             "multiple-scattering compensation, first-order thin film";
    case Accuracy::Balanced:
      return "albedo scaling with tabulated directional albedos, exact Fresnel, multiple-scattering "
             "compensation of rough microfacet lobes (Turquin 2019), height-correlated refraction masking";
    case Accuracy::Reference:
      return "Monte Carlo random walk through the slab stacks: microsurface walks on rough interfaces (Heitz et al. "
             "2016), volumetric walks in media, eval an unbiased estimate";
  }
  return "?";
}

/// The tier of a name, as the command line spells it.
inline std::optional<Accuracy> parseAccuracy(std::string_view name) {
  for (Accuracy a : kAccuracies) {
    if (accuracyName(a) == name) return a;
  }
  return std::nullopt;
}

}  // namespace mxc
