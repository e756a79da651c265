#pragma once
/// \file
/// An independent reference for the reference tier: the albedo of a material's slab stacks by
/// an analog random walk on the CPU, in double precision, one colour channel at a time, written
/// from the papers and the IR's definitions, sharing no code with the shader walk
/// (compiler/glsl/library/mxc_walk.glsl) beyond the IR and the observed-albedo tables
/// (compiler/glsl/WalkTables.h, which define what the colours mean, not how light moves).
///
/// How it differs from the shader walk, on purpose:
/// - one channel per walk (the shader carries three and chooses free flights by one of them);
/// - analog: every factor f <= 1 is a survival probability, so a walk's outcome is 0 or 1 and
///   the standard error is binomial (the shader carries weights and uses Russian roulette);
/// - positions: a walk keeps its depth in each finite medium explicitly;
/// - layers are re-built from the IR's scattering tree here (ir/Scatter.h's semantics:
///   Slab{top, medium, base, coverage} == mix(base, layer(base, Slab(top, medium)), coverage)).
///
/// What light does at each kind of layer:
/// - a microfacet interface (GGX dielectric, conductor, F82-tint Schlick): the multiple-
///   scattering random walk on its microsurface (Heitz, Hanika, d'Eon and Dachsbacher 2016), with
///   uniform heights, anisotropic visible normals (Heitz 2018), Fresnel by Born and Wolf (complex
///   for conductors) or OpenPBR eq. F82 (Kutz et al. 2021); a smooth one (alpha < 1e-4) its
///   specular reflection and refraction. Tints: specular_color on the reflection from above,
///   the transmission tint on the crossing downwards (the IR's ReflectionTint, TransmissionTint);
/// - a Lambertian base; right under a dielectric, its albedo from base_color by the glossy-diffuse
///   constraint for that interface as the walk sees it (WalkTables.h); a subsurface medium's
///   likewise from subsurface_color;
/// - fuzz (OpenPBR "Fuzz", Zeltner, Burley and Chiang 2022): reflects E(mu) with colour
///   fuzz_color into the LTC lobe, and transmits 1 - E untinted, straight on ("the transmittance
///   is gray so the base is not tinted"), from either side;
/// - media: Beer-Lambert free flights, Henyey-Greenstein scattering (Pharr, Jakob and Humphreys
///   2023, s. 11.3), a finite thickness, a half-space (subsurface) or a clear bulk that what
///   enters leaves through (the closure sees one interface: a path of unit length in it, as the
///   shader assumes, mxc_walk.glsl MXC_BULK_PATH);
/// - a layer of coverage w is there for a walk with probability w.
///
/// Not covered (throws std::runtime_error): textures and other non-constant values, thin film,
/// specular_weight != 1, rough (Oren-Nayar) diffuse, sheen other than fuzz, diffuse transmission
/// and sheets, hair, transmitting Schlick lobes, Add and Tint nodes.

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "compiler/glsl/WalkTables.h"
#include "compiler/ir/Evaluate.h"
#include "compiler/ir/Material.h"
#include "support/ClosedForms.h"

namespace mxc::test::slab {

using Vec = glm::dvec3;
constexpr double kPi = 3.14159265358979323846;

/// Uniform numbers in (0, 1), so logarithms and negative powers stay finite.
class Random {
 public:
  explicit Random(uint64_t seed) : engine_(seed) {}
  double operator()() { return std::max(uniform_(engine_), 1e-300); }

