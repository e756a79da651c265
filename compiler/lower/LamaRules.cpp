// Pixar's Lama nodes to the slab IR. The parameters' meanings are those of the Lama
// definitions MaterialX 1.39 ships (libraries/bxdf/lama, each input's `doc`), which follow
// RenderMan's Lama documentation; where MaterialX's own graph of a node departs from its
// documentation, the documentation is followed and the difference is stated here.
//
//   LamaConductor          GGX conductor, complex IOR from (reflectivity, edgeColor) by
//                          Gulbrandsen 2014 (Artistic) or (IOR, extinction) (Scientific); tint
//   LamaDielectric         one GGX dielectric interface reflecting and transmitting, its IOR from
//                          reflectivity F0 (Artistic: n = (1 + sqrt F0) / (1 - sqrt F0)) or IOR,
//                          over its interior: a bulk medium reaching absorptionColor at
//                          absorptionRadius (mu_t = -ln(C) / R), scatterColor the single-
//                          scattering albedo (mu_s = S mu_t), Henyey-Greenstein scatterAnisotropy
//   LamaGeneralizedSchlick the same over a Schlick Fresnel from reflectivity (or ((n-1)/(n+1))^2)
//                          to reflectivity90, exponent 1 / reflectivityProfile
//   LamaIridescence        a thin film (thickness lerp(min, max, relative), filmIOR) on an
//                          index-matched interface: only the film reflects
//   LamaDiffuse            Oren-Nayar of sigma = roughness^2 / 2, energy-compensated (EON,
//                          Portsmouth et al. 2025) in proportion energyCompensation
//   LamaTranslucent        Lambertian transmission of `color`
//   LamaSheen              Conty-Kulla sheen of roughness (0.1 + 0.9 r)^2
//   LamaSSS                a bulk subsurface medium of mean free path sssRadius sssScale
//                          sssUnitLength (OpenPBR's van de Hulst inversion of `color`); radius 0 is
//                          a Lambertian reflection (its documentation)
//   LamaEmission           uniform emission of `color`
//   LamaAdd / LamaMix      weight1 m1 + weight2 m2 / mix(m1, m2, mix)
//   LamaLayer              materialTop over materialBase over a coverage topMix; the top's
//                          interior becomes a layer of thickness topThickness (its documentation:
//                          "only relevant for interior effects ... such as absorption"), or of
//                          its absorptionRadius when topThickness is 0, so that absorptionColor
//                          "acts as coating color"
//   LamaSurface            the material: materialFront with presence as its opacity
//
// Anisotropy (LamaConductor, LamaDielectric, LamaIridescence): the documentation moves the
// co-tangent roughness "from the original value to 1 (or to 0 with a negative value)":
// r_b = r + a (1 - r) for a >= 0, r + a r for a < 0. (MaterialX's graph compares 1 - r with r
// instead of the sign of a, which squares a.) LamaGeneralizedSchlick's anisotropy is the
// co-tangent roughness itself, negative meaning none. alpha = r^2 on each axis (MaterialX's
// graphs), and the direction turns about the normal by -360 rotation degrees (their sign).
// Tints above 1 are clamped: each is a multiplier that "breaks physicality" when not white,
// and above 1 it creates energy (the hard cases forbid energy gain).

#include "compiler/lower/LamaRules.h"

#include <cmath>
#include <optional>

#include "compiler/ir/Evaluate.h"
#include "compiler/lower/ClosureAlgebra.h"
#include "compiler/lower/Layering.h"
#include "compiler/lower/Media.h"
#include "compiler/lower/Microfacet.h"
#include "compiler/lower/ShadingModel.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Index;
using ir::Param;
using ir::Slot;
using ir::Type;

namespace {

Closure scatter(Index index) { return {Closure::Kind::Scatter, index, {}}; }

struct LamaNode : ShadingModelInputs {
  /// `artistic` or `science` as fresnelMode picks (Artistic 0, Scientific 1): a constant mode
  /// decides at compile time, a variable one (a --param) selects at run time.
  ExprId byMode(ExprId artistic, ExprId science) {
    const ExprId mode = p("fresnelMode").value;
    if (mode == ir::kNoExpr) return artistic;
    if (c.material.exprs.isConstant(mode)) return c.material.exprs.constantComponents(mode)[0] > 0.5f ? science : artistic;
    return b.select(b.greater(b.convert(mode, Type::Float), b.f(0.5f)), science, artistic);
  }

