// gltf_pbr to the slab IR, following the glTF 2.0 specification ("Metallic-Roughness Material"
// and Appendix B, "BRDF Implementation") and the Khronos material extensions:
//
//   material    = mix(coverage by alpha_mode) of
//                 slab(clear coat, IOR 1.5, coverage clearcoat)            KHR_materials_clearcoat
//                 over emission(emissive * emissive_strength)              KHR_materials_emissive_strength
//                 over slab(sheen, Charlie) over base                       KHR_materials_sheen
//   base        = mix(dielectric, metal, metallic)                          Appendix B
//   dielectric  = mix(slab(f_dielectric) over diffuse, slab(f_dielectric) over the volume, transmission)
//   metal       = Schlick F0 = base_color, F90 = 1 (Appendix B, conductor_fresnel)
//
// f_dielectric is one interface of IOR `ior` (KHR_materials_ior) that reflects and transmits
// (the seed commentary, 4.1); KHR_materials_specular's `specular` and `specular_color` are its
// Fresnel scale and reflection tint, which agree with the extension at normal incidence (F0
// scaled and tinted; the IR's forms, OpenPBR's, also scale and tint the grazing reflection that
// the extension leaves white). Every specular lobe is GGX with alpha = roughness^2, made
// anisotropic by KHR_materials_anisotropy (alpha_t = mix(alpha, 1, strength^2), the tangent
// turned by anisotropy_rotation radians). KHR_materials_iridescence is a thin film on the base
// interfaces with coverage `iridescence`. KHR_materials_volume: thickness 0 is thin-walled;
// otherwise the volume absorbs mu_a = -ln(attenuation_color) / attenuation_distance (no
// absorption without a distance), with KHR_materials_dispersion's Abbe number 20 / dispersion.
// alpha_mode OPAQUE ignores alpha, MASK cuts out below alpha_cutoff, BLEND takes alpha as the
// coverage. `occlusion` scales the host's ambient light and is not part of the BSDF.

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

struct GltfPbr : ShadingModelInputs {
  /// GGX alpha (alpha_t, alpha_b) from roughness^2; KHR_materials_anisotropy stretches alpha_t
  /// towards 1 by strength^2.
  Param specularAlpha() {
    const ExprId roughness = clamped01("roughness").value;
    ExprId alpha = b.mul(roughness, roughness);
    Param strength = clamped01("anisotropy_strength");
    if (isConstant(p("anisotropy_strength"), 0.0f)) return {b.construct(Type::Vec2, {alpha, alpha}), at("roughness")};
    ExprId alphaT = b.lerp(alpha, b.f(1.0f), b.mul(strength.value, strength.value));
    return {b.construct(Type::Vec2, {alphaT, alpha}), strength.origin};
  }

  /// The tangent turned about the normal by anisotropy_rotation (radians, counter-clockwise).
  Param tangent() {
    Param rotation = p("anisotropy_rotation");
    if (isConstant(rotation, 0.0f) || isConstant(p("anisotropy_strength"), 0.0f)) return p("tangent");
    ExprId degrees = b.mul(rotation.value, b.f(57.29577951308232f));
    return {b.normalize(c.material.exprs.op(ir::Op::Rotate3D, Type::Vec3, {p("tangent").value, degrees, p("normal").value})),
            rotation.origin};
  }

  /// KHR_materials_iridescence: a film of iridescence_thickness nanometres and iridescence_ior
  /// on the base interfaces, with coverage `iridescence`.
  ir::ThinFilm iridescence() {
    ir::ThinFilm film;
    Param weight = clamped01("iridescence");
    if (isConstant(p("iridescence"), 0.0f)) return film;
    film.thickness = nonNegative("iridescence_thickness");
    film.ior = p("iridescence_ior");
    film.coverage = weight;
    film.origin = weight.origin;
    return film;
  }