 private:
  std::mt19937_64 engine_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
};

// ---- Fresnel ----

/// A conductor's reflectance for the complex IOR n + ik seen from a dielectric of IOR 1 (Born
/// and Wolf 1999, s. 14.2), by the complex form of the s and p amplitudes.
inline double conductorFresnel(double cosi, double n, double k) {
  cosi = std::clamp(cosi, 0.0, 1.0);
  const std::complex<double> eta(n, k), c(cosi, 0.0);
  const std::complex<double> cost = std::sqrt(1.0 - (1.0 - cosi * cosi) / (eta * eta));
  const std::complex<double> rs = (c - eta * cost) / (c + eta * cost);
  const std::complex<double> rp = (eta * c - cost) / (eta * c + cost);
  return std::clamp(0.5 * (std::norm(rs) + std::norm(rp)), 0.0, 1.0);
}

/// OpenPBR 1.1 "Metal", eq. F82: generalized Schlick F0 + (F90 - F0)(1 - mu)^p, less
/// mu (1 - mu)^6 / (mu_b (1 - mu_b)^6) (F_S(mu_b) - tint F_S(mu_b)) with mu_b = 1/7.
inline double f82Fresnel(double mu, double f0, double f90, double exponent, double tint) {
  mu = std::clamp(mu, 0.0, 1.0);
  auto schlick = [&](double m) { return f0 + (f90 - f0) * std::pow(1.0 - m, exponent); };
  const double mb = 1.0 / 7.0;
  const double correction = mu * std::pow(1.0 - mu, 6.0) / (mb * std::pow(1.0 - mb, 6.0)) * schlick(mb) * (1.0 - tint);
  return std::clamp(schlick(mu) - correction, 0.0, 1.0);
}

// ---- GGX microsurface (Heitz et al. 2016; Heitz 2018) ----

/// Smith's Lambda of anisotropic GGX for the direction w with |w.z| as its cosine.
inline double lambda(Vec w, double ax, double ay) {
  const double z2 = w.z * w.z;
  if (z2 <= 0.0) return 1e300;
  return 0.5 * (-1.0 + std::sqrt(1.0 + (ax * ax * w.x * w.x + ay * ay * w.y * w.y) / z2));
}

/// A visible normal of anisotropic GGX for v (any z): the stretched direction's projected
/// disk sampled uniformly (below the horizon, the half outside the horizon's ellipse).
inline Vec visibleNormal(Vec v, double ax, double ay, double u1, double u2) {
  const Vec vh = glm::normalize(Vec(ax * v.x, ay * v.y, v.z));
  const double lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec t1 = lensq > 0.0 ? (1.0 / std::sqrt(lensq)) * Vec(-vh.y, vh.x, 0.0) : Vec(1.0, 0.0, 0.0);
  const Vec t2 = glm::cross(vh, t1);
  const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  const double p1 = r * std::cos(phi);
  const double s = 0.5 * (1.0 + vh.z);
  const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
  const Vec nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return glm::normalize(Vec(ax * nh.x, ay * nh.y, std::max(nh.z, 1e-12)));
}

/// What an interface does to one walk: the direction it leaves in (travel, interface frame),
/// or none when the walk ends there (absorbed or cut).
using Outcome = std::optional<Vec>;

/// Survives with probability f (analog absorption); a factor above 1 is not expected here.
inline bool survive(double f, Random& u) { return u() < f; }

// ---- The layers of a stack ----

struct Interface {
  enum class Kind { None, Dielectric, Conductor, F82, Lambert, Fuzz } kind = Kind::None;
  double ax = 0.0, ay = 0.0;           ///< GGX alpha
  double n = 1.5;                      ///< Dielectric: absolute IOR (relative to the medium above when `relative`)
  bool relative = false;               ///< the IOR is relative to the medium above (IorReference::Ambient)
  bool reflects = true, transmits = true;
  double reflectionTint = 1.0, transmissionTint = 1.0;
  double cn = 1.0, ck = 0.0;           ///< Conductor: complex IOR
  double f0 = 1.0, f90 = 1.0, exponent = 5.0, tint = 1.0;  ///< F82
  double albedo = 1.0;                 ///< Lambert: rho; Fuzz: colour
  /// Lambert: `albedo` is the colour observed through a dielectric right above (an IR diffuse
  /// lobe, as OpenPBR's base_color), turned into rho by each walk; else rho itself.
  bool observed = false;
  double roughness = 0.5;              ///< Fuzz
  bool delta() const { return std::max(ax, ay) < 1e-4; }
};

struct Layer {
  Interface top;
  enum class Under { Nothing, Finite, HalfSpace, ClearBulk } under = Under::Nothing;
  double sigmaA = 0.0, sigmaS = 0.0, g = 0.0, thickness = 0.0;
  double coverage = 1.0;
  /// A medium given by its observed colour (subsurface): its extinction and the colour, turned
  /// into sigma_a and sigma_s by each walk for the interface over it as that walk sees it.
  bool observed = false;
  double extinction = 0.0, colour = 0.0;
};

struct Stack {
  std::vector<Layer> layers;
  double weight = 0.0;
};

/// The stacks of a material for one colour channel, and what is transmitted straight through
/// (opacity).
struct Stacks {
  std::vector<Stack> stacks;
  double transparency = 0.0;
};

namespace detail {

inline std::vector<float> constant(const ir::Material& m, ir::ExprId id) {
  std::optional<ir::Constant> c = ir::evaluateExpr(m.exprs, id);
  if (!c) throw std::runtime_error("SlabReference: a value that is not a constant");
  return c->v;
}
/// Component `channel` of a slot's constant (a float broadcasts), or `fallback` when absent.
inline double slot(const ir::Material& m, const ir::Slots& slots, ir::Slot s, int channel, double fallback) {
  const ir::Param* p = slots.find(s);
  if (!p || !p->present()) return fallback;
  const std::vector<float> v = constant(m, p->value);
  return v.size() == 1 ? v[0] : v.at(static_cast<size_t>(channel));
}
inline double param(const ir::Material& m, const ir::Param& p, int channel, double fallback) {
  if (!p.present()) return fallback;
  const std::vector<float> v = constant(m, p.value);
  return v.size() == 1 ? v[0] : v.at(static_cast<size_t>(channel));
}

class Builder {
 public:
  Builder(const ir::Material& m, int channel) : m_(m), c_(channel) {}