  /// GGX alphas (r^2, r_b^2) with the co-tangent roughness r_b the documentation gives.
  Param alpha(bool anisotropyIsRoughness) {
    const ExprId r = nonNegative("roughness").value;
    const Param anisotropy = p("anisotropy");
    ExprId rb = r;
    if (anisotropyIsRoughness) {
      // LamaGeneralizedSchlick: the co-tangent roughness itself; negative means none.
      rb = b.select(b.greater(anisotropy.value, b.f(0.0f)), anisotropy.value, r);
    } else if (!isConstant(anisotropy, 0.0f)) {
      // a in [-1, 1] (its documented range: beyond it r_b would leave [0, 1]).
      const ExprId a = b.clamp(anisotropy.value, b.f(-1.0f), b.f(1.0f));
      const ExprId toward = b.select(b.greater(a, b.f(0.0f)), b.oneMinus(r), r);
      rb = b.nonNegative(b.add(r, b.mul(a, toward)));
    }
    return {b.construct(Type::Vec2, {b.mul(r, r), b.mul(rb, rb)}), at("roughness")};
  }

  /// The anisotropy direction turned by -360 `rotation` degrees about the normal; none (the
  /// surface's tangent) for an isotropic lobe.
  void setTangent(ir::Interface& i, std::string_view direction, std::string_view rotation, bool anisotropic) {
    if (!anisotropic) return;
    ExprId t = p(direction).value;
    const Param angle = p(rotation);
    if (!isConstant(angle, 0.0f)) {
      // normalize: the rotated direction has the length of the direction (a unit tangent).
      t = b.normalize(c.material.exprs.op(ir::Op::Rotate3D, Type::Vec3,
                                          {t, b.mul(angle.value, b.f(-360.0f)), p("normal").value}));
    }
    i.slots.set(Slot::Tangent, {t, at(direction)});
  }

  /// True when `x` folds to `value` in every component, within 1e-5: white given in another
  /// colour space (the Lama definitions' acescg) arrives as 0.99999994 after conversion, and a
  /// tint of it is none.
  bool folds(ExprId x, float value) {
    const std::optional<ir::Constant> folded = x == ir::kNoExpr ? std::nullopt : ir::evaluateExpr(c.material.exprs, x);
    if (!folded || folded->v.empty()) return false;
    for (float v : folded->v) {
      if (std::abs(v - value) > 1e-5f) return false;
    }
    return true;
  }
  bool white(ExprId x) { return folds(x, 1.0f); }

  ir::Interface interface(ir::InterfaceKind kind) {
    ir::Interface i;
    i.kind = kind;
    i.origin = c.nodeOrigin(n);
    i.iorReference = ir::IorReference::Ambient;
    if (Param normal = p("normal"); normal.present()) i.slots.set(Slot::Normal, normal);
    return i;
  }

  /// The interior of LamaDielectric and LamaGeneralizedSchlick: mu_t = -ln(C) / R (the colour
  /// reached at the radius), mu_s = S mu_t with the albedo S in [0, 1] (a ratio), as OpenPBR's
  /// translucent base with depth R and scatter S (-ln C). A radius of 0 means no interior, as
  /// transmissionMedium treats a depth of 0. The medium keeps R as its thickness, which a
  /// LamaLayer uses when the interior becomes a coating.
  Index interior(const Param& ior) {
    Param color = p("absorptionColor");
    if (white(color.value)) color.value = b.vec(Type::Vec3, 1.0f);  // no absorption, exactly
    const Param radius = nonNegative("absorptionRadius");
    // -ln(C) for C clamped to [1e-6, 1]: finite and >= 0.
    const ExprId depth = b.neg(b.ln(b.clamp(color.value, b.f(1e-6f), b.f(1.0f))));
    const Param scatterCoefficient{b.mul(clamped01("scatterColor").value, depth), at("scatterColor")};
    const Index m = transmissionMedium(c, color, radius, scatterCoefficient, p("scatterAnisotropy"), ior, {},
                                       at("absorptionColor"));
    c.material.media[m].slots.set(Slot::Thickness, radius);
    return m;
  }
};

}  // namespace

