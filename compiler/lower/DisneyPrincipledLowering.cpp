// disney_principled to the slab IR, following Burley 2012, "Physically-Based Shading at Disney"
// (s. 5: the BRDF and its parameters) and Burley 2015, "Extending the Disney BRDF to a BSDF with
// Integrated Subsurface Scattering" (specular transmission, its IOR, subsurface distance):
//
//   surface    = slab(clear coat, IOR 1.5; coverage clearcoat / 4) over metallic
//   metallic   = mix(dielectric, slab(Schlick F0 = baseColor, F90 = 1), metallic)
//   dielectric = mix(slab(Schlick F0 = 0.08 specular lerp(1, tint, specularTint)) over sheened,
//                    slab(dielectric of IOR `ior`) over a clear bulk,  specTrans)
//   sheened    = slab(sheen, colour lerp(1, tint, sheenTint); coverage sheen) over
//                mix(Burley diffuse(baseColor, roughness), subsurface(baseColor, subsurfaceDistance), subsurface)
//
// where tint = baseColor / luminance(baseColor), the hue (2012, "Specular tint"). Every specular
// lobe is GGX with alpha = roughness^2, stretched by the aspect sqrt(1 - 0.9 anisotropic) (2012,
// addenda: alpha_x = alpha / aspect, alpha_y = alpha aspect). Burley's additive lobes become
// layers and mixes, so that the whole is energy-bounded: the specular reflection is a Schlick
// layer over what it does not reflect, and the metal replaces the dielectric in proportion to
// `metallic` (2012's (1 - metallic) on the diffuse and lerp of the specular colour). Two of the
// paper's lobes are replaced by the nearest of mxc's: the clear coat's GTR1 distribution by GGX
// of the same alpha, lerp(0.1, 0.001, clearcoatGloss), with the paper's fixed IOR 1.5 and its
// 0.25 amplitude as the layer's coverage; and the sheen's Schlick-weighted retro-reflection by
// Estevez and Kulla's sheen at roughness 0.3 (MaterialX's sheen_bsdf default, which MaterialX's
// own graph of this node uses). The transmission is tinted by baseColor (2015, s. 4), and its
// body is clear: the paper's thin-surface and absorption-at-depth options have no inputs here.

#include "compiler/lower/Context.h"
#include "compiler/lower/Media.h"
#include "compiler/lower/ShadingModel.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Index;
using ir::Param;
using ir::Slot;
using ir::Type;

namespace {

struct DisneyPrincipled : ShadingModelInputs {
  /// The hue of baseColor: baseColor / luminance (Rec. 709 weights), white for a black base
  /// (the paper's "tint ... normalized by luminance to isolate hue and saturation").
  ExprId tint() {
    const ExprId base = clamped01("baseColor").value;
    const ExprId l = b.dot(base, c.material.exprs.constantVector(Type::Vec3, {0.2126f, 0.7152f, 0.0722f}));
    // luminance > 0: divided (by at least 1e-6); 0 (black): white, as the paper's code does.
    return b.select(b.greater(l, b.f(0.0f)), b.div(base, b.max(l, b.f(1e-6f))), b.vec(Type::Vec3, 1.0f));
  }

  /// alpha = roughness^2 along the tangent and bitangent, stretched by the aspect
  /// sqrt(1 - 0.9 anisotropic) (>= sqrt(0.1): never 0).
  Param specularAlpha() {
    const ExprId alpha = b.mul(clamped01("roughness").value, clamped01("roughness").value);
    const Param anisotropic = clamped01("anisotropic");
    if (isConstant(p("anisotropic"), 0.0f)) return {b.construct(Type::Vec2, {alpha, alpha}), at("roughness")};
    const ExprId aspect = b.sqrt(b.sub(b.f(1.0f), b.mul(b.f(0.9f), anisotropic.value)));
    return {b.construct(Type::Vec2, {b.div(alpha, aspect), b.mul(alpha, aspect)}), at("anisotropic")};
  }

  Index interface(ir::Interface i) { return c.material.addInterface(std::move(i)); }
  Index dielectric(const Param& ior, const Param& alpha) { return interface(dielectricInterface(ior, alpha)); }
  Index schlick(const Param& f0, const Param& alpha) { return interface(schlickInterface(f0, alpha)); }