  Stacks run() {
    if (m_.root != ir::kNone) node(m_.root, 1.0, {});
    return out_;
  }

 private:
  Interface interface(const ir::Interface& f) {
    using ir::InterfaceKind;
    using ir::Slot;
    if (f.thinFilm.present()) throw std::runtime_error("SlabReference: thin film");
    if (const ir::Param* xi = f.slots.find(Slot::FresnelScale); xi && xi->present() && param(m_, *xi, 0, 1.0) != 1.0) {
      throw std::runtime_error("SlabReference: specular_weight");
    }
    if (const ir::Param* w = f.slots.find(Slot::Weight); w && w->present() && param(m_, *w, c_, 1.0) != 1.0) {
      throw std::runtime_error("SlabReference: a lobe weight");
    }
    Interface i;
    if (const ir::Param* a = f.slots.find(Slot::Alpha); a && a->present()) {
      const std::vector<float> v = constant(m_, a->value);
      i.ax = v.at(0);
      i.ay = v.size() > 1 ? v[1] : v[0];
    }
    // The shader keeps a rough lobe's alpha >= 1e-4 (mxc_rough_alpha).
    if (!i.delta()) i.ax = std::max(i.ax, 1e-4), i.ay = std::max(i.ay, 1e-4);
    switch (f.kind) {
      case InterfaceKind::Dielectric:
        i.kind = Interface::Kind::Dielectric;
        i.n = std::max(slot(m_, f.slots, Slot::Ior, 0, 1.5), 1e-3);
        i.relative = f.iorReference == ir::IorReference::Ambient;
        i.reflects = f.scatter != ir::ScatterMode::T;
        i.transmits = f.scatter != ir::ScatterMode::R;
        i.reflectionTint = slot(m_, f.slots, Slot::ReflectionTint, c_, 1.0);
        i.transmissionTint = slot(m_, f.slots, Slot::TransmissionTint, c_, 1.0);
        break;
      case InterfaceKind::Conductor:
        i.kind = Interface::Kind::Conductor;
        i.cn = slot(m_, f.slots, Slot::ComplexIor, c_, 1.0);
        i.ck = slot(m_, f.slots, Slot::Extinction, c_, 0.0);
        break;
      case InterfaceKind::Schlick:
        if (f.scatter != ir::ScatterMode::R) throw std::runtime_error("SlabReference: a transmitting Schlick lobe");
        i.kind = Interface::Kind::F82;
        i.f0 = slot(m_, f.slots, Slot::F0, c_, 1.0);
        i.f90 = slot(m_, f.slots, Slot::F90, c_, 1.0);
        i.exponent = slot(m_, f.slots, Slot::Exponent, 0, 5.0);
        i.tint = slot(m_, f.slots, Slot::F82, c_, 1.0);
        break;
      case InterfaceKind::Diffuse:
        if (slot(m_, f.slots, Slot::Roughness, 0, 0.0) != 0.0) throw std::runtime_error("SlabReference: rough diffuse");
        i.kind = Interface::Kind::Lambert;
        i.albedo = slot(m_, f.slots, Slot::Color, c_, 1.0);
        i.observed = true;
        break;
      case InterfaceKind::Sheen:
        if (f.sheenModel != ir::SheenModel::Zeltner) throw std::runtime_error("SlabReference: sheen other than fuzz");
        i.kind = Interface::Kind::Fuzz;
        i.albedo = slot(m_, f.slots, Slot::Color, c_, 1.0);
        i.roughness = slot(m_, f.slots, Slot::Roughness, 0, 0.5);
        break;
      default: throw std::runtime_error("SlabReference: an interface kind it does not model");
    }
    return i;
  }

