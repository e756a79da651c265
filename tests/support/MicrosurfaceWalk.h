#pragma once
/// \file
/// A random walk on a GGX microsurface (Heitz, Hanika, d'Eon and Dachsbacher 2016,
/// "Multiple-scattering microfacet BSDFs with the Smith model"), in double precision on the
/// CPU: the multiple-scattering ground truth of a single rough interface, written from the
/// paper's model, for tests. Heights are uniform on [-1, 1] (the Smith model's results do not
/// depend on the height distribution). A ray is always expressed in the frame of the medium it
/// travels in, that medium above the surface: crossing a dielectric mirrors heights and
/// directions (the surface seen from below is a GGX surface of mirrored heights).
///
/// Why each step is what it is:
/// - between heights h < h', a ray going up is unmasked with probability (C1(h) / C1(h'))^L
///   (L = Lambda of its direction), so it leaves from h with probability G1 = C1(h)^L; a ray
///   going down also needs the point to be above the surface there: (C1(h') / C1(h))^(1 + L)
///   with L the Lambda of the upward mirror (Heitz et al. 2016, s. 3; Heitz 2014, s. 6);
/// - the microfacet a ray meets is a visible normal of the direction it comes from, sampled by
///   stretching, sampling the visible hemisphere's projection and unstretching (Heitz 2018),
///   which also covers directions below the horizon (rays going up meet microfacets that face
///   down-going light): the projection is then the half disk outside the horizon's ellipse,
///   which the same warp of a uniform disk covers uniformly;
/// - a conductor reflects with weight F; a dielectric reflects with probability F and refracts
///   otherwise (a white walk: no weight).

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include <glm/glm.hpp>

#include "support/ClosedForms.h"

namespace mxc::test::walk {

using Vec = glm::dvec3;

/// Smith's Lambda of GGX (Heitz 2014, eq. 86) for the upward direction (w.x, w.y, |w.z|).
inline double lambda(Vec w, double alpha) {
  const double z2 = w.z * w.z;
  if (z2 <= 0.0) return 1e300;
  return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * (w.x * w.x + w.y * w.y) / z2));
}

/// A visible normal of GGX for the direction v (|v| = 1, any z), from two uniform numbers.
inline Vec visibleNormal(Vec v, double alpha, double u1, double u2) {
  const Vec vh = glm::normalize(Vec(alpha * v.x, alpha * v.y, v.z));
  const double lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec t1 = lensq > 0.0 ? (1.0 / std::sqrt(lensq)) * Vec(-vh.y, vh.x, 0.0) : Vec(1.0, 0.0, 0.0);
  const Vec t2 = glm::cross(vh, t1);
  const double r = std::sqrt(u1), phi = 2.0 * 3.14159265358979323846 * u2;
  const double p1 = r * std::cos(phi);
  double p2 = r * std::sin(phi);
  const double s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
  const Vec nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return glm::normalize(Vec(alpha * nh.x, alpha * nh.y, std::max(nh.z, 1e-12)));
}

/// The outcome of walks from one view: the albedo reflected and transmitted, all orders and
/// single scattering alone, and the walks cut at the bounce limit.
struct Albedo {
  double reflected = 0.0, transmitted = 0.0;
  double reflectedSingle = 0.0, transmittedSingle = 0.0;
  double cut = 0.0;
  double total() const { return reflected + transmitted; }
};

/// Walks from the view wo (wo.z > 0) on a surface of roughness alpha. `eta` > 0: a dielectric
/// of that IOR ratio (below over above); `eta` = 0: a conductor of Fresnel `conductor(cos)`.
inline Albedo albedo(Vec wo, double alpha, double eta, const std::function<double(double)>& conductor, int walks,
                     uint64_t seed = 1, int maxBounces = 1000) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto u = [&]() { return std::max(uniform(random), 1e-300); };  // in (0, 1): logs and roots stay finite
  auto c1 = [](double h) { return std::clamp(0.5 * (h + 1.0), 0.0, 1.0); };
  Albedo out;
  for (int k = 0; k < walks; ++k) {
    Vec w = -wo;
    double h = 1.0;  // the top of the surface: nothing above it masks
    bool inside = false;
    double eta0 = eta, weight = 1.0;
    for (int bounce = 1;; ++bounce) {
      if (bounce > maxBounces) {
        out.cut += 1.0;
        break;
      }
      // The next height the ray meets the surface at, or its escape.
      const double l = lambda(w, alpha);
      double c;
      if (w.z > 0.0) {
        c = c1(h) * std::pow(u(), -1.0 / std::max(l, 1e-300));
        if (c >= 1.0 || l <= 0.0) {  // escaped (Lambda 0: straight up, nothing masks)
          const bool single = bounce == 2;
          (inside ? out.transmitted : out.reflected) += weight;
          if (single) (inside ? out.transmittedSingle : out.reflectedSingle) += weight;
          break;
        }
      } else {
        c = c1(h) * std::pow(u(), 1.0 / (1.0 + l));
      }
      h = 2.0 * c - 1.0;
      // The microfacet: a visible normal of the direction the ray comes from.
      const Vec wi = -w;
      const Vec m = visibleNormal(wi, alpha, u(), u());
      const double cosm = glm::dot(wi, m);
      if (eta0 <= 0.0) {
        weight *= conductor(std::max(cosm, 0.0));
        w = w - 2.0 * glm::dot(w, m) * m;
        continue;
      }
      const double f = closed::fresnel(std::max(cosm, 0.0), eta0);
      if (u() < f) {
        w = w - 2.0 * glm::dot(w, m) * m;
        continue;
      }
      // Refraction into the other medium (Snell in vector form, cosm > 0 when f < 1), then the
      // frame of that medium: heights and directions mirrored.
      const double r = 1.0 / eta0, cost = std::sqrt(std::max(0.0, 1.0 - r * r * (1.0 - cosm * cosm)));
      w = r * w + (r * cosm - cost) * m;
      w.z = -w.z;
      h = -h;
      inside = !inside;
      eta0 = 1.0 / eta0;
    }
  }
  for (double* v : {&out.reflected, &out.transmitted, &out.reflectedSingle, &out.transmittedSingle, &out.cut}) {
    *v /= walks;
  }
  return out;
}

}  // namespace mxc::test::walk
