// open_pbr_surface to the slab IR, following the OpenPBR Surface 1.1 specification, "Model":
//
//   M_PBR            = mix(Slab(empty), M_surface, geometry_opacity)
//   M_surface        = layer(M_coated_base, S_fuzz, fuzz_weight)
//   M_coated_base    = layer(M_base_substrate, S_coat, coat_weight)      (emission from the base)
//   M_base_substrate = mix(M_dielectric_base, S_metal, base_metalness)
//   M_dielectric_base= mix(M_opaque_base, S_translucent_base, transmission_weight)
//   M_opaque_base    = mix(M_glossy_diffuse, S_subsurface, subsurface_weight)
//   M_glossy_diffuse = layer(S_diffuse, S_gloss)
//
// The IR keeps the physical parameters (IORs, roughnesses, media); the approximations the spec
// suggests for a lobe mixture (eta lerp across coat coverage, coat darkening and roughening,
// TIR fix) belong to the evaluation tiers, which read them from here.

#include <fmt/format.h>

#include "compiler/lower/Context.h"
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

// The input ranges clamped to are OpenPBR's "Parameter reference".
struct OpenPbr : ShadingModelInputs {
  /// OpenPBR "Darkening" needs two properties of the base under the coat, estimated from the
  /// parameters. E_b, its albedo at normal incidence: the metal's F0 = base_weight * base_color,
  /// else the dielectric's diffuse albedo (base_weight * base_color, or subsurface_color as
  /// subsurface_weight mixes it in).
  ExprId darkeningBaseAlbedo() {
    const ExprId metal = b.mul(clamped("base_color", 0.0f, 1.0f).value, clamped("base_weight", 0.0f, 1.0f).value);
    const ExprId dielectric = b.lerp(metal, clamped("subsurface_color", 0.0f, 1.0f).value,
                                     clamped("subsurface_weight", 0.0f, 1.0f).value);
    return b.lerp(dielectric, metal, clamped("base_metalness", 0.0f, 1.0f).value);
  }
  /// r_b, its effective roughness: lerp(r_d, r_m, M) with r_m = r and
  /// r_d = lerp(1, r, clamp(xi_s F_s, 0, 1)) (eqs. base_roughness_estimate and
  /// dielectric_roughness_estimate), F_s the base interface's normal-incidence Fresnel under
  /// the coat (IOR ratio specular_ior / coat_ior, inverted when below 1 as in eq.
  /// specular_ior_ratio_with_tir_fix).
  ExprId darkeningBaseRoughness() {
    const ExprId r = clamped("specular_roughness", 0.0f, 1.0f).value;
    // Both IORs kept >= 1e-3, so the ratio and its inverse are finite and positive.
    const ExprId ratio = b.div(b.max(p("specular_ior").value, b.f(1e-3f)), b.max(p("coat_ior").value, b.f(1e-3f)));
    const ExprId eta = b.max(ratio, b.div(b.f(1.0f), ratio));  // >= 1
    const ExprId amplitude = b.div(b.sub(eta, b.f(1.0f)), b.add(eta, b.f(1.0f)));  // eta + 1 >= 2
    const ExprId fs = b.mul(amplitude, amplitude);
    const ExprId xiFs = b.clamp(b.mul(b.nonNegative(p("specular_weight").value), fs), b.f(0.0f), b.f(1.0f));
    const ExprId rd = b.lerp(b.f(1.0f), r, xiFs);
    return b.lerp(rd, r, clamped("base_metalness", 0.0f, 1.0f).value);
  }