  void slab(const ir::ScatterNode& n, double weight, std::vector<Layer> stack) {
    Layer layer;
    layer.coverage = std::clamp(param(m_, n.coverage, c_, 1.0), 0.0, 1.0);
    const ir::Interface* top = n.top != ir::kNone ? &m_.interfaces[n.top] : nullptr;
    if (top) layer.top = interface(*top);
    Layer inside;  // a thin wall's far interface
    bool thinWall = false;
    if (n.medium != ir::kNone) {
      const ir::Medium& v = m_.media[n.medium];
      layer.sigmaA = slot(m_, v.slots, ir::Slot::Absorption, c_, 0.0);
      layer.sigmaS = slot(m_, v.slots, ir::Slot::Scattering, c_, 0.0);
      layer.g = slot(m_, v.slots, ir::Slot::Anisotropy, 0, 0.0);
      switch (v.extent) {
        case ir::Medium::Extent::Bulk:
          layer.under = v.slots.find(ir::Slot::Scattering) ? Layer::Under::HalfSpace : Layer::Under::ClearBulk;
          break;
        case ir::Medium::Extent::Finite:
        case ir::Medium::Extent::ThinWall:
          layer.under = Layer::Under::Finite;
          layer.thickness = std::max(slot(m_, v.slots, ir::Slot::Thickness, 0, 1.0), 0.0);
          thinWall = v.extent == ir::Medium::Extent::ThinWall && top;
          break;
      }
      if (const ir::Param* observed = v.slots.find(ir::Slot::ObservedAlbedo); observed && observed->present()) {
        layer.observed = true;
        layer.colour = std::clamp(param(m_, *observed, c_, 0.8), 0.0, 1.0);
        layer.extinction = layer.sigmaA + layer.sigmaS;
      }
      if (thinWall) {
        // OpenPBR "Thin-walled mode": the sheet, then the same interface seen from inside, under
        // which is the outside again (its ratio the inverse, and no coat above it).
        inside.top = layer.top;
        inside.top.n = 1.0 / layer.top.n;
        inside.top.relative = true;
        inside.under = Layer::Under::ClearBulk;
        inside.coverage = layer.coverage;
      }
    }
    stack.push_back(layer);
    if (thinWall) stack.push_back(inside);
    if (n.base == ir::kNone) {
      emit(std::move(stack), weight);
      return;
    }
    node(n.base, weight, std::move(stack));
  }

  void node(ir::Index index, double weight, std::vector<Layer> stack) {
    const ir::ScatterNode& n = m_.nodes[index];
    switch (n.kind) {
      case ir::ScatterKind::Slab: slab(n, weight, std::move(stack)); break;
      case ir::ScatterKind::Mix: {
        const double w = param(m_, n.weight, c_, 0.0);
        node(n.a, weight * (1.0 - w), stack);
        node(n.b, weight * w, std::move(stack));
        break;
      }
      case ir::ScatterKind::Emissive: {
        // An emitting plane: nothing to the albedo; light goes on to what is under it.
        Layer plane;
        stack.push_back(plane);
        if (n.a == ir::kNone || m_.nodes[n.a].kind == ir::ScatterKind::Absorber) {
          emit(std::move(stack), weight);
        } else {
          node(n.a, weight, std::move(stack));
        }
        break;
      }
      case ir::ScatterKind::Ambient: out_.transparency += weight; break;
      // Black under the layers above: they still reflect (a stack whose light, once through
      // its last layer, is lost).
      case ir::ScatterKind::Absorber: emit(std::move(stack), weight); break;
      default: throw std::runtime_error("SlabReference: an Add or Tint node");
    }
  }