Closure lamaConductor(Context& c, const NodeRef& n, std::string_view) {
  LamaNode lama{{c, n, c.b}};
  ir::ExprBuilder& b = c.b;
  ir::Interface i = lama.interface(ir::InterfaceKind::Conductor);
  i.scatter = ir::ScatterMode::R;
  auto [eta, kappa] = gulbrandsenIor(b, lama.p("reflectivity").value, lama.p("edgeColor").value);
  i.slots.set(Slot::ComplexIor, {lama.byMode(eta, b.convert(lama.nonNegative("IOR").value, Type::Vec3)),
                                 lama.at("reflectivity")});
  i.slots.set(Slot::Extinction, {lama.byMode(kappa, b.convert(lama.nonNegative("extinction").value, Type::Vec3)),
                                 lama.at("edgeColor")});
  i.slots.set(Slot::Alpha, lama.alpha(false));
  lama.setTangent(i, "anisotropyDirection", "anisotropyRotation", !lama.isConstant(lama.p("anisotropy"), 0.0f));
  Closure out = scatter(interfaceSlab(c, std::move(i), {}));
  if (lama.white(lama.p("tint").value)) return out;
  const Param tint = lama.clamped01("tint");
  return scaleClosure(c, out, tint, c.nodeOrigin(n));
}

Closure lamaDielectric(Context& c, const NodeRef& n, std::string_view) {
  LamaNode lama{{c, n, c.b}};
  ir::ExprBuilder& b = c.b;
  ir::Interface i = lama.interface(ir::InterfaceKind::Dielectric);
  i.scatter = ir::ScatterMode::RT;
  // F0 = ((n - 1) / (n + 1))^2 inverted: n = (1 + sqrt F0) / (1 - sqrt F0); F0 in [0, 0.99]
  // keeps 1 - sqrt F0 >= 0.005 (n <= 399).
  const ExprId root = b.sqrt(b.clamp(lama.p("reflectivity").value, b.f(0.0f), b.f(0.99f)));
  const Param ior{lama.byMode(b.div(b.add(b.f(1.0f), root), b.sub(b.f(1.0f), root)), lama.p("IOR").value),
                  lama.at("reflectivity")};
  i.slots.set(Slot::Ior, ior);
  if (!lama.white(lama.p("reflectionTint").value)) i.slots.set(Slot::ReflectionTint, lama.clamped01("reflectionTint"));
  if (!lama.white(lama.p("transmissionTint").value)) {
    i.slots.set(Slot::TransmissionTint, lama.clamped01("transmissionTint"));
  }
  i.slots.set(Slot::Alpha, lama.alpha(false));
  lama.setTangent(i, "direction", "rotation", !lama.isConstant(lama.p("anisotropy"), 0.0f));
  const Index top = c.material.addInterface(std::move(i));
  return scatter(c.material.slab(top, lama.interior(ior), ir::kNone, {}, c.nodeOrigin(n)));
}

