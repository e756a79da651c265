#include "runtime/EnvironmentDistribution.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mxc::rt {

namespace {

constexpr double kPi = 3.14159265358979323846;

double luminance(const float* rgb) {
  // Rec.709 weights, as mxc_luminance; negative channels (image processing undershoot) add no light.
  return 0.2126 * std::max(rgb[0], 0.0f) + 0.7152 * std::max(rgb[1], 0.0f) + 0.0722 * std::max(rgb[2], 0.0f);
}

}  // namespace

glm::vec2 equirectUv(const glm::vec3& d) {
  // At the poles every longitude is the same point (and atan2(0, 0) is arbitrary).
  const float u = std::abs(d.x) + std::abs(d.z) > 1e-12f ? 0.5f + std::atan2(d.x, -d.z) / float(2.0 * kPi) : 0.5f;
  const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / float(kPi);  // clamp: acos's domain
  return {u, v};
}

glm::vec3 equirectDirection(const glm::vec2& uv) {
  const double phi = 2.0 * kPi * (double(uv.x) - 0.5);
  const double theta = kPi * double(uv.y);
  const double r = std::sin(theta);
  return glm::vec3(float(r * std::sin(phi)), float(std::cos(theta)), float(-r * std::cos(phi)));
}

glm::vec3 environmentToMap(const glm::vec3& w, float radians) {
  const float c = std::cos(radians), s = std::sin(radians);
  return {c * w.x - s * w.z, w.y, s * w.x + c * w.z};
}

glm::vec3 environmentToWorld(const glm::vec3& m, float radians) {
  const float c = std::cos(radians), s = std::sin(radians);
  return {c * m.x + s * m.z, m.y, -s * m.x + c * m.z};
}