  void emit(std::vector<Layer> stack, double weight) {
    if (weight == 0.0 || stack.empty()) return;
    out_.stacks.push_back({std::move(stack), weight});
  }

  const ir::Material& m_;
  int c_;
  Stacks out_;
};

}  // namespace detail

/// The stacks as text, one layer a line, for a failing test's message.
inline std::string describe(const Stacks& s) {
  static const char* kinds[] = {"none", "dielectric", "conductor", "f82", "lambert", "fuzz"};
  static const char* unders[] = {"nothing", "finite", "half-space", "clear bulk"};
  std::string out;
  for (const Stack& stack : s.stacks) {
    out += "stack, weight " + std::to_string(stack.weight) + "\n";
    for (const Layer& l : stack.layers) {
      out += std::string("  ") + kinds[int(l.top.kind)] + " n " + std::to_string(l.top.n) + " alpha " +
             std::to_string(l.top.ax) + " albedo " + std::to_string(l.top.albedo) + "; under: " + unders[int(l.under)] +
             " sigma_a " + std::to_string(l.sigmaA) + " sigma_s " + std::to_string(l.sigmaS) + " thickness " +
             std::to_string(l.thickness) + "; coverage " + std::to_string(l.coverage) + "\n";
    }
  }
  return out + "transparency " + std::to_string(s.transparency) + "\n";
}

/// The material's stacks for colour channel `channel` (0, 1, 2), at a flat surface (normal +z,
/// tangent +x).
inline Stacks stacksOf(const ir::Material& material, int channel) { return detail::Builder(material, channel).run(); }

// ---- The walk ----

/// The Zeltner fuzz's reflectance R(mu, r) and LTC (a, b): the published fits (the numbers
/// MaterialX 1.39 publishes for its sheen_bsdf "zeltner" mode), r clamped to [0.01, 1].
inline double fuzzReflectance(double mu, double r) {
  r = std::clamp(r, 0.01, 1.0);
  const double s = r * (0.0206607 + 1.58491 * r) / (0.0379424 + r * (1.32227 + r));
  const double m = r * (-0.193854 + r * (-1.14885 + r * (1.7932 - 0.95943 * r * r))) / (0.046391 + r);
  const double o = r * (0.000654023 + (-0.0207818 + 0.119681 * r) * r) / (1.26264 + r * (-1.92021 + r));
  const double gauss = std::exp(-0.5 * (mu - m) * (mu - m) / (s * s)) / (s * std::sqrt(2.0 * kPi));
  return std::clamp(gauss + o, 0.0, 1.0);
}
/// A direction from the fuzz's lobe for the view v (v.z > 0): a cosine-distributed direction
/// transformed by the LTC's matrix M = (M^-1)^-1, M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]] in the
/// frame whose x axis is v's tangent part (Heitz et al. 2016).
inline Vec fuzzSample(Vec v, double r, Random& u) {
  r = std::clamp(r, 0.01, 1.0);
  const double mu = std::clamp(v.z, 0.0, 1.0);
  const double a = (2.58126 * mu + 0.813703 * r) * r / (1.0 + 0.310327 * mu * mu + 2.60994 * mu * r);
  const double b = std::sqrt(1.0 - mu) * (r - 1.0) * r * r * r /
                   (0.0000254053 + 1.71228 * mu - 1.71506 * mu * r + 1.34174 * r * r);
  const double r1 = std::sqrt(u()), phi = 2.0 * kPi * u();
  const Vec d(r1 * std::cos(phi), r1 * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - r1 * r1)));
  const Vec t = glm::normalize(Vec((d.x - b * d.z) / a, d.y / a, d.z));
  const double len = std::sqrt(v.x * v.x + v.y * v.y);
  const double cx = len > 1e-12 ? v.x / len : 1.0, cy = len > 1e-12 ? v.y / len : 0.0;
  return Vec(t.x * cx - t.y * cy, t.x * cy + t.y * cx, t.z);
}

