// standard_surface to the slab IR, following the Autodesk Standard Surface specification
// (version 1.0.1), "Closures": the closure tree
//
//   standard_surface          = mix(transparency, coat_layer, opacity)
//   coat_layer                = layer(emission_specular_mixture, coat_brdf, coat)   (coat_color absorbs)
//   emission_specular_mixture = emission (under the coat) + specular_mixture
//   specular_mixture          = mix(specular_reflection_layer, metal_brdf, metalness)
//   specular_reflection_layer = layer(transmission_sheen_mix, specular_brdf, specular)
//   transmission_sheen_mix    = mix(sheen_layer, specular_btdf, transmission)
//   sheen_layer               = layer(base_mix, sheen_brdf, sheen)
//   base_mix                  = mix(diffuse_brdf, subsurface_mix, subsurface)
//
// where layer(base, top, w) is a slab of `top` with coverage w. The reflection and
// transmission of the specular dielectric are one interface (the seed commentary, 4.1); the
// transmissive part gets its own interface when transmission_extra_roughness roughens it.

#include <fmt/format.h>

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

struct StandardSurface : ShadingModelInputs {
  /// The coat's effect on the colours under it (Standard Surface "Coating"): colours are
  /// raised to the power 1 + coat_affect_color * coat. The colours are albedos (base_color,
  /// subsurface_color: what the lobe reflects or transmits), at most 1 so that no lobe creates
  /// energy; coat and coat_affect_color are weights in [0, 1], so the power is in [1, 2] and pow
  /// of a base in [0, 1] is defined.
  ExprId coatAffected(std::string_view color) {
    ExprId gamma = b.add(b.f(1.0f), b.mul(clamped01("coat_affect_color").value, clamped01("coat").value));
    return b.pow(clamped01(color).value, gamma);
  }

  /// Roughness under the coat: lerp(r, 1, coat * coat_affect_roughness * coat_roughness).
  ExprId coatAffectedRoughness(ExprId roughness) {
    ExprId t = b.mul(b.mul(p("coat").value, p("coat_affect_roughness").value), p("coat_roughness").value);
    return b.lerp(roughness, b.f(1.0f), b.clamp01(t));
  }

  /// A tangent rotated by rotation * 360 degrees about the normal (the spec's *_rotation), when
  /// anisotropy is used; otherwise the tangent as given.
  ExprId rotatedTangent(std::string_view tangent, std::string_view rotation, std::string_view normal) {
    Param angle = p(rotation);
    if (isConstant(angle, 0.0f)) return p(tangent).value;
    ExprId degrees = b.mul(angle.value, b.f(360.0f));
    return b.normalize(c.material.exprs.op(ir::Op::Rotate3D, Type::Vec3, {p(tangent).value, degrees, p(normal).value}));
  }

  Index dielectric(ExprId roughness, std::string_view origin) {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Dielectric;
    i.scatter = ir::ScatterMode::RT;
    i.origin = c.nodeOrigin(n);
    // Standard Surface "Layering": the specular BRDF's Fresnel uses specular_IOR as given, the
    // coat only weighting it by (1 - coat reflectance); unlike OpenPBR, whose eq.
    // specular_ior_ratio makes the IOR relative to the coat (index-matched when equal).
    i.iorReference = ir::IorReference::Ambient;
    i.slots.set(Slot::Ior, p("specular_IOR"));
    i.slots.set(Slot::ReflectionTint, clamped("specular_color", 0.0f, 1.0f));
    // transm_color = transmission_color when transmission_depth == 0, else the medium absorbs.
    Param depth = nonNegative("transmission_depth");
    Param tint = clamped("transmission_color", 0.0f, 1.0f);
    tint.value = b.select(b.greater(depth.value, b.f(0.0f)), b.vec(Type::Vec3, 1.0f), tint.value);
    i.slots.set(Slot::TransmissionTint, tint);
    const bool anisotropic = !isConstant(p("specular_anisotropy"), 0.0f);
    i.slots.set(Slot::Alpha, {burleyAlpha(b, roughness, p("specular_anisotropy").value),
                              anisotropic ? at("specular_anisotropy") : at(origin)});
    i.slots.set(Slot::Normal, p("normal"));
    i.slots.set(Slot::Tangent, {rotatedTangent("tangent", "specular_rotation", "normal"), at("tangent")});
    Param thickness = nonNegative("thin_film_thickness");
    if (!isConstant(thickness, 0.0f)) {
      i.thinFilm.thickness = thickness;
      i.thinFilm.ior = p("thin_film_IOR");
      i.thinFilm.origin = thickness.origin;
    }
    return c.material.addInterface(std::move(i));
  }