Closure lamaGeneralizedSchlick(Context& c, const NodeRef& n, std::string_view) {
  LamaNode lama{{c, n, c.b}};
  ir::ExprBuilder& b = c.b;
  ir::Interface i = lama.interface(ir::InterfaceKind::Schlick);
  i.scatter = ir::ScatterMode::RT;
  // Scientific: F0 = ((n - 1) / (n + 1))^2 per channel; n >= 0 keeps n + 1 >= 1.
  const ExprId eta = b.convert(lama.nonNegative("IOR").value, Type::Vec3);
  const ExprId ratio = b.div(b.sub(eta, b.f(1.0f)), b.add(eta, b.f(1.0f)));
  i.slots.set(Slot::F0, {lama.byMode(lama.clamped01("reflectivity").value, b.mul(ratio, ratio)), lama.at("reflectivity")});
  i.slots.set(Slot::F90, lama.clamped01("reflectivity90"));
  // exponent = 1 / profile; the profile floored at 1e-3 (an exponent of at most 1000: F0 up to
  // grazing).
  i.slots.set(Slot::Exponent, {b.div(b.f(1.0f), b.max(lama.p("reflectivityProfile").value, b.f(1e-3f))),
                               lama.at("reflectivityProfile")});
  i.slots.set(Slot::Alpha, lama.alpha(true));
  lama.setTangent(i, "anisotropyDirection", "anisotropyRotation", !lama.isConstant(lama.p("anisotropy"), -1.0f));
  const Index top = c.material.addInterface(std::move(i));
  // The interior's IOR: the Schlick interface bends light as an IOR of its F0 would (MaterialX
  // refracts a generalized Schlick lobe that way); its mean is what the medium carries.
  const ExprId meanEta = b.div(b.add(b.add(b.extract(eta, 0), b.extract(eta, 1)), b.extract(eta, 2)), b.f(3.0f));
  Closure out = scatter(c.material.slab(top, lama.interior({meanEta, lama.at("IOR")}), ir::kNone, {}, c.nodeOrigin(n)));
  // The Schlick lobe has one colour for reflection and transmission: the reflection tint
  // scales the whole; a different transmission tint is reported, not dropped silently.
  const Param tint = lama.clamped01("reflectionTint");
  const Param transmissionTint = lama.clamped01("transmissionTint");
  const bool sameTints = transmissionTint.value == tint.value ||
                         (lama.white(lama.p("reflectionTint").value) && lama.white(lama.p("transmissionTint").value));
  if (!sameTints) {
    c.note(transmissionTint.origin, "LamaGeneralizedSchlick: a transmission tint other than the reflection tint is "
                                    "not applied on its own; the reflection tint scales both");
  }
  if (lama.white(lama.p("reflectionTint").value)) return out;
  return scaleClosure(c, out, tint, c.nodeOrigin(n));
}

Closure lamaIridescence(Context& c, const NodeRef& n, std::string_view) {
  LamaNode lama{{c, n, c.b}};
  ir::ExprBuilder& b = c.b;
  ir::Interface i = lama.interface(ir::InterfaceKind::Dielectric);
  i.scatter = ir::ScatterMode::RT;
  i.slots.set(Slot::Ior, {b.f(1.0f), c.nodeOrigin(n)});
  i.slots.set(Slot::Alpha, lama.alpha(false));
  lama.setTangent(i, "anisotropyDirection", "anisotropyRotation", !lama.isConstant(lama.p("anisotropy"), 0.0f));
  i.thinFilm.thickness = {b.nonNegative(b.lerp(lama.p("minFilmThickness").value, lama.p("maxFilmThickness").value,
                                               lama.p("relativeFilmThickness").value)),
                          lama.at("relativeFilmThickness")};
  i.thinFilm.ior = lama.p("filmIOR");
  i.thinFilm.origin = c.nodeOrigin(n);
  // What the film does not reflect passes into a clear, index-matched body.
  const Param none{b.f(0.0f), c.nodeOrigin(n)};
  const Index body = transmissionMedium(c, {b.vec(Type::Vec3, 1.0f), c.nodeOrigin(n)}, none,
                                        {b.vec(Type::Vec3, 0.0f), c.nodeOrigin(n)}, none, {b.f(1.0f), c.nodeOrigin(n)},
                                        {}, c.nodeOrigin(n));
  return scatter(c.material.slab(c.material.addInterface(std::move(i)), body, ir::kNone, {}, c.nodeOrigin(n)));
}

Closure lamaDiffuse(Context& c, const NodeRef& n, std::string_view) {
  LamaNode lama{{c, n, c.b}};
  ir::ExprBuilder& b = c.b;
  const ExprId r = lama.nonNegative("roughness").value;
  auto diffuse = [&](ir::DiffuseModel model) {
    ir::Interface i = lama.interface(ir::InterfaceKind::Diffuse);
    i.diffuseModel = model;
    i.slots.set(Slot::Color, lama.clamped01("color"));  // an albedo: above 1 it creates energy
    i.slots.set(Slot::Roughness, {b.mul(b.mul(r, r), b.f(0.5f)), lama.at("roughness")});
    return scatter(interfaceSlab(c, std::move(i), {}));
  };
  // energyCompensation in [0, 1] mixes the plain model (0) into the compensated one (1).
  const Param amount = lama.clamped01("energyCompensation");
  if (lama.isConstant(lama.p("energyCompensation"), 1.0f)) return diffuse(ir::DiffuseModel::EON);
  if (lama.isConstant(lama.p("energyCompensation"), 0.0f)) return diffuse(ir::DiffuseModel::OrenNayar);
  return mixClosures(c, diffuse(ir::DiffuseModel::EON), diffuse(ir::DiffuseModel::OrenNayar), amount, c.nodeOrigin(n));
}