/// Henyey-Greenstein: a direction around the direction of travel w, by the inverse CDF of the
/// cosine (Pharr, Jakob and Humphreys 2023, eq. 11.13 turned around).
inline Vec henyeyGreenstein(Vec w, double g, Random& u) {
  g = std::clamp(g, -0.99, 0.99);
  double cosTheta;
  if (std::abs(g) < 1e-3) {
    cosTheta = 1.0 - 2.0 * u();
  } else {
    const double s = (1.0 - g * g) / (1.0 + g - 2.0 * g * u());
    cosTheta = std::clamp((1.0 + g * g - s * s) / (2.0 * g), -1.0, 1.0);
  }
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta)), phi = 2.0 * kPi * u();
  const Vec a = std::abs(w.x) < 0.9 ? Vec(1.0, 0.0, 0.0) : Vec(0.0, 1.0, 0.0);
  const Vec t = glm::normalize(glm::cross(a, w)), b = glm::cross(w, t);
  return sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * w;
}

/// One crossing of an interface by a walk arriving along w (travel direction, world = the
/// interface's frame, normal +z). `eta`: a dielectric's IOR below over above.
inline Outcome scatter(const Interface& f, double eta, Vec w, Random& u) {
  const bool fromAbove = w.z < 0.0;
  using Kind = Interface::Kind;
  if (f.kind == Kind::None) return w;
  if (f.kind == Kind::Lambert) {
    // Cosine-distributed on the side the light came from (a base reflects from above; seen from
    // below it is the same surface).
    if (!survive(f.albedo, u)) return std::nullopt;
    const double r = std::sqrt(u()), phi = 2.0 * kPi * u();
    const Vec d(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - r * r)));
    return fromAbove ? d : Vec(d.x, d.y, -d.z);
  }
  if (f.kind == Kind::Fuzz) {
    // Seen from the side the light arrives on: reflect E (grey) into the lobe, tinted by the
    // colour; transmit 1 - E straight on.
    Vec v = -w;
    if (!fromAbove) v.z = -v.z;
    const double e = fuzzReflectance(std::clamp(v.z, 0.0, 1.0), f.roughness);
    if (!(u() < e)) return w;
    if (!survive(f.albedo, u)) return std::nullopt;
    Vec out = fuzzSample(v, f.roughness, u);
    if (!fromAbove) out.z = -out.z;
    return out;
  }
  // A microfacet interface, in the frame whose upper side is the light's: z mirrored from below.
  const bool dielectric = f.kind == Kind::Dielectric;
  double e = fromAbove ? eta : 1.0 / eta;  // far side over near side
  auto fresnel = [&](double cosm, double ratio) {
    switch (f.kind) {
      case Kind::Dielectric: return closed::fresnel(std::clamp(cosm, 0.0, 1.0), ratio);
      case Kind::Conductor: return conductorFresnel(cosm, f.cn, f.ck);
      default: return f82Fresnel(cosm, f.f0, f.f90, f.exponent, f.tint);
    }
  };
  Vec d = w;
  if (!fromAbove) d.z = -d.z;
  bool flipped = false;  // the walk is in the far medium's frame
  if (f.delta()) {
    const double cosi = -d.z;
    const double fr = fresnel(cosi, e);
    if (!dielectric) {
      if (!survive(fr, u)) return std::nullopt;
      d.z = -d.z;
    } else if (u() < fr) {
      d.z = -d.z;
    } else {
      const double r = 1.0 / e, cost = std::sqrt(std::max(0.0, 1.0 - r * r * (1.0 - cosi * cosi)));
      d = Vec(r * d.x, r * d.y, -cost);  // on, into the far medium (this frame is not mirrored)
    }
  } else {
    auto c1 = [](double h) { return std::clamp(0.5 * (h + 1.0), 0.0, 1.0); };
    double h = 1.0;
    for (int bounce = 0;; ++bounce) {
      if (bounce > 100000) return std::nullopt;
      const double l = lambda(d, f.ax, f.ay);
      double c;
      if (d.z > 0.0) {
        c = l > 0.0 ? c1(h) * std::pow(u(), -1.0 / l) : 2.0;
        if (c >= 1.0) break;  // leaves the microsurface
      } else {
        c = c1(h) * std::pow(u(), 1.0 / (1.0 + l));
      }
      h = 2.0 * c - 1.0;
      const Vec i = -d;
      const Vec m = visibleNormal(i, f.ax, f.ay, u(), u());
      const double cosm = glm::dot(i, m);
      const double fr = fresnel(cosm, e);
      if (!dielectric) {
        if (!survive(fr, u)) return std::nullopt;
        d = d - 2.0 * glm::dot(d, m) * m;
        continue;
      }
      if (u() < fr) {
        d = d - 2.0 * glm::dot(d, m) * m;
        continue;
      }
      const double r = 1.0 / e, cost = std::sqrt(std::max(0.0, 1.0 - r * r * (1.0 - cosm * cosm)));
      d = glm::normalize(r * d + (r * std::max(cosm, 0.0) - cost) * m);
      d.z = -d.z;
      h = -h;
      e = 1.0 / e;
      flipped = !flipped;
    }
  }
  // Back to the interface's frame: the walk's upper side is the side the light came from,
  // mirrored again for each crossing.
  Vec out = flipped ? Vec(d.x, d.y, -d.z) : d;
  if (!fromAbove) out.z = -out.z;
  const bool reflected = (out.z > 0.0) == fromAbove;
  if (reflected && dielectric && !f.reflects) return std::nullopt;
  if (!reflected && (!dielectric || !f.transmits)) return std::nullopt;
  if (dielectric && fromAbove && !survive(reflected ? f.reflectionTint : f.transmissionTint, u)) return std::nullopt;
  return out;
}

