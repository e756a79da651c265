// UsdPreviewSurface to the slab IR, following the UsdPreviewSurface specification (version 2.6,
// OpenUSD documentation, "UsdPreviewSurface Specification", "Preview Surface" inputs):
//
//   surface     = emission(emissiveColor) over mix(nothing, coated, coverage)
//   coated      = slab(clearcoat dielectric, IOR 1.5, alpha clearcoatRoughness^2; coverage clearcoat)
//                 over workflow
//   workflow    = mix(metalness, specular, useSpecularWorkflow)
//   specular    = slab(Schlick F0 = specularColor, F90 = 1) over base
//   metalness   = mix(slab(dielectric ior) over base, Schlick F0 = diffuseColor, F90 = 1; metallic)
//   base        = mix(diffuse(diffuseColor), refraction through the ior, 1 - opacity)   (transparent mode)
//
// Every specular lobe is GGX with alpha = roughness^2 ("roughness ... usually squared before
// use with a GGX lobe"). The spec's metallic F0 "derived from diffuseColor" with a white edge
// is the generalized Schlick lobe; its non-metallic F0 from `ior` is the exact Fresnel of a
// dielectric of that IOR, the interface whose transmission also carries the transparent
// mode's refraction (the seed commentary, 4.1: one dielectric BSDF reflects and transmits).
// The spec gives the clear coat no IOR: 1.5 (F0 = 0.04), the value of common coats.
// opacityMode "transparent" (0): opacity below 1 refracts (glass still reflects); with
// opacityThreshold > 0, or in "presence" mode (1), opacity is the coverage instead (a cutout:
// 0 below the threshold, 1 at or above it). `occlusion` (an ambient-occlusion factor for the
// host's indirect light) and `displacement` (geometry) are not part of the BSDF.

#include "compiler/lower/Context.h"
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

struct UsdPreviewSurface : ShadingModelInputs {
  Param normal;  // the shading normal, from the tangent-space `normal` input

  /// GGX alpha = roughness^2, isotropic (the spec's squaring; burleyAlpha with no anisotropy).
  Param alpha(std::string_view roughness) { return {burleyAlpha(b, clamped01(roughness).value, b.f(0.0f)), at(roughness)}; }

  /// The spec's `normal` is a tangent-space normal in [-1, 1]^3: normalmap of it mapped to [0, 1].
  /// The default (0, 0, 1) is the geometric normal itself.
  Param shadingNormal() {
    Param tangentSpace = p("normal");
    const ExprId world = c.material.exprs.named(ir::Op::GeomProp, Type::Vec3, "Nworld");
    if (c.material.exprs.isConstant(tangentSpace.value)) {
      const std::vector<float> v = c.material.exprs.constantComponents(tangentSpace.value);
      if (v.size() == 3 && v[0] == 0.0f && v[1] == 0.0f && v[2] > 0.0f) return {world, tangentSpace.origin};
    }
    ExprId encoded = b.add(b.mul(tangentSpace.value, b.f(0.5f)), b.f(0.5f));
    ExprId mapped = c.material.exprs.op(
        ir::Op::NormalMap, Type::Vec3,
        {encoded, b.vec(Type::Vec2, 1.0f), world, c.material.exprs.named(ir::Op::GeomProp, Type::Vec3, "Tworld"),
         c.material.exprs.named(ir::Op::GeomProp, Type::Vec3, "Bworld")});
    return {mapped, tangentSpace.origin};
  }

  Index interface(ir::Interface i) {
    i.origin = c.nodeOrigin(n);
    i.slots.set(Slot::Normal, normal);
    return c.material.addInterface(std::move(i));
  }

  Index dielectric(const Param& ior, const Param& a) { return interface(dielectricInterface(ior, a)); }
  Index schlick(const Param& f0, const Param& a) { return interface(schlickInterface(f0, a)); }

  /// The weight of refraction in the transparent mode: 1 - opacity when the mode is
  /// "transparent" and no threshold makes opacity a cutout; 0 otherwise.
  Param refraction() {
    ExprId opacity = clamped01("opacity").value;
    ExprId transparent = b.select(b.greater(p("opacityThreshold").value, b.f(0.0f)), b.f(1.0f), opacity);
    ExprId presence = c.material.exprs.op(ir::Op::Greater, Type::Bool, {p("opacityMode").value, c.material.exprs.constantInt(0)});
    return {b.select(presence, b.f(0.0f), b.sub(b.f(1.0f), transparent)), at("opacity")};
  }