  /// The IOR of the medium in which the light the base returns into the coat starts: the
  /// dielectric base's (its diffuse lobe and subsurface lie under that interface), the coat's own
  /// for a metal (which returns its light into the coat directly), mixed by base_metalness. A
  /// base less dense than the coat fills only part of the coat's hemisphere with its light
  /// (mxc_coat_darkening). The dielectric's IOR is specular_ior modulated by specular_weight, as
  /// the interface's Fresnel is (eq. modulated_ior: F0 scaled by xi_s, the IOR ratio to the coat
  /// that has that F0, on the same side of 1): specular_weight 0 is index-matched to the coat.
  ExprId darkeningBaseIor() {
    const ExprId coat = b.max(p("coat_ior").value, b.f(1e-3f));
    const ExprId ratio = b.div(b.max(p("specular_ior").value, b.f(1e-3f)), coat);  // both >= 1e-3
    const ExprId eta = b.max(ratio, b.div(b.f(1.0f), ratio));                         // >= 1
    const ExprId amplitude = b.div(b.sub(eta, b.f(1.0f)), b.add(eta, b.f(1.0f)));    // eta + 1 >= 2
    const ExprId f0 = b.clamp(b.mul(b.nonNegative(p("specular_weight").value), b.mul(amplitude, amplitude)), b.f(0.0f),
                              b.f(0.99f));
    const ExprId root = b.sqrt(f0);                                                  // f0 >= 0
    const ExprId modulated = b.div(b.add(b.f(1.0f), root), b.sub(b.f(1.0f), root));  // 1 - root >= 0.005
    const ExprId modulatedRatio = b.select(b.greater(ratio, b.f(1.0f)), modulated, b.div(b.f(1.0f), modulated));
    return b.lerp(b.mul(modulatedRatio, coat), coat, clamped("base_metalness", 0.0f, 1.0f).value);
  }

  /// The thin film of the base interfaces (OpenPBR "Thin-film iridescence"): thickness is given
  /// in micrometres; the IR keeps nanometres.
  ir::ThinFilm thinFilm() {
    ir::ThinFilm film;
    Param weight = clamped("thin_film_weight", 0.0f, 1.0f);
    Param thickness = nonNegative("thin_film_thickness");
    thickness.value = b.mul(thickness.value, b.f(1000.0f));
    film.thickness = thickness;
    film.ior = p("thin_film_ior");
    film.coverage = weight;
    film.origin = weight.origin;
    return film;
  }

  /// f_dielectric: the interface of the whole dielectric base (OpenPBR "Dielectric base").
  Index dielectric(ExprId alpha, bool thinWalled) {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Dielectric;
    i.scatter = ir::ScatterMode::RT;
    i.origin = c.nodeOrigin(n);
    i.slots.set(Slot::Ior, p("specular_ior"));
    // specular_weight may exceed 1; the evaluator clamps xi to [0, 1/F_s] (eq. modulated_ior).
    i.slots.set(Slot::FresnelScale, nonNegative("specular_weight"));
    // The dielectric's tint stays in [0, 1] (OpenPBR "Specular": range [0, 1]^3): it scales the
    // Fresnel factor, which reaches 1 at grazing incidence, so a tint above 1 would reflect more
    // light than arrives there.
    i.slots.set(Slot::ReflectionTint, clamped("specular_color", 0.0f, 1.0f));
    // At transmission_depth 0 the transmission_color tints the refraction instead of a medium.
    // Not in thin-walled mode, where the sheet under the interface is what absorbs it (translucent):
    // a tint as well counted the colour once more on the way in, and again on the way out through
    // the sheet's far side, which is the same interface (0.125 for a colour of 0.5, issue 39).
    if (!thinWalled) {
      Param depth = nonNegative("transmission_depth");
      Param tint = clamped("transmission_color", 0.0f, 1.0f);
      tint.value = b.select(b.greater(depth.value, b.f(0.0f)), b.vec(Type::Vec3, 1.0f), tint.value);
      i.slots.set(Slot::TransmissionTint, tint);
    }
    i.slots.set(Slot::Alpha, {alpha, roughnessOrigin("specular_roughness", "specular_roughness_anisotropy")});
    i.slots.set(Slot::Normal, p("geometry_normal"));
    i.slots.set(Slot::Tangent, p("geometry_tangent"));
    i.thinFilm = thinFilm();
    return c.material.addInterface(std::move(i));
  }

