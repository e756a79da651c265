#pragma once
/// \file
/// Closed forms that the physical tests compare against, computed in double precision by
/// their own quadrature, independently of the shader library (physics notes 2.3, 2.5, 2.9):
/// the exact dielectric Fresnel and its hemispherical averages, the interfaced Lambertian, and
/// Chandrasekhar's H-function with the albedo of a semi-infinite isotropically scattering
/// medium. Each is checked against published values in tests/support/ClosedFormsTest.cpp.

#include <cmath>
#include <vector>

namespace mxc::test::closed {

/// Unpolarised Fresnel reflectance of a dielectric interface for the incident cosine `cosi`
/// and the relative IOR eta = n(transmitted side) / n(incident side) (Born & Wolf 1999,
/// s. 1.5.2); total internal reflection gives 1.
inline double fresnel(double cosi, double eta) {
  const double sin2t = (1.0 - cosi * cosi) / (eta * eta);  // eta > 0
  if (sin2t >= 1.0) return 1.0;
  const double cost = std::sqrt(1.0 - sin2t);
  const double rs = (cosi - eta * cost) / (cosi + eta * cost);  // denominators > 0 unless both cosines are 0
  const double rp = (eta * cosi - cost) / (eta * cosi + cost);
  return 0.5 * (rs * rs + rp * rp);
}

/// The cosine-weighted hemispherical average 2 integral_0^1 F(mu, eta) mu dmu, by the midpoint
/// rule on 200,000 intervals (error below 1e-9 for the smooth integrand; with total internal
/// reflection the kink at the critical angle costs at most one interval's width, 5e-6).
inline double fresnelAverage(double eta) {
  constexpr int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double mu = (i + 0.5) / n;
    sum += fresnel(mu, eta) * 2.0 * mu;
  }
  return sum / n;
}

/// A Lambertian base of albedo rho under a smooth dielectric of relative IOR eta (> 1), lit
/// from outside at cosine mu: the light refracted in is reflected diffusely by the base and
/// bounces between base and interface, leaving through it with the internal hemispherical
/// transmittance (Elias 2001; physics notes 2.9):
/// A = F(mu) + (1 - F(mu)) rho (1 - F_in) / (1 - rho F_in), F_in = fresnelAverage(1 / eta).
inline double interfacedLambertian(double mu, double rho, double eta) {
  const double fin = fresnelAverage(1.0 / eta);
  return fresnel(mu, eta) + (1.0 - fresnel(mu, eta)) * rho * (1.0 - fin) / (1.0 - rho * fin);  // rho F_in < 1
}

/// Gauss-Legendre nodes and weights on [0, 1], by Newton's method on the Legendre polynomial
/// P_n from the usual cosine guesses (Abramowitz & Stegun 25.4.29).
inline void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);  // P_n'(x); |x| < 1 at the roots
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    nodes[i] = 0.5 * (1.0 - x);                     // [-1, 1] to [0, 1]
    weights[i] = 1.0 / ((1.0 - x * x) * dp * dp);  // 2 / ((1 - x^2) P_n'^2), halved for [0, 1]
  }
}

/// Chandrasekhar's H-function for isotropic scattering of single-scattering albedo omega <= 1,
/// on the nodes of a 64-point Gauss-Legendre rule, by iterating its equivalent form
/// 1 / H(mu) = sqrt(1 - omega) + (omega / 2) integral_0^1 mu' H(mu') / (mu + mu') dmu'
/// (Chandrasekhar 1960, "Radiative Transfer", ch. V), from H = 1 until it changes by less than
/// 1e-14. Each step takes the geometric mean of H and the equation's right-hand side: in the
/// conservative case the plain iteration maps c H to H / c and oscillates for ever, and the mean
/// removes that mode (about 45 steps for any omega). Returns H at `mu` by the same equation with
/// the converged H under the integral (the Nystrom interpolation).
inline double chandrasekharH(double omega, double mu) {
  std::vector<double> x, w;
  gaussLegendre(64, x, w);
  std::vector<double> h(x.size(), 1.0);
  const double root = std::sqrt(std::max(0.0, 1.0 - omega));
  auto apply = [&](double m) {
    double integral = 0.0;
    for (size_t j = 0; j < x.size(); ++j) integral += w[j] * x[j] * h[j] / (m + x[j]);  // x_j > 0
    return 1.0 / (root + 0.5 * omega * integral);  // > 0: H > 0 keeps the integral positive
  };
  for (int it = 0; it < 1000; ++it) {
    double change = 0.0;
    std::vector<double> next(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      next[i] = std::sqrt(h[i] * apply(x[i]));  // both > 0
      change = std::max(change, std::abs(next[i] - h[i]));
    }
    h.swap(next);
    if (change < 1e-14) break;
  }
  return apply(mu);
}

/// The directional-hemispherical albedo of a semi-infinite, isotropically scattering medium of
/// single-scattering albedo omega without an interface, lit at cosine mu:
/// A(mu) = 1 - H(mu) sqrt(1 - omega) (physics notes 2.9).
inline double semiInfiniteAlbedo(double omega, double mu) {
  return 1.0 - chandrasekharH(omega, mu) * std::sqrt(std::max(0.0, 1.0 - omega));
}

}  // namespace mxc::test::closed