  Index lowerBase(bool thinWalled) {
    ExprId roughness = coatAffectedRoughness(p("specular_roughness").value);

    // base_mix = mix(diffuse_brdf, subsurface_mix, subsurface)
    ir::Interface diffuse;
    diffuse.kind = ir::InterfaceKind::Diffuse;
    diffuse.diffuseModel = ir::DiffuseModel::OrenNayar;
    diffuse.origin = c.nodeOrigin(n);
    // base * base_color * diffuse_brdf: `base` weights the lobe (the slab's coverage).
    diffuse.slots.set(Slot::Color, {coatAffected("base_color"), at("base_color")});
    diffuse.slots.set(Slot::Roughness, clamped("diffuse_roughness", 0.0f, 1.0f));
    diffuse.slots.set(Slot::Normal, p("normal"));
    Index diffuseSlab = c.material.slab(c.material.addInterface(std::move(diffuse)), ir::kNone, ir::kNone,
                                        clamped("base", 0.0f, 1.0f), at("base"));
    Index subsurfaceSlab;
    if (thinWalled) {
      ir::Interface translucent;
      translucent.kind = ir::InterfaceKind::DiffuseTransmission;
      translucent.origin = c.nodeOrigin(n);
      translucent.slots.set(Slot::Color, {coatAffected("subsurface_color"), at("subsurface_color")});
      translucent.slots.set(Slot::Normal, p("normal"));
      subsurfaceSlab = c.material.slab(c.material.addInterface(std::move(translucent)), ir::kNone, ir::kNone, {},
                                       at("subsurface"));
    } else {
      Param color{coatAffected("subsurface_color"), at("subsurface_color")};
      Param mfp{b.mul(b.nonNegative(p("subsurface_radius").value), nonNegative("subsurface_scale").value),
                at("subsurface_radius")};
      Index medium = subsurfaceMedium(c, color, mfp, p("subsurface_anisotropy"), at("subsurface"));
      subsurfaceSlab = c.material.slab(ir::kNone, medium, ir::kNone, {}, at("subsurface"));
    }
    Index baseMix = c.material.mix(diffuseSlab, subsurfaceSlab, clamped("subsurface", 0.0f, 1.0f), at("subsurface"));

    // sheen_layer: sheen over base_mix, coverage sheen (Estevez & Kulla 2017 sheen).
    ir::Interface sheen;
    sheen.kind = ir::InterfaceKind::Sheen;
    sheen.sheenModel = ir::SheenModel::ContyKulla;
    sheen.origin = c.nodeOrigin(n);
    sheen.slots.set(Slot::Color, clamped("sheen_color", 0.0f, 1.0f));
    sheen.slots.set(Slot::Roughness, clamped("sheen_roughness", 0.0f, 1.0f));
    sheen.slots.set(Slot::Normal, p("normal"));
    Index sheenLayer = c.material.slab(c.material.addInterface(std::move(sheen)), ir::kNone, baseMix,
                                       clamped("sheen", 0.0f, 1.0f), at("sheen"));

    // specular_reflection_layer: the specular dielectric over the rest, coverage `specular`.
    Index specularTop = dielectric(roughness, "specular_roughness");
    Index opaque = c.material.slab(specularTop, ir::kNone, sheenLayer, clamped("specular", 0.0f, 1.0f), at("specular"));

    // The transmissive part: the same dielectric, roughened by transmission_extra_roughness.
    Param extra = p("transmission_extra_roughness");
    Index transmissiveTop = specularTop;
    if (!isConstant(extra, 0.0f)) {
      ExprId rough = coatAffectedRoughness(b.clamp01(b.add(p("specular_roughness").value, extra.value)));
      transmissiveTop = dielectric(rough, "transmission_extra_roughness");
    }
    Index medium;
    if (thinWalled) {
      ir::Medium sheet;
      sheet.extent = ir::Medium::Extent::ThinWall;
      sheet.origin = at("transmission");
      medium = c.material.addMedium(std::move(sheet));
    } else {
      // transmission_dispersion is the Abbe number (0: none).
      Param dispersion = nonNegative("transmission_dispersion");
      if (isConstant(p("transmission_dispersion"), 0.0f)) dispersion = {};
      medium = transmissionMedium(c, clamped("transmission_color", 0.0f, 1.0f), nonNegative("transmission_depth"),
                                  p("transmission_scatter"), p("transmission_scatter_anisotropy"), p("specular_IOR"),
                                  dispersion, at("transmission"));
    }
    Index transmissive = c.material.slab(transmissiveTop, medium, ir::kNone, {}, at("transmission"));
    Index specularMix = c.material.mix(opaque, transmissive, clamped("transmission", 0.0f, 1.0f), at("transmission"));

    // metal_brdf: a conductor whose complex IOR comes from base * base_color and
    // specular * specular_color (Gulbrandsen 2014).
    ir::Interface metal;
    metal.kind = ir::InterfaceKind::Conductor;
    metal.scatter = ir::ScatterMode::R;
    metal.origin = c.nodeOrigin(n);
    ExprId reflectivity = b.mul(clamped("base_color", 0.0f, 1.0f).value, clamped("base", 0.0f, 1.0f).value);
    // Clamped: Gulbrandsen's edge tint g moves n from (1 + sqrt r) / (1 - sqrt r) at g = 0 to
    // (1 - r) / (1 + r) at g = 1 (Microfacet.cpp, gulbrandsenIor); past 1 it would extrapolate n
    // below that, towards a negative IOR.
    ExprId edge = b.mul(clamped("specular_color", 0.0f, 1.0f).value, clamped("specular", 0.0f, 1.0f).value);
    auto [ior, extinction] = gulbrandsenIor(b, reflectivity, edge);
    metal.slots.set(Slot::ComplexIor, {ior, at("base_color")});
    metal.slots.set(Slot::Extinction, {extinction, at("specular_color")});
    metal.slots.set(Slot::Alpha, {burleyAlpha(b, roughness, p("specular_anisotropy").value), at("specular_roughness")});
    metal.slots.set(Slot::Normal, p("normal"));
    metal.slots.set(Slot::Tangent, {rotatedTangent("tangent", "specular_rotation", "normal"), at("tangent")});
    Param thickness = nonNegative("thin_film_thickness");
    if (!isConstant(thickness, 0.0f)) {
      metal.thinFilm.thickness = thickness;
      metal.thinFilm.ior = p("thin_film_IOR");
      metal.thinFilm.origin = thickness.origin;
    }
    Index metalSlab = c.material.slab(c.material.addInterface(std::move(metal)), ir::kNone, ir::kNone, {}, at("metalness"));
    return c.material.mix(specularMix, metalSlab, clamped("metalness", 0.0f, 1.0f), at("metalness"));
  }