  /// S_metal = Slab(f_conductor): F82-tint Schlick Fresnel (OpenPBR "Metal", Kutz 2021):
  /// F0 = base_weight * base_color, edge tint specular_color, scaled by specular_weight.
  Index metal(ExprId alpha) {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Schlick;
    i.scatter = ir::ScatterMode::R;
    i.origin = c.nodeOrigin(n);
    Param f0 = clamped("base_color", 0.0f, 1.0f);
    f0.value = b.mul(f0.value, clamped("base_weight", 0.0f, 1.0f).value);
    i.slots.set(Slot::F0, f0);
    // The edge tint is not clamped to its UI range [0, 1]: OpenPBR's own metal presets (brass,
    // potassium, rubidium, sodium) tint above 1, and the spec's bound is physical, on the
    // reflectance: F82-tint keeps F(mu) in [0, 1] at every angle (mxc_fresnel_f82 clamps it), so
    // only a negative tint, which has no meaning, is refused.
    i.slots.set(Slot::F82, nonNegative("specular_color"));
    i.slots.set(Slot::F90, {b.vec(Type::Vec3, 1.0f), at("specular_color")});
    i.slots.set(Slot::Exponent, {b.f(5.0f), at("specular_color")});
    // OpenPBR "Metal": F = specular_weight F82(mu), a reflectance: a weight above 1 (allowed for
    // the dielectric, whose F0 it modulates within [0, 1]) would reflect more than arrives.
    i.slots.set(Slot::FresnelScale, clamped("specular_weight", 0.0f, 1.0f));
    i.slots.set(Slot::Alpha, {alpha, roughnessOrigin("specular_roughness", "specular_roughness_anisotropy")});
    i.slots.set(Slot::Normal, p("geometry_normal"));
    i.slots.set(Slot::Tangent, p("geometry_tangent"));
    i.thinFilm = thinFilm();
    return c.material.slab(c.material.addInterface(std::move(i)), ir::kNone, ir::kNone, {}, at("base_metalness"));
  }

  /// S_diffuse = Slab(f_diffuse), EON (OpenPBR "Glossy-diffuse", eqs. FON_brdf, EON_comp): rho is
  /// base_color; the weight w_d = base_weight scales the whole lobe (not rho, which the
  /// energy compensation term depends on), so it is the coverage of the diffuse slab.
  Index diffuse() {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Diffuse;
    i.diffuseModel = ir::DiffuseModel::EON;
    i.origin = c.nodeOrigin(n);
    i.slots.set(Slot::Color, clamped("base_color", 0.0f, 1.0f));
    i.slots.set(Slot::Roughness, clamped("base_diffuse_roughness", 0.0f, 1.0f));
    i.slots.set(Slot::Normal, p("geometry_normal"));
    return c.material.slab(c.material.addInterface(std::move(i)), ir::kNone, ir::kNone,
                           clamped("base_weight", 0.0f, 1.0f), at("base_color"));
  }

  /// S_subsurface = Slab(f_dielectric, V_subsurface) in bulk; in thin-walled mode a diffuse
  /// sheet splitting subsurface_color into reflection and transmission by g (OpenPBR
  /// "Thin-walled mode", eq. thin_wall_subsurface).
  Index subsurface(Index dielectricTop, bool thinWalled) {
    if (thinWalled) {
      ir::Interface sheet;
      sheet.kind = ir::InterfaceKind::DiffuseSheet;
      sheet.origin = c.nodeOrigin(n);
      sheet.slots.set(Slot::Color, clamped("subsurface_color", 0.0f, 1.0f));
      sheet.slots.set(Slot::Anisotropy, clamped("subsurface_scatter_anisotropy", -1.0f, 1.0f));
      sheet.slots.set(Slot::Roughness, clamped("base_diffuse_roughness", 0.0f, 1.0f));
      sheet.slots.set(Slot::Normal, p("geometry_normal"));
      Index inner = c.material.slab(c.material.addInterface(std::move(sheet)), ir::kNone, ir::kNone, {},
                                    at("subsurface_weight"));
      return c.material.slab(dielectricTop, ir::kNone, inner, {}, at("subsurface_weight"));
    }
    Param mfp = nonNegative("subsurface_radius");
    mfp.value = b.mul(b.nonNegative(p("subsurface_radius_scale").value), mfp.value);
    Index medium = subsurfaceMedium(c, p("subsurface_color"), mfp, p("subsurface_scatter_anisotropy"),
                                    at("subsurface_weight"));
    return c.material.slab(dielectricTop, medium, ir::kNone, {}, at("subsurface_weight"));
  }