  Index dielectric(const Param& alpha, const Param& tangentParam) {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Dielectric;
    i.scatter = ir::ScatterMode::RT;
    i.origin = c.nodeOrigin(n);
    i.iorReference = ir::IorReference::Ambient;
    i.slots.set(Slot::Ior, p("ior"));
    // KHR_materials_specular: F0 = min(F0(ior) specular_color, 1), the whole weighted by
    // specular. specular_color is not bounded by 1 (its UI range is soft): its largest channel
    // joins specular in the Fresnel scale, which modulates F0 within [0, 1] (mxc_modulated_eta),
    // and the tint keeps the hue, color / max(color) <= 1, so no channel reflects more than
    // arrives. A black colour is a tint of 0.
    const Param color = nonNegative("specular_color");
    const ExprId largest = b.max(b.max(b.extract(color.value, 0), b.extract(color.value, 1)), b.extract(color.value, 2));
    i.slots.set(Slot::FresnelScale, {b.mul(clamped01("specular").value, largest), at("specular")});
    // largest > 0 where divided (the select), guarded again at 1e-6 for the branch not taken.
    i.slots.set(Slot::ReflectionTint, {b.select(b.greater(largest, b.f(0.0f)), b.safeDiv(color.value, largest, 1e-6f),
                                                b.vec(Type::Vec3, 0.0f)),
                                       color.origin});
    i.slots.set(Slot::Alpha, alpha);
    i.slots.set(Slot::Normal, p("normal"));
    i.slots.set(Slot::Tangent, tangentParam);
    i.thinFilm = iridescence();
    return c.material.addInterface(std::move(i));
  }

  Index metal(const Param& alpha, const Param& tangentParam) {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Schlick;
    i.scatter = ir::ScatterMode::R;
    i.origin = c.nodeOrigin(n);
    i.slots.set(Slot::F0, clamped01("base_color"));
    i.slots.set(Slot::F90, {b.vec(Type::Vec3, 1.0f), at("metallic")});
    i.slots.set(Slot::Alpha, alpha);
    i.slots.set(Slot::Normal, p("normal"));
    i.slots.set(Slot::Tangent, tangentParam);
    i.thinFilm = iridescence();
    return c.material.slab(c.material.addInterface(std::move(i)), ir::kNone, ir::kNone, {}, at("metallic"));
  }

  /// KHR_materials_volume under the transmitting dielectric.
  Index volume() {
    if (isConstant(p("thickness"), 0.0f)) {
      // "thickness 0: the material is thin-walled".
      ir::Medium sheet;
      sheet.extent = ir::Medium::Extent::ThinWall;
      sheet.origin = at("thickness");
      return c.material.addMedium(std::move(sheet));
    }
    // Without an attenuation distance the volume does not absorb (the extension's infinity):
    // depth 0 gives the medium no coefficients.
    Param distance = p("attenuation_distance");
    distance.value = distance.value == ir::kNoExpr ? b.f(0.0f) : b.nonNegative(distance.value);
    Param abbe;
    Param dispersion = nonNegative("dispersion");
    if (!isConstant(p("dispersion"), 0.0f)) {
      // KHR_materials_dispersion: dispersion = 20 / V_d; guarded for dispersion 0 (no dispersion).
      abbe = {b.select(b.greater(dispersion.value, b.f(0.0f)), b.safeDiv(b.f(20.0f), dispersion.value, 1e-6f), b.f(0.0f)),
              dispersion.origin};
    }
    return transmissionMedium(c, clamped01("attenuation_color"), distance, {b.vec(Type::Vec3, 0.0f), at("thickness")},
                              {b.f(0.0f), at("thickness")}, p("ior"), abbe, at("thickness"));
  }

  /// alpha_mode: 0 OPAQUE (covered), 1 MASK (alpha >= alpha_cutoff), 2 BLEND (alpha).
  Param coverage() {
    ExprId mode = p("alpha_mode").value;
    ExprId alpha = clamped01("alpha").value;
    ExprId mask = c.material.exprs.op(ir::Op::Select, Type::Float,
                                      {c.material.exprs.op(ir::Op::GreaterEq, Type::Bool, {alpha, p("alpha_cutoff").value}),
                                       b.f(1.0f), b.f(0.0f)});
    auto is = [&](int code) { return c.material.exprs.op(ir::Op::Equal, Type::Bool, {mode, c.material.exprs.constantInt(code)}); };
    return {b.select(is(1), mask, b.select(is(2), alpha, b.f(1.0f))), at("alpha_mode")};
  }

