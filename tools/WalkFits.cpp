#include "tools/WalkFits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "compiler/glsl/Bindings.h"
#include "compiler/glsl/WalkTables.h"

#include <fmt/format.h>

namespace mxc::tools {

std::string writeMeasurements(const std::vector<WalkMeasurement>& measurements) {
  std::string out = "kind,eta,g,roughness,x,value,error\n";
  for (const WalkMeasurement& m : measurements) {
    out += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", m.kind, m.eta, m.g, m.roughness, m.x, m.value,
                       m.error);
  }
  return out;
}

std::vector<WalkMeasurement> readMeasurements(const std::string& text) {
  std::vector<WalkMeasurement> out;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1 || line.empty()) continue;  // the header
    std::istringstream row(line);
    WalkMeasurement m;
    std::string field;
    std::vector<std::string> fields;
    while (std::getline(row, field, ',')) fields.push_back(field);
    if (fields.size() != 7) throw std::runtime_error(fmt::format("measurements line {}: 7 fields expected", number));
    try {
      m.kind = fields[0];
      m.eta = std::stod(fields[1]);
      m.g = std::stod(fields[2]);
      m.roughness = std::stod(fields[3]);
      m.x = std::stod(fields[4]);
      m.value = std::stod(fields[5]);
      m.error = std::stod(fields[6]);
    } catch (const std::exception&) {
      throw std::runtime_error(fmt::format("measurements line {}: not a number", number));
    }
    out.push_back(m);
  }
  return out;
}

void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  // Newton's method on the Legendre polynomial P_n from the usual cosine guesses (Abramowitz
  // and Stegun 25.4.29), mapped from [-1, 1] to [0, 1].
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);  // |x| < 1 at the roots
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    nodes[i] = 0.5 * (1.0 - x);
    weights[i] = 1.0 / ((1.0 - x * x) * dp * dp);
  }
}

namespace {

/// The measurements of one grid point, by kind and the grid's indices.
bool near(double a, double b) { return std::abs(a - b) < 1e-6; }

/// The measured curve C(s): van de Hulst's form (1 - s)(1 + a s) / (1 + b s) (OpenPBR
/// "Subsurface") with one more numerator term, (1 - s)(1 + a1 s + a2 s^2) / (1 + b s). C(0) = 1
/// (omega = 1 returns everything) and C(1) = 0 (omega = 0 returns nothing) hold for any
/// coefficients. Chosen by the fits' residuals over the 585 measured curves: chi^2 per degree of
/// freedom 0.7 on average; van de Hulst's own two coefficients, 2.4; with c s^2 in the
/// denominator as well, poles inside [0, 1] in a fifth of the curves.
struct MediumCurve {
  double a1 = -0.139, a2 = 0.0, b = 1.17;
  double denominator(double s) const { return 1.0 + b * s; }
  double operator()(double s) const { return (1.0 - s) * (1.0 + a1 * s + a2 * s * s) / denominator(s); }
};

/// Solves the 3 x 3 system m x = r by Gaussian elimination with partial pivoting; false when
/// it is singular.
bool solve3(double m[3][3], double r[3], double x[3]) {
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int row = col + 1; row < 3; ++row) {
      if (std::abs(m[row][col]) > std::abs(m[pivot][col])) pivot = row;
    }
    if (std::abs(m[pivot][col]) < 1e-300) return false;
    std::swap(m[col], m[pivot]);
    std::swap(r[col], r[pivot]);
    for (int row = col + 1; row < 3; ++row) {
      const double f = m[row][col] / m[col][col];  // the pivot is not 0
      for (int k = col; k < 3; ++k) m[row][k] -= f * m[col][k];
      r[row] -= f * r[col];
    }
  }
  for (int row = 2; row >= 0; --row) {
    double v = r[row];
    for (int k = row + 1; k < 3; ++k) v -= m[row][k] * x[k];
    x[row] = v / m[row][row];  // not 0: checked while eliminating
  }
  return true;
}

struct Point {
  double s, c, error;
};