Closure lamaTranslucent(Context& c, const NodeRef& n, std::string_view) {
  // Lambertian transmission; Lama's roughness and energyCompensation shape an Oren-Nayar
  // transmission mxc does not have (MaterialX's graph ignores them too): noted when set.
  LamaNode lama{{c, n, c.b}};
  ir::Interface i = lama.interface(ir::InterfaceKind::DiffuseTransmission);
  i.slots.set(Slot::Color, lama.clamped01("color"));  // an albedo: above 1 it creates energy
  if (!lama.isConstant(lama.p("roughness"), 0.0f)) {
    c.note(lama.at("roughness"), "LamaTranslucent: the roughness of the transmission is not modelled (Lambertian)");
  }
  return scatter(interfaceSlab(c, std::move(i), {}));
}

Closure lamaSheen(Context& c, const NodeRef& n, std::string_view) {
  LamaNode lama{{c, n, c.b}};
  ir::ExprBuilder& b = c.b;
  ir::Interface i = lama.interface(ir::InterfaceKind::Sheen);
  i.sheenModel = ir::SheenModel::ContyKulla;
  i.slots.set(Slot::Color, lama.clamped01("color"));  // an albedo: above 1 it creates energy
  // roughness remapped to [0.1, 1] then squared, as MaterialX's graph of LamaSheen does.
  const ExprId remapped = b.add(b.mul(lama.clamped01("roughness").value, b.f(0.9f)), b.f(0.1f));
  i.slots.set(Slot::Roughness, {b.mul(remapped, remapped), lama.at("roughness")});
  return scatter(interfaceSlab(c, std::move(i), {}));
}

Closure lamaSss(Context& c, const NodeRef& n, std::string_view) {
  LamaNode lama{{c, n, c.b}};
  ir::ExprBuilder& b = c.b;
  const ExprId radius = b.mul(b.mul(lama.nonNegative("sssRadius").value, lama.nonNegative("sssScale").value),
                              lama.nonNegative("sssUnitLength").value);
  if (lama.folds(radius, 0.0f)) {
    // "If zero ... the computation simplifies to a Lambertian reflection lobe".
    ir::Interface i = lama.interface(ir::InterfaceKind::Diffuse);
    i.diffuseModel = ir::DiffuseModel::OrenNayar;
    i.slots.set(Slot::Color, lama.clamped01("color"));
    return scatter(interfaceSlab(c, std::move(i), {}));
  }
  if (!lama.isConstant(lama.p("sssIOR"), 1.0f)) {
    c.note(lama.at("sssIOR"), "LamaSSS: sssIOR (total internal reflection of the subsurface paths) is not modelled; "
                              "layer a LamaDielectric over it for a refractive boundary");
  }
  const Index medium = subsurfaceMedium(c, lama.p("color"), {radius, lama.at("sssRadius")}, lama.p("sssAnisotropy"),
                                        c.nodeOrigin(n));
  return scatter(c.material.slab(ir::kNone, medium, ir::kNone, {}, c.nodeOrigin(n)));
}

Closure lamaEmission(Context& c, const NodeRef& n, std::string_view) {
  ir::Emission e;
  e.kind = ir::Emission::Kind::Uniform;
  e.origin = c.nodeOrigin(n);
  ir::Param color = c.param(n, "color");
  color.value = c.b.nonNegative(color.value);  // radiance is never negative
  e.slots.set(Slot::Color, color);
  return {Closure::Kind::Emission, ir::kNone, {c.material.addEmission(std::move(e))}};
}

// Inputs are read in order into locals (a call's arguments are evaluated in no fixed order).
Closure lamaAdd(Context& c, const NodeRef& n, std::string_view) {
  const Closure m1 = c.closureInput(n, "material1");
  const Closure a = scaleClosure(c, m1, c.param(n, "weight1"), c.nodeOrigin(n));
  const Closure m2 = c.closureInput(n, "material2");
  const Closure b = scaleClosure(c, m2, c.param(n, "weight2"), c.nodeOrigin(n));
  return addClosures(c, a, b, c.nodeOrigin(n));
}