  Index lower() {
    const Param alpha = specularAlpha();
    const Param tangentParam = tangent();

    ir::Interface diffuse;
    diffuse.kind = ir::InterfaceKind::Diffuse;
    diffuse.diffuseModel = ir::DiffuseModel::OrenNayar;  // roughness 0: Appendix B's Lambertian
    diffuse.origin = c.nodeOrigin(n);
    diffuse.slots.set(Slot::Color, clamped01("base_color"));
    diffuse.slots.set(Slot::Roughness, {b.f(0.0f), at("base_color")});
    diffuse.slots.set(Slot::Normal, p("normal"));
    const Index diffuseSlab =
        c.material.slab(c.material.addInterface(std::move(diffuse)), ir::kNone, ir::kNone, {}, at("base_color"));

    const Index top = dielectric(alpha, tangentParam);
    Index dielectricBase = c.material.slab(top, ir::kNone, diffuseSlab, {}, at("specular"));
    Param transmission = clamped01("transmission");
    if (!isConstant(p("transmission"), 0.0f)) {
      // Thin-walled exactly when volume() makes a sheet: a thickness that is 0 everywhere.
      c.material.thinWalled = {c.material.exprs.constantBool(isConstant(p("thickness"), 0.0f)), at("thickness")};
      const Index transmissive = c.material.slab(top, volume(), ir::kNone, {}, at("transmission"));
      dielectricBase = c.material.mix(dielectricBase, transmissive, transmission, at("transmission"));
    }
    Index base = c.material.mix(dielectricBase, metal(alpha, tangentParam), clamped01("metallic"), at("metallic"));

    // KHR_materials_sheen: the Charlie sheen (Estevez & Kulla 2017) over the base, scaling it
    // by its albedo; absent when sheen_color is black.
    Param sheenColor = clamped01("sheen_color");
    if (!isConstant(p("sheen_color"), 0.0f)) {
      ir::Interface sheen;
      sheen.kind = ir::InterfaceKind::Sheen;
      sheen.sheenModel = ir::SheenModel::ContyKulla;
      sheen.origin = c.nodeOrigin(n);
      sheen.slots.set(Slot::Color, sheenColor);
      sheen.slots.set(Slot::Roughness, clamped01("sheen_roughness"));
      sheen.slots.set(Slot::Normal, p("normal"));
      base = c.material.slab(c.material.addInterface(std::move(sheen)), ir::kNone, base, {}, at("sheen_color"));
    }

    // Emission under the clear coat (KHR_materials_clearcoat: the coat's Fresnel dims it).
    ir::Emission e;
    e.kind = ir::Emission::Kind::Uniform;
    e.origin = at("emissive");
    e.slots.set(Slot::Color, {b.mul(b.nonNegative(p("emissive").value), nonNegative("emissive_strength").value), at("emissive")});
    ir::ScatterNode emissive;
    emissive.kind = ir::ScatterKind::Emissive;
    emissive.a = base;
    emissive.emission = c.material.addEmission(std::move(e));
    emissive.origin = at("emissive");
    const Index emitting = c.material.addNode(std::move(emissive));

    // KHR_materials_clearcoat: a dielectric of IOR 1.5 (F0 = 0.04), its own roughness and normal.
    ir::Interface coat;
    coat.kind = ir::InterfaceKind::Dielectric;
    coat.scatter = ir::ScatterMode::RT;
    coat.origin = c.nodeOrigin(n);
    coat.iorReference = ir::IorReference::Ambient;
    coat.slots.set(Slot::Ior, {b.f(1.5f), at("clearcoat")});
    const ExprId coatRoughness = clamped01("clearcoat_roughness").value;
    ExprId coatAlpha = b.mul(coatRoughness, coatRoughness);
    coat.slots.set(Slot::Alpha, {b.construct(Type::Vec2, {coatAlpha, coatAlpha}), at("clearcoat_roughness")});
    coat.slots.set(Slot::Normal, p("clearcoat_normal"));
    Index coated = c.material.slab(c.material.addInterface(std::move(coat)), ir::kNone, emitting, clamped01("clearcoat"),
                                   at("clearcoat"));

    const Param covered = coverage();
    if (!isConstant(covered, 1.0f)) {
      c.material.opacity = covered;
      coated = c.material.mix(c.material.leaf(ir::ScatterKind::Ambient, at("alpha")), coated, covered, at("alpha"));
    }
    return coated;
  }
};

}  // namespace

Index lowerGltfPbr(Context& c, const NodeRef& n) {
  GltfPbr model{{c, n, c.b}};
  return model.lower();
}

}  // namespace mxc::lower
