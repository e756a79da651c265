#include "compiler/glsl/WalkTables.h"

#include <algorithm>
#include <cmath>

#include "compiler/glsl/AlbedoTableFile.h"
#include "compiler/glsl/Bindings.h"

namespace mxc::glsl {

namespace {

/// A fractional index on a grid of `steps` values from a coordinate mapped to [0, 1].
double gridIndex(double unit, uint32_t steps) { return std::clamp(unit, 0.0, 1.0) * (steps - 1.0); }

/// The .x of the image at fractional texel coordinates (column, row), bilinear between texel
/// centres as the sampler filters: the rows `row` and `row + 1` (a caller keeps row within its
/// block, where the weight of a row beyond it is 0).
double texel(double column, double row) {
  const AlbedoTableData& t = committedAlbedoTables();
  const double c = std::clamp(column, 0.0, kTableSize - 1.0), r = std::clamp(row, 0.0, kTableHeight - 1.0);
  const uint32_t c0 = std::min(static_cast<uint32_t>(c), kTableSize - 2), r0 = std::min(static_cast<uint32_t>(r), kTableHeight - 2);
  const double fc = c - c0, fr = r - r0;
  auto at = [&](uint32_t i, uint32_t j) { return double(t.texels[(size_t{j} * t.width + i) * 4]); };
  return (1.0 - fr) * ((1.0 - fc) * at(c0, r0) + fc * at(c0 + 1, r0)) + fr * ((1.0 - fc) * at(c0, r0 + 1) + fc * at(c0 + 1, r0 + 1));
}

/// eta's fractional index: u = (eta - 1) / (eta + 1) over [0, 0.5].
double etaIndex(double eta) { return gridIndex((std::max(eta, 1.0) - 1.0) / (std::max(eta, 1.0) + 1.0) / 0.5, kWalkEtaSteps); }

}  // namespace

double walkTableEta(int k) {
  const double u = 0.5 * k / (kWalkEtaSteps - 1.0);
  return (1.0 + u) / (1.0 - u);  // u <= 0.5
}
double walkTableAnisotropy(int k) { return -0.9 + 1.8 * k / (kWalkAnisotropySteps - 1.0); }
double walkTableRoughness(int k) { return double(k) / (kWalkRoughnessSteps - 1.0); }

double walkInternalReflectance(double eta, double roughness) {
  return texel(gridIndex(roughness, kTableSize), kWalkGlossRow + etaIndex(eta));
}

double walkGlossAlbedo(double c, double eta, double roughness) {
  const double ri = walkInternalReflectance(eta, roughness);
  c = std::clamp(c, 0.0, 1.0);
  return c / (1.0 - ri + c * ri);  // >= 1 - r_i > 0 (r_i < 1 for eta <= 3)
}

double walkSubsurfaceAlbedo(double c, double eta, double g, double roughness) {
  const double column = gridIndex(c, kTableSize), e = etaIndex(eta);
  const double fg = gridIndex((g + 0.9) / 1.8, kWalkAnisotropySteps), fr = gridIndex(roughness, kWalkRoughnessSteps);
  const uint32_t g0 = std::min(static_cast<uint32_t>(fg), kWalkAnisotropySteps - 2);
  const uint32_t r0 = std::min(static_cast<uint32_t>(fr), kWalkRoughnessSteps - 2);
  double s = 0.0;
  for (uint32_t dr = 0; dr < 2; ++dr) {
    for (uint32_t dg = 0; dg < 2; ++dg) {
      const double w = (dg ? fg - g0 : 1.0 - (fg - g0)) * (dr ? fr - r0 : 1.0 - (fr - r0));
      const double row = kWalkMediumRow + double(((r0 + dr) * kWalkAnisotropySteps + g0 + dg) * kWalkEtaSteps) + e;
      s += w * texel(column, row);
    }
  }
  s = std::clamp(s, 0.0, 1.0);
  const double gc = std::clamp(g, -0.99, 0.99);
  return (1.0 - s * s) / (1.0 - gc * s * s);  // 1 - g s^2 >= 0.01
}

}  // namespace mxc::glsl