  Index lower() {
    Param thin = p("thin_walled");
    c.material.thinWalled = thin;
    Index base;
    if (isConstant(thin, 0.0f)) {
      base = lowerBase(false);
    } else if (isConstant(thin, 1.0f)) {
      base = lowerBase(true);
    } else {
      Param w{c.material.exprs.op(ir::Op::Construct, Type::Float, {thin.value}), thin.origin};
      base = c.material.mix(lowerBase(false), lowerBase(true), w, thin.origin);
    }

    // Emission sits under the coat (Standard Surface "Emission").
    ir::Emission e;
    e.kind = ir::Emission::Kind::Uniform;
    e.origin = at("emission");
    e.slots.set(Slot::Color, {b.mul(nonNegative("emission_color").value, nonNegative("emission").value), at("emission")});
    ir::ScatterNode emissive;
    emissive.kind = ir::ScatterKind::Emissive;
    emissive.a = base;
    emissive.emission = c.material.addEmission(std::move(e));
    emissive.origin = at("emission");
    Index emitting = c.material.addNode(std::move(emissive));

    // coat_layer: the coat dielectric with coat_color absorption, coverage `coat`.
    ir::Interface coat;
    coat.kind = ir::InterfaceKind::Dielectric;
    coat.scatter = ir::ScatterMode::RT;
    coat.origin = c.nodeOrigin(n);
    coat.slots.set(Slot::Ior, p("coat_IOR"));
    coat.slots.set(Slot::Alpha, {burleyAlpha(b, p("coat_roughness").value, p("coat_anisotropy").value), at("coat_roughness")});
    coat.slots.set(Slot::Normal, p("coat_normal"));
    coat.slots.set(Slot::Tangent, {rotatedTangent("tangent", "coat_rotation", "coat_normal"), at("tangent")});
    Index medium = coatMedium(c, clamped("coat_color", 0.0f, 1.0f), at("coat_color"));
    Index coated = c.material.slab(c.material.addInterface(std::move(coat)), medium, emitting, clamped("coat", 0.0f, 1.0f),
                                   at("coat"));

    // standard_surface = mix(transparency, coat_layer, opacity); opacity is a colour.
    Param opacity = clamped("opacity", 0.0f, 1.0f);
    c.material.opacity = opacity;
    return c.material.mix(c.material.leaf(ir::ScatterKind::Ambient, at("opacity")), coated, opacity, at("opacity"));
  }
};

}  // namespace

Index lowerStandardSurface(Context& c, const NodeRef& n) {
  StandardSurface model{{c, n, c.b}};
  return model.lower();
}

}  // namespace mxc::lower