Closure lamaMix(Context& c, const NodeRef& n, std::string_view) {
  // mix 0 is material1, 1 material2.
  const Closure m1 = c.closureInput(n, "material1");
  const Closure m2 = c.closureInput(n, "material2");
  ir::Param w = c.param(n, "mix");
  w.value = c.b.clamp01(w.value);  // a mixing weight: outside [0, 1] one side is negative
  return mixClosures(c, m2, m1, w, c.nodeOrigin(n));
}

namespace {

/// A copy of the tree under `node` whose bottom bulk media (not subsurface ones) are layers of
/// `thickness`, or of the thickness they carry (LamaNode::interior's radius) where
/// `thickness` is 0.
Index interiorAsLayer(Context& c, Index node, ExprId thickness, const ir::Origin& origin) {
  ir::ScatterNode copy = c.material.nodes[node];
  switch (copy.kind) {
    case ir::ScatterKind::Slab: {
      if (copy.base != ir::kNone) {
        copy.base = interiorAsLayer(c, copy.base, thickness, origin);
        break;
      }
      if (copy.medium == ir::kNone) return node;
      ir::Medium m = c.material.media[copy.medium];
      if (m.extent != ir::Medium::Extent::Bulk || m.slots.find(Slot::ObservedAlbedo)) return node;
      m.extent = ir::Medium::Extent::Finite;
      const ir::Param* own = m.slots.find(Slot::Thickness);
      const ExprId fallback = own && own->present() ? own->value : c.b.f(1.0f);
      m.slots.set(Slot::Thickness, {c.b.select(c.b.greater(thickness, c.b.f(0.0f)), thickness, fallback), origin});
      copy.medium = c.material.addMedium(std::move(m));
      break;
    }
    case ir::ScatterKind::Mix:
    case ir::ScatterKind::Add:
      copy.a = interiorAsLayer(c, copy.a, thickness, origin);
      copy.b = interiorAsLayer(c, copy.b, thickness, origin);
      break;
    case ir::ScatterKind::Tint:
    case ir::ScatterKind::Emissive:
      copy.a = interiorAsLayer(c, copy.a, thickness, origin);
      break;
    case ir::ScatterKind::Ambient:
    case ir::ScatterKind::Absorber:
      return node;
  }
  return c.material.addNode(std::move(copy));
}

}  // namespace

Closure lamaLayer(Context& c, const NodeRef& n, std::string_view) {
  Closure top = c.closureInput(n, "materialTop");
  const Closure base = c.closureInput(n, "materialBase");
  if (top.kind == Closure::Kind::Scatter && base.kind == Closure::Kind::Scatter) {
    const ir::Param thickness = c.param(n, "topThickness");
    top.index = interiorAsLayer(c, top.index, c.b.nonNegative(thickness.value), thickness.origin);
  }
  // topMix is the top's coverage: layer(topMix top, base) = mix(base, layer(top, base), topMix).
  ir::Param coverage = c.param(n, "topMix");
  coverage.value = c.b.clamp01(coverage.value);  // a coverage: a fraction of the surface
  if (!c.material.exprs.isConstantEqual(coverage.value, 1.0f)) top = scaleClosure(c, top, coverage, c.nodeOrigin(n));
  return layerClosures(c, top, base, c.nodeOrigin(n));
}

Closure lamaSurface(Context& c, const NodeRef& n, std::string_view) {
  const Closure front = c.closureInput(n, "materialFront");
  if (c.closureInput(n, "materialBack").kind != Closure::Kind::None) {
    c.note(c.origin(n, "materialBack"), "LamaSurface: the back side's material is not rendered (mxc shades the front "
                                        "side of every surface)");
  }
  Index root = front.kind == Closure::Kind::Scatter ? front.index : c.material.leaf(ir::ScatterKind::Absorber, c.nodeOrigin(n));
  const ir::Param presence = c.param(n, "presence");
  const Index covered = withOpacity(c, root, presence, c.nodeOrigin(n));
  if (covered != root) c.material.opacity = presence;  // for transparent shadows
  return scatter(covered);
}

}  // namespace mxc::lower