  /// Dispersion of the bulk (OpenPBR "Translucent base"): V_d = abbe_number / dispersion_scale;
  /// scale 0 is "no dispersion" (infinite V_d), written 0. The division is in the branch where
  /// scale > 0 and is guarded by max(scale, 1e-6). Absent when the scale is the constant 0.
  Param abbeNumber() {
    // [0, 1] is the scale's UI range; any scale >= 0 gives a positive V_d.
    Param scale = nonNegative("transmission_dispersion_scale");
    if (isConstant(p("transmission_dispersion_scale"), 0.0f)) return {};
    Param abbe = nonNegative("transmission_dispersion_abbe_number");
    ExprId vd = b.select(b.greater(scale.value, b.f(0.0f)), b.safeDiv(abbe.value, scale.value, 1e-6f), b.f(0.0f));
    return {vd, scale.origin};
  }

  /// S_translucent_base = Slab(f_dielectric, V_dielectric) in bulk; in thin-walled mode an
  /// absorbing sheet whose normal-incidence transmittance is transmission_color.
  Index translucent(Index dielectricTop, bool thinWalled) {
    if (thinWalled) {
      ir::Medium sheet;
      sheet.extent = ir::Medium::Extent::ThinWall;
      sheet.origin = at("transmission_weight");
      // -ln(T) with T clamped to [1e-6, 1]: finite and >= 0.
      Param color = clamped("transmission_color", 1e-6f, 1.0f);
      sheet.slots.set(Slot::Absorption, {b.neg(b.ln(color.value)), color.origin});
      sheet.slots.set(Slot::Thickness, {b.f(1.0f), color.origin});
      return c.material.slab(dielectricTop, c.material.addMedium(std::move(sheet)), ir::kNone, {},
                             at("transmission_weight"));
    }
    Index medium = transmissionMedium(c, clamped("transmission_color", 0.0f, 1.0f), nonNegative("transmission_depth"),
                                      p("transmission_scatter"), p("transmission_scatter_anisotropy"), p("specular_ior"),
                                      abbeNumber(), at("transmission_weight"));
    return c.material.slab(dielectricTop, medium, ir::kNone, {}, at("transmission_weight"));
  }

  /// Where a roughness comes from: its anisotropy input when that is not the constant 0 (the
  /// input that makes the lobe anisotropic), else the roughness input.
  ir::Origin roughnessOrigin(std::string_view roughness, std::string_view anisotropy) {
    return isConstant(p(anisotropy), 0.0f) ? at(roughness) : at(anisotropy);
  }

  /// M_base_substrate for one thin-walled mode.
  Index baseSubstrate(bool thinWalled) {
    ExprId alpha = openPbrAlpha(b, p("specular_roughness").value, p("specular_roughness_anisotropy").value);
    Index top = dielectric(alpha, thinWalled);
    Index gloss = c.material.slab(top, ir::kNone, diffuse(), {}, at("specular_weight"));
    Index opaque = c.material.mix(gloss, subsurface(top, thinWalled), clamped("subsurface_weight", 0.0f, 1.0f),
                                  at("subsurface_weight"));
    Index dielectricBase = c.material.mix(opaque, translucent(top, thinWalled),
                                          clamped("transmission_weight", 0.0f, 1.0f), at("transmission_weight"));
    return c.material.mix(dielectricBase, metal(alpha), clamped("base_metalness", 0.0f, 1.0f), at("base_metalness"));
  }