  Index lower() {
    const Param alpha = specularAlpha();
    const Param base = clamped01("baseColor");

    // The diffuse base: Burley's diffuse, or subsurface scattering over subsurfaceDistance.
    ir::Interface diffuse;
    diffuse.kind = ir::InterfaceKind::Burley;
    diffuse.origin = c.nodeOrigin(n);
    diffuse.slots.set(Slot::Color, base);
    diffuse.slots.set(Slot::Roughness, clamped01("roughness"));
    Index under = c.material.slab(interface(std::move(diffuse)), ir::kNone, ir::kNone, {}, at("baseColor"));
    if (!isConstant(p("subsurface"), 0.0f)) {
      const Index medium = subsurfaceMedium(c, base, nonNegative("subsurfaceDistance"), {b.f(0.0f), at("subsurface")},
                                            at("subsurface"));
      under = c.material.mix(under, c.material.slab(ir::kNone, medium, ir::kNone, {}, at("subsurface")),
                             clamped01("subsurface"), at("subsurface"));
    }

    // Sheen over it, coverage `sheen`, coloured lerp(1, tint, sheenTint).
    ir::Interface sheen;
    sheen.kind = ir::InterfaceKind::Sheen;
    sheen.origin = c.nodeOrigin(n);
    sheen.sheenModel = ir::SheenModel::ContyKulla;
    // The hue of a saturated base exceeds 1 in a channel (pure blue: 13.8); clamped to 1, so that
    // the sheen, like every lobe, reflects at most what it receives.
    sheen.slots.set(Slot::Color, {b.clamp01(b.lerp(b.vec(Type::Vec3, 1.0f), tint(), clamped01("sheenTint").value)),
                                  at("sheenTint")});
    sheen.slots.set(Slot::Roughness, {b.f(0.3f), at("sheen")});
    const Index sheened = c.material.slab(interface(std::move(sheen)), ir::kNone, under, clamped01("sheen"), at("sheen"));

    // The specular reflection of the opaque dielectric: F0 = 0.08 specular lerp(1, tint,
    // specularTint) (2012: specular 0.5 is F0 0.04, an IOR of 1.5), to white at grazing.
    // At most 1 per channel: the tint of a saturated base can take 0.08 x 13.8 past it.
    const ExprId f0 = b.clamp01(b.mul(b.mul(b.f(0.08f), clamped01("specular").value),
                                      b.lerp(b.vec(Type::Vec3, 1.0f), tint(), clamped01("specularTint").value)));
    Index dielectricPart = c.material.slab(schlick({f0, at("specular")}, alpha), ir::kNone, sheened, {}, at("specular"));

    // Specular transmission (2015): a rough dielectric of IOR `ior` over a clear body, tinted
    // by baseColor, in proportion specTrans.
    if (!isConstant(p("specTrans"), 0.0f)) {
      const Param none{b.f(0.0f), at("specTrans")};
      const Index body = transmissionMedium(c, base, none, {b.vec(Type::Vec3, 0.0f), at("specTrans")}, none, p("ior"), {},
                                            at("specTrans"));
      const Index refractive = dielectric(p("ior"), alpha);
      c.material.interfaces[refractive].slots.set(Slot::TransmissionTint, base);
      dielectricPart = c.material.mix(dielectricPart, c.material.slab(refractive, body, ir::kNone, {}, at("specTrans")),
                                      clamped01("specTrans"), at("specTrans"));
    }

    // The metal: Schlick from baseColor to white (2012: the specular colour lerps to baseColor
    // with metallic, and the diffuse fades out).
    const Index metal = c.material.slab(schlick(base, alpha), ir::kNone, ir::kNone, {}, at("metallic"));
    const Index metallic = c.material.mix(dielectricPart, metal, clamped01("metallic"), at("metallic"));

    // The clear coat: IOR 1.5 (F0 0.04), alpha lerp(0.1, 0.001, clearcoatGloss), amplitude 1/4.
    const ExprId coatAlpha = b.lerp(b.f(0.1f), b.f(0.001f), clamped01("clearcoatGloss").value);
    const Index coat = dielectric({b.f(1.5f), at("clearcoat")}, {b.construct(Type::Vec2, {coatAlpha, coatAlpha}),
                                                                  at("clearcoatGloss")});
    const Param coverage{b.mul(clamped01("clearcoat").value, b.f(0.25f)), at("clearcoat")};
    return c.material.slab(coat, ir::kNone, metallic, coverage, at("clearcoat"));
  }
};

}  // namespace

Index lowerDisneyPrincipled(Context& c, const NodeRef& n) {
  DisneyPrincipled model{{c, n, c.b}};
  return model.lower();
}

}  // namespace mxc::lower