/// The weighted least-squares fit of the form to the points by Sanathanan-Koerner iteration:
/// each step minimises sum ((1 - s)(1 + a1 s + a2 s^2) - C D(s)) / (D_previous(s) sigma))^2,
/// linear in a1, a2 and b, which converges to the fit of C itself.
MediumCurve fitCurve(const std::vector<Point>& points) {
  MediumCurve curve;
  for (int iteration = 0; iteration < 60; ++iteration) {
    double m[3][3] = {}, r[3] = {};
    for (const Point& p : points) {
      // Both factors > 0: the denominator is checked on [0, 1] after the fit (a step whose D
      // falls to 0 is refused below), errors are floored at 1e-4.
      const double w = 1.0 / (std::max(curve.denominator(p.s), 1e-6) * p.error);
      const double row[3] = {(1.0 - p.s) * p.s * w, (1.0 - p.s) * p.s * p.s * w, -p.c * p.s * w};
      const double target = (p.c - (1.0 - p.s)) * w;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
        r[i] += row[i] * target;
      }
    }
    double x[3];
    if (!solve3(m, r, x)) throw std::runtime_error("a medium curve's fit is singular");
    curve = {x[0], x[1], x[2]};
  }
  return curve;
}

}  // namespace

std::vector<float> walkTableRows(const std::vector<WalkMeasurement>& measurements) {
  const uint32_t n = glsl::kTableSize;
  std::vector<float> rows(size_t{glsl::kWalkTableRows} * n * 4, 0.0f);
  auto texel = [&](uint32_t row, uint32_t column) -> float* { return &rows[(size_t{row} * n + column) * 4]; };
  std::vector<double> mus, weights;
  gaussLegendre(kInterfaceViews, mus, weights);

  // The gloss rows: r_i = 1 - (1 - R_out) / eta^2, R_out = 2 integral R(mu) mu dmu.
  for (uint32_t e = 0; e < glsl::kWalkEtaSteps; ++e) {
    const double eta = glsl::walkTableEta(int(e));
    for (uint32_t i = 0; i < n; ++i) {
      const double roughness = double(i) / (n - 1.0);
      double integral = 0.0;
      int found = 0;
      for (const WalkMeasurement& m : measurements) {
        if (m.kind != "interface" || !near(m.eta, eta) || !near(m.roughness, roughness)) continue;
        for (int k = 0; k < kInterfaceViews; ++k) {
          if (near(m.x, mus[k])) {
            integral += weights[k] * 2.0 * mus[k] * m.value;
            ++found;
          }
        }
      }
      if (found != kInterfaceViews) {
        throw std::runtime_error(fmt::format("interface eta {} roughness {}: {} of {} views measured", eta, roughness, found,
                                             kInterfaceViews));
      }
      texel(e, i)[0] = float(1.0 - (1.0 - integral) / (eta * eta));  // eta >= 1
      texel(e, i)[1] = float(integral);
    }
  }

  // The reflectance rows, as measured; and, as a check of both, the cosine-weighted integral of
  // each row (trapezoids in sqrt(mu), the grid's own axis) against the Gauss-Legendre one.
  double worstIntegral = 0.0;
  for (uint32_t e = 0; e < glsl::kWalkEtaSteps; ++e) {
    const double eta = glsl::walkTableEta(int(e));
    for (uint32_t j = 0; j < n; ++j) {
      const double roughness = double(j) / (n - 1.0);
      const uint32_t row = glsl::kWalkReflectanceRow - glsl::kWalkGlossRow + e * n + j;
      uint32_t found = 0;
      for (const WalkMeasurement& m : measurements) {
        if (m.kind != "reflectance" || !near(m.eta, eta) || !near(m.roughness, roughness)) continue;
        for (uint32_t i = 0; i < n; ++i) {
          if (near(m.x, std::max(std::pow(double(i) / (n - 1.0), 2.0), 1e-4))) {
            texel(row, i)[0] = float(m.value);
            ++found;
          }
        }
      }
      if (found != n) {
        throw std::runtime_error(fmt::format("reflectance eta {} roughness {}: {} of {} views measured", eta, roughness,
                                             found, n));
      }
      // R_out = integral_0^1 R 2 mu dmu = integral_0^1 R(u^2) 4 u^3 du.
      double integral = 0.0;
      for (uint32_t i = 0; i + 1 < n; ++i) {
        const double u0 = double(i) / (n - 1.0), u1 = double(i + 1) / (n - 1.0);
        integral += 0.5 * (u1 - u0) * (texel(row, i)[0] * 4.0 * u0 * u0 * u0 + texel(row, i + 1)[0] * 4.0 * u1 * u1 * u1);
      }
      worstIntegral = std::max(worstIntegral, std::abs(integral - texel(e, j)[1]));
    }
  }
  std::fprintf(stderr, "  reflectance rows: their integral is the Gauss-Legendre one within %.5f\n", worstIntegral);

  // The medium rows: per (roughness, g, eta), the curve C(s) fitted, then s at C = i / (n - 1).
  double worstChi2 = 0.0, sumChi2 = 0.0;
  int curves = 0;
  for (uint32_t r = 0; r < glsl::kWalkRoughnessSteps; ++r) {
    for (uint32_t gi = 0; gi < glsl::kWalkAnisotropySteps; ++gi) {
      for (uint32_t e = 0; e < glsl::kWalkEtaSteps; ++e) {
        const double eta = glsl::walkTableEta(int(e)), g = glsl::walkTableAnisotropy(int(gi));
        const double roughness = glsl::walkTableRoughness(int(r));
        std::vector<const WalkMeasurement*> found;
        const WalkMeasurement* specular = nullptr;
        for (const WalkMeasurement& m : measurements) {
          if (m.kind != "medium" || !near(m.eta, eta) || !near(m.g, g) || !near(m.roughness, roughness)) continue;
          if (near(m.x, 1.0)) {
            specular = &m;
          } else {
            found.push_back(&m);
          }
        }
        if (!specular || found.size() != size_t(kMediumSteps - 1)) {
          throw std::runtime_error(fmt::format("medium eta {} g {} roughness {}: not every s measured", eta, g, roughness));
        }
        // C = (E - E_spec) / (1 - E_spec): of what the interface lets in, what comes back out.
        const double espec = specular->value;
        std::vector<Point> points;
        for (const WalkMeasurement* m : found) {
          // The error of C: the estimate's, scaled; floored at 1e-4 (the fit's weights divide by it).
          points.push_back({m->x, (m->value - espec) / (1.0 - espec), std::max(m->error / (1.0 - espec), 1e-4)});
        }
        points.push_back({0.0, 1.0, 1e-4});  // omega = 1: a white half-space returns everything
        const MediumCurve curve = fitCurve(points);
        double chi2 = 0.0;
        for (const Point& p : points) chi2 += (curve(p.s) - p.c) * (curve(p.s) - p.c) / (p.error * p.error);
        chi2 /= double(points.size() - 3);
        worstChi2 = std::max(worstChi2, chi2);
        sumChi2 += chi2;
        ++curves;
        // The inverse of C(s) on [0, 1]: of its running minimum, which is C itself where C falls
        // (everywhere but within 1e-5 of 0 near s = 1 on a few curves, where the fitted numerator
        // crosses 0 just before s = 1), with a positive denominator.
        constexpr int kSteps = 4000;
        std::vector<double> envelope(kSteps + 1);
        for (int k = 0; k <= kSteps; ++k) {
          const double x = double(k) / kSteps;
          if (!(curve.denominator(x) > 0.0)) {
            throw std::runtime_error(fmt::format("medium eta {} g {} roughness {}: the fit has a pole at s = {}", eta, g,
                                                 roughness, x));
          }
          envelope[k] = std::clamp(k ? std::min(envelope[k - 1], curve(x)) : 1.0, 0.0, 1.0);
        }
        if (envelope[kSteps / 2] < 1e-4 || curve(0.999) < -1e-3) {
          throw std::runtime_error(fmt::format("medium eta {} g {} roughness {}: the fitted C(s) falls below 0", eta, g,
                                               roughness));
        }
        const uint32_t row = glsl::kWalkEtaSteps + (r * glsl::kWalkAnisotropySteps + gi) * glsl::kWalkEtaSteps + e;
        for (uint32_t i = 0; i < n; ++i) {
          // The first step where the envelope reaches the colour, interpolated within it.
          const double target = double(i) / (n - 1.0);
          double s = 1.0;
          for (int k = 1; k <= kSteps; ++k) {
            if (envelope[k] <= target) {
              const double drop = envelope[k - 1] - envelope[k];
              s = (k - 1 + (drop > 0.0 ? (envelope[k - 1] - target) / drop : 1.0)) / kSteps;
              break;
            }
          }
          texel(row, i)[0] = float(i == 0 ? 1.0 : s);  // C = 0: s = 1 (omega = 0) exactly
          texel(row, i)[1] = float(espec);
        }
      }
    }
  }
  std::fprintf(stderr, "  %d medium curves fitted: chi^2 per degree of freedom %.2f on average, %.2f at worst\n", curves,
               sumChi2 / std::max(curves, 1), worstChi2);
  return rows;
}

}  // namespace mxc::tools