  /// The coverage: in "presence" mode, or with a threshold, opacity as a cutout when the
  /// threshold is above 0 and as it is otherwise; in "transparent" mode without a threshold, 1.
  Param coverage() {
    Param opacity = clamped01("opacity");
    ExprId threshold = p("opacityThreshold").value;
    ExprId cutout = c.material.exprs.op(ir::Op::Select, Type::Float,
                                        {c.material.exprs.op(ir::Op::GreaterEq, Type::Bool, {opacity.value, threshold}),
                                         b.f(1.0f), b.f(0.0f)});
    ExprId thresholded = b.greater(threshold, b.f(0.0f));
    ExprId presence = c.material.exprs.op(ir::Op::Greater, Type::Bool, {p("opacityMode").value, c.material.exprs.constantInt(0)});
    ExprId presenceCoverage = b.select(thresholded, cutout, opacity.value);
    // Transparent mode: a threshold still cuts out; without one, opacity >= 0 always holds.
    return {b.select(presence, presenceCoverage, cutout), at("opacity")};
  }

  Index lower() {
    normal = shadingNormal();
    const Param a = alpha("roughness");

    // base: the diffuse lobe, or refraction through a body of IOR `ior`.
    ir::Interface diffuse;
    diffuse.kind = ir::InterfaceKind::Diffuse;
    diffuse.diffuseModel = ir::DiffuseModel::OrenNayar;  // roughness 0: Lambertian, as the spec's diffuse
    diffuse.slots.set(Slot::Color, clamped01("diffuseColor"));
    diffuse.slots.set(Slot::Roughness, {b.f(0.0f), at("diffuseColor")});
    const Index diffuseSlab = c.material.slab(interface(std::move(diffuse)), ir::kNone, ir::kNone, {}, at("diffuseColor"));
    const Param refract = refraction();
    const bool opaque = isConstant(refract, 0.0f);
    auto body = [&]() {
      const Param none{b.f(0.0f), at("ior")};
      return transmissionMedium(c, {b.vec(Type::Vec3, 1.0f), at("opacity")}, none, {b.vec(Type::Vec3, 0.0f), at("opacity")},
                                none, p("ior"), {}, at("opacity"));
    };

    // Metalness workflow: the dielectric over the diffuse base (or over the refracting body),
    // mixed by `metallic` with the metal's Schlick reflection.
    Index metalness = ir::kNone;
    if (!isConstant(p("useSpecularWorkflow"), 1.0f)) {
      const Index top = dielectric(p("ior"), a);
      Index nonMetal = c.material.slab(top, ir::kNone, diffuseSlab, {}, at("ior"));
      if (!opaque) nonMetal = c.material.mix(nonMetal, c.material.slab(top, body(), ir::kNone, {}, at("opacity")), refract, at("opacity"));
      const Index metal =
          c.material.slab(schlick(clamped01("diffuseColor"), a), ir::kNone, ir::kNone, {}, at("metallic"));
      metalness = c.material.mix(nonMetal, metal, clamped01("metallic"), at("metallic"));
    }
    // Specular workflow: the specular colour's Schlick reflection over the diffuse base (or a
    // refracting dielectric of IOR `ior`).
    Index specular = ir::kNone;
    if (!isConstant(p("useSpecularWorkflow"), 0.0f)) {
      Index base = diffuseSlab;
      if (!opaque) {
        base = c.material.mix(diffuseSlab, c.material.slab(dielectric(p("ior"), a), body(), ir::kNone, {}, at("opacity")),
                              refract, at("opacity"));
      }
      specular = c.material.slab(schlick(clamped01("specularColor"), a), ir::kNone, base, {}, at("specularColor"));
    }
    Index workflow = metalness == ir::kNone ? specular
                     : specular == ir::kNone
                         ? metalness
                         : c.material.mix(metalness, specular,
                                          {c.material.exprs.op(ir::Op::Construct, Type::Float, {p("useSpecularWorkflow").value}),
                                           at("useSpecularWorkflow")},
                                          at("useSpecularWorkflow"));

    // The clear coat: a white dielectric of IOR 1.5 over the rest, coverage `clearcoat`.
    const Index coat = dielectric({b.f(1.5f), at("clearcoat")}, alpha("clearcoatRoughness"));
    Index coated = c.material.slab(coat, ir::kNone, workflow, clamped01("clearcoat"), at("clearcoat"));

    const Param covered = coverage();
    if (!isConstant(covered, 1.0f)) {
      c.material.opacity = covered;
      coated = c.material.mix(c.material.leaf(ir::ScatterKind::Ambient, at("opacity")), coated, covered, at("opacity"));
    }

    // Emission on top of everything (the spec's emissiveColor is the surface's own radiance).
    ir::Emission e;
    e.kind = ir::Emission::Kind::Uniform;
    e.origin = at("emissiveColor");
    e.slots.set(Slot::Color, {b.nonNegative(p("emissiveColor").value), at("emissiveColor")});
    ir::ScatterNode emissive;
    emissive.kind = ir::ScatterKind::Emissive;
    emissive.a = coated;
    emissive.emission = c.material.addEmission(std::move(e));
    emissive.origin = at("emissiveColor");
    return c.material.addNode(std::move(emissive));
  }
};

}  // namespace

Index lowerUsdPreviewSurface(Context& c, const NodeRef& n) {
  UsdPreviewSurface model{{c, n, c.b}, {}};
  return model.lower();
}

}  // namespace mxc::lower