  Index lower() {
    // Thin-walled mode changes the base (OpenPBR "Thin-walled mode"); when it is not a constant,
    // both structures are kept and mixed by it.
    Param thin = p("geometry_thin_walled");
    c.material.thinWalled = thin;
    Index base;
    if (isConstant(thin, 0.0f)) {
      base = baseSubstrate(false);
    } else if (isConstant(thin, 1.0f)) {
      base = baseSubstrate(true);
    } else {
      Param w{c.material.exprs.op(ir::Op::Construct, Type::Float, {thin.value}), thin.origin};
      base = c.material.mix(baseSubstrate(false), baseSubstrate(true), w, thin.origin);
    }

    // Emission from the base substrate, under coat and fuzz (OpenPBR "Emission").
    ir::Emission e;
    e.kind = ir::Emission::Kind::Uniform;
    e.origin = at("emission_luminance");
    Param luminance = nonNegative("emission_luminance");
    e.slots.set(Slot::Color, {b.mul(nonNegative("emission_color").value, luminance.value), luminance.origin});
    ir::ScatterNode emissive;
    emissive.kind = ir::ScatterKind::Emissive;
    emissive.a = base;
    emissive.emission = c.material.addEmission(std::move(e));
    emissive.origin = at("emission_luminance");
    Index emitting = c.material.addNode(std::move(emissive));

    // S_coat = Slab(f_coat, V_coat) with coverage coat_weight (OpenPBR "Coat").
    ir::Interface coat;
    coat.kind = ir::InterfaceKind::Dielectric;
    coat.scatter = ir::ScatterMode::RT;
    coat.origin = c.nodeOrigin(n);
    coat.slots.set(Slot::Ior, p("coat_ior"));
    coat.slots.set(Slot::Alpha, {openPbrAlpha(b, p("coat_roughness").value, p("coat_roughness_anisotropy").value),
                                 roughnessOrigin("coat_roughness", "coat_roughness_anisotropy")});
    coat.slots.set(Slot::Normal, p("geometry_coat_normal"));
    coat.slots.set(Slot::Tangent, p("geometry_coat_tangent"));
    coat.slots.set(Slot::Darkening, clamped("coat_darkening", 0.0f, 1.0f));
    coat.slots.set(Slot::BaseAlbedo, {darkeningBaseAlbedo(), at("coat_darkening")});
    coat.slots.set(Slot::BaseRoughness, {darkeningBaseRoughness(), at("coat_darkening")});
    coat.slots.set(Slot::BaseIor, {darkeningBaseIor(), at("coat_darkening")});
    Index coatMediumIndex = coatMedium(c, clamped("coat_color", 0.0f, 1.0f), at("coat_color"));
    Index coated = c.material.slab(c.material.addInterface(std::move(coat)), coatMediumIndex, emitting,
                                   clamped("coat_weight", 0.0f, 1.0f), at("coat_weight"));

    // S_fuzz (OpenPBR "Fuzz"): Zeltner 2022 sheen, index-matched, coverage fuzz_weight. Its
    // normal follows the substrate: the base and coat normals blended by coat_weight (the
    // spec's practical approximation).
    ir::Interface fuzz;
    fuzz.kind = ir::InterfaceKind::Sheen;
    fuzz.sheenModel = ir::SheenModel::Zeltner;
    fuzz.origin = c.nodeOrigin(n);
    fuzz.slots.set(Slot::Color, clamped("fuzz_color", 0.0f, 1.0f));
    fuzz.slots.set(Slot::Roughness, clamped("fuzz_roughness", 0.0f, 1.0f));
    // The albedo under the fuzz, for the light it returns to the base (the fuzz's darkening, as
    // the coat's: the base substrate's estimate, ignoring the coat).
    fuzz.slots.set(Slot::BaseAlbedo, {darkeningBaseAlbedo(), at("fuzz_weight")});
    ExprId fuzzNormal = b.normalize(b.lerp(p("geometry_normal").value, p("geometry_coat_normal").value,
                                           clamped("coat_weight", 0.0f, 1.0f).value));
    fuzz.slots.set(Slot::Normal, {fuzzNormal, at("geometry_normal")});
    Index surface = c.material.slab(c.material.addInterface(std::move(fuzz)), ir::kNone, coated,
                                    clamped("fuzz_weight", 0.0f, 1.0f), at("fuzz_weight"));

    // M_PBR = mix(Slab(empty), M_surface, geometry_opacity) (OpenPBR "Opacity / Transparency").
    Param opacity = clamped("geometry_opacity", 0.0f, 1.0f);
    c.material.opacity = opacity;
    Index ambient = c.material.leaf(ir::ScatterKind::Ambient, at("geometry_opacity"));
    return c.material.mix(ambient, surface, opacity, at("geometry_opacity"));
  }
};

}  // namespace

Index lowerOpenPbrSurface(Context& c, const NodeRef& n) {
  OpenPbr model{{c, n, c.b}};
  return model.lower();
}

}  // namespace mxc::lower