EnvironmentDistribution EnvironmentDistribution::build(const RgbaImage& radiance, uint32_t maxWidth) {
  EnvironmentDistribution d;
  if (radiance.width == 0 || radiance.height == 0) return d;  // one black cell
  maxWidth = std::max(maxWidth, 2u);
  d.width = std::min(radiance.width, maxWidth);
  d.height = std::min(radiance.height, maxWidth / 2);
  const size_t n = size_t{d.width} * d.height;

  // Each cell's weight is the largest luminance the renderer's bilinear lookup can return in it:
  // the maximum over the texels whose centres it holds and their neighbours (one texel around,
  // wrapping across, clamped down). With the mean instead, a direction in a dark cell beside a
  // bright one (a softbox's edge) reads light interpolated from the bright texel while its
  // density is the dark cell's: the closure's samples would carry nearly all of it, as fireflies.
  // Texels [floor(i W / w), floor((i + 1) W / w)) are the cell's, at least one since w <= W.
  std::vector<double> weight(n, 0.0);
  std::vector<double> rowMax(size_t{radiance.width} * d.height, 0.0);  // per cell row, per texel column
  for (uint32_t j = 0; j < d.height; ++j) {
    const int64_t y0 = int64_t(uint64_t{j} * radiance.height / d.height) - 1;
    const int64_t y1 = std::max<int64_t>(y0 + 2, int64_t(uint64_t{j + 1} * radiance.height / d.height)) + 1;
    for (int64_t y = std::max<int64_t>(y0, 0); y < std::min<int64_t>(y1, radiance.height); ++y) {
      for (uint32_t x = 0; x < radiance.width; ++x) {
        double& m = rowMax[size_t{j} * radiance.width + x];
        m = std::max(m, luminance(radiance.at(x, uint32_t(y))));
      }
    }
  }
  double total = 0.0;
  const int64_t w = radiance.width;
  for (uint32_t j = 0; j < d.height; ++j) {
    const double solidAngle = d.cellSolidAngle(j);
    for (uint32_t i = 0; i < d.width; ++i) {
      const int64_t x0 = int64_t(uint64_t{i} * radiance.width / d.width) - 1;
      const int64_t x1 = std::max<int64_t>(x0 + 2, int64_t(uint64_t{i + 1} * radiance.width / d.width)) + 1;
      double m = 0.0;
      for (int64_t x = x0; x < x1; ++x) m = std::max(m, rowMax[size_t{j} * radiance.width + size_t(((x % w) + w) % w)]);
      weight[size_t{j} * d.width + i] = m * solidAngle;  // the cell's share of the (bounding) power
      total += m * solidAngle;
    }
  }
  d.cells.assign(n, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
  for (size_t k = 0; k < n; ++k) {
    uint32_t self = uint32_t(k);
    std::memcpy(&d.cells[k].y, &self, 4);
  }
  if (!(total > 0.0) || !std::isfinite(total)) return d;  // black: nothing to sample, every pdf 0

  // Density per steradian: the cell's share of the power over its solid angle.
  for (uint32_t j = 0; j < d.height; ++j) {
    const double solidAngle = d.cellSolidAngle(j);  // > 0 for every row (its latitudes differ)
    for (uint32_t i = 0; i < d.width; ++i) {
      const size_t k = size_t{j} * d.width + i;
      d.cells[k].z = float(weight[k] / total / solidAngle);  // total > 0
    }
  }

  // The alias table (Vose 1991): probabilities scaled so that their mean is 1; each cell below
  // 1 is topped up by one above 1, which becomes its alias.
  std::vector<double> scaled(n);
  std::vector<uint32_t> small, large;
  for (size_t k = 0; k < n; ++k) {
    scaled[k] = weight[k] / total * double(n);  // total > 0
    (scaled[k] < 1.0 ? small : large).push_back(uint32_t(k));
  }
  while (!small.empty() && !large.empty()) {
    const uint32_t s = small.back();
    small.pop_back();
    const uint32_t l = large.back();
    d.cells[s].x = float(scaled[s]);
    std::memcpy(&d.cells[s].y, &l, 4);
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // What is left is 1 up to rounding: kept always (their alias is themselves).
  for (uint32_t k : small) d.cells[k].x = 1.0f;
  for (uint32_t k : large) d.cells[k].x = 1.0f;
  return d;
}

double EnvironmentDistribution::cellSolidAngle(uint32_t row) const {
  // Longitude 2 pi / width times the band of cos(theta) between the row's edges.
  const double z0 = std::cos(kPi * double(row) / double(height));
  const double z1 = std::cos(kPi * double(row + 1) / double(height));
  return 2.0 * kPi / double(width) * (z0 - z1);
}

float EnvironmentDistribution::pdf(const glm::vec3& direction) const {
  const glm::vec2 uv = equirectUv(direction);
  const uint32_t i = std::min(uint32_t(std::max(uv.x, 0.0f) * float(width)), width - 1);
  const uint32_t j = std::min(uint32_t(std::max(uv.y, 0.0f) * float(height)), height - 1);
  return cells[size_t{j} * width + i].z;
}

std::vector<uint8_t> EnvironmentDistribution::bufferBytes() const {
  std::vector<uint8_t> bytes(16 + cells.size() * sizeof(glm::vec4), 0);
  const uint32_t header[4] = {width, height, 0, 0};
  std::memcpy(bytes.data(), header, 16);
  std::memcpy(bytes.data() + 16, cells.data(), cells.size() * sizeof(glm::vec4));
  return bytes;
}

glm::vec3 equirectLookup(const RgbaImage& radiance, const glm::vec3& direction) {
  if (radiance.width == 0 || radiance.height == 0) return glm::vec3(0.0f);
  const glm::vec2 uv = equirectUv(direction);
  // Texel centres at (x + 0.5) / W, as Vulkan's linear filter.
  const float fx = uv.x * float(radiance.width) - 0.5f;
  const float fy = std::clamp(uv.y * float(radiance.height) - 0.5f, 0.0f, float(radiance.height - 1));
  const float x0f = std::floor(fx), y0f = std::floor(fy);
  const float tx = fx - x0f, ty = fy - y0f;
  const int w = int(radiance.width), h = int(radiance.height);
  auto wrap = [w](int x) { return ((x % w) + w) % w; };  // w > 0
  const int xa = wrap(int(x0f)), xb = wrap(int(x0f) + 1);
  const int ya = std::clamp(int(y0f), 0, h - 1), yb = std::clamp(int(y0f) + 1, 0, h - 1);
  glm::vec3 out(0.0f);
  const float weights[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
  const int xs[4] = {xa, xb, xa, xb}, ys[4] = {ya, ya, yb, yb};
  for (int k = 0; k < 4; ++k) {
    const float* p = radiance.at(uint32_t(xs[k]), uint32_t(ys[k]));
    out += weights[k] * glm::vec3(p[0], p[1], p[2]);
  }
  return out;
}

}  // namespace mxc::rt