/// The albedo of one stack seen from wo (wo.z > 0), reflected and transmitted, by `walks`
/// analog walks, with binomial standard errors.
struct Albedo {
  double reflected = 0.0, transmitted = 0.0;
  double reflectedError = 0.0, transmittedError = 0.0;
  double cut = 0.0;  ///< walks ended by the event cap
};

inline Albedo albedo(const Stack& stack, Vec wo, int walks, uint64_t seed) {
  Random u(seed);
  const int events = 1000000;
  double reflected = 0.0, transmitted = 0.0, cut = 0.0;
  for (int walk = 0; walk < walks; ++walk) {
    // The layers this walk sees, and each dielectric's IOR ratio below them: over the nearest
    // dielectric above (OpenPBR "Coat": the coat's IOR is the medium over the base).
    std::vector<Layer> seen;
    for (const Layer& l : stack.layers) {
      if (l.coverage >= 1.0 || u() < l.coverage) seen.push_back(l);
    }
    const int n = static_cast<int>(seen.size());
    std::vector<double> eta(n, 1.0);
    double above = 1.0;  // the absolute IOR of the medium above the current layer
    for (int k = 0; k < n; ++k) {
      const Interface& f = seen[k].top;
      if (f.kind != Interface::Kind::Dielectric) continue;
      eta[k] = f.relative ? f.n : f.n / above;
      above = f.relative ? above * f.n : f.n;
    }
    if (n == 0) continue;
    // The colours defined by what is observed through the dielectric over them, as this walk
    // sees it (its ratio under whatever coat is there: an index-matched coat takes the
    // dielectric's place, and its internal reflections darken what is under it, OpenPBR
    // "Darkening"): a Lambertian right under a dielectric (eq. glossy_diffuse_albedo_constraint)
    // and a medium under its own interface or, without one, under the dielectric right above
    // (eq. subsurface_albedo_constraint). WalkTables.h.
    auto roughness = [](const Interface& f) { return std::sqrt(std::sqrt(f.ax * f.ay)); };
    for (int k = 0; k < n; ++k) {
      Layer& l = seen[k];
      const bool under = k > 0 && seen[k - 1].top.kind == Interface::Kind::Dielectric;
      if (l.top.kind == Interface::Kind::Lambert && l.top.observed && under) {
        l.top.albedo = glsl::walkGlossAlbedo(l.top.albedo, eta[k - 1], roughness(seen[k - 1].top));
      }
      if (l.observed) {
        const int over = l.top.kind != Interface::Kind::None ? k : (under ? k - 1 : -1);
        const bool dielectric = over >= 0 && seen[over].top.kind == Interface::Kind::Dielectric;
        const double omega = glsl::walkSubsurfaceAlbedo(l.colour, dielectric ? eta[over] : 1.0, l.g,
                                                        dielectric ? roughness(seen[over].top) : 0.0);
        l.sigmaS = l.extinction * omega;
        l.sigmaA = l.extinction - l.sigmaS;
      }
    }
    Vec w = -wo;
    int k = 0;
    bool inMedium = false;
    double z = 0.0;  // depth below the top of layer k's medium
    int outcome = 0;  // 1 reflected, 2 transmitted, 0 lost
    for (int event = 0;; ++event) {
      if (event > events) {
        cut += 1.0;
        break;
      }
      const Layer& layer = seen[k];
      if (!inMedium) {
        // At interface k, arriving from above (w.z < 0) or from below.
        Outcome o = scatter(layer.top, eta[k], w, u);
        if (!o) break;
        w = *o;
        if (w.z > 0.0) {
          if (k == 0) {
            outcome = 1;
            break;
          }
          k -= 1;  // up into the medium above, at its bottom
          inMedium = true;
          z = seen[k].under == Layer::Under::Finite ? seen[k].thickness : 0.0;
          continue;
        }
        if (layer.under == Layer::Under::ClearBulk) {
          // Into a clear bulk: transmitted, through a unit path of its absorption.
          if (survive(std::exp(-layer.sigmaA), u)) outcome = 2;
          break;
        }
        inMedium = true;
        z = 0.0;
        continue;
      }
      // In layer k's medium, at depth z, going along w.
      const double mu = std::abs(w.z);
      const bool down = w.z < 0.0;
      const double extinction = layer.sigmaA + layer.sigmaS;
      double boundary;
      if (layer.under == Layer::Under::HalfSpace) {
        boundary = down ? INFINITY : z / std::max(mu, 1e-300);
      } else if (layer.under == Layer::Under::Finite) {
        boundary = (down ? layer.thickness - z : z) / std::max(mu, 1e-300);
      } else {
        boundary = 0.0;  // no medium
      }
      const double t = extinction > 0.0 ? -std::log(u()) / extinction : INFINITY;
      if (t < boundary) {
        z += down ? t * mu : -t * mu;
        if (!survive(layer.sigmaS / extinction, u)) break;
        w = henyeyGreenstein(w, layer.g, u);
        continue;
      }
      if (std::isinf(boundary)) break;  // down a half-space for ever
      inMedium = false;
      if (!down) continue;  // up to interface k from below
      if (k + 1 >= n) break;  // nothing under the last layer
      k += 1;
    }
    if (outcome == 1) reflected += 1.0;
    if (outcome == 2) transmitted += 1.0;
  }
  Albedo a;
  a.reflected = reflected / walks;
  a.transmitted = transmitted / walks;
  a.reflectedError = std::sqrt(a.reflected * (1.0 - a.reflected) / std::max(walks - 1, 1));
  a.transmittedError = std::sqrt(a.transmitted * (1.0 - a.transmitted) / std::max(walks - 1, 1));
  a.cut = cut / walks;
  return a;
}

/// The material's albedo for one channel at wo: every stack by its weight (each with `walks`
/// walks), and the transparency as transmitted.
inline Albedo albedo(const Stacks& s, Vec wo, int walks, uint64_t seed) {
  Albedo total;
  double reflectedVariance = 0.0, transmittedVariance = 0.0;
  for (size_t i = 0; i < s.stacks.size(); ++i) {
    const Albedo a = albedo(s.stacks[i], wo, walks, seed * 7919u + i);
    const double w = s.stacks[i].weight;
    total.reflected += w * a.reflected;
    total.transmitted += w * a.transmitted;
    reflectedVariance += w * w * a.reflectedError * a.reflectedError;
    transmittedVariance += w * w * a.transmittedError * a.transmittedError;
    total.cut += w * a.cut;
  }
  total.transmitted += s.transparency;
  total.reflectedError = std::sqrt(reflectedVariance);
  total.transmittedError = std::sqrt(transmittedVariance);
  return total;
}

}  // namespace mxc::test::slab
