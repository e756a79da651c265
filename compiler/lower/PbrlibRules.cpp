// Lowering rules for the closure nodes of MaterialX pbrlib (MaterialX 1.39 "Physically Based
// Shading Nodes"): BSDF nodes become interfaces of slabs, VDF nodes media, EDF nodes
// emission; layer, mix, add and multiply build the scattering tree.

#include <unordered_map>

#include <fmt/format.h>

#include "compiler/lower/Context.h"
#include "compiler/lower/Layering.h"
#include "compiler/lower/Media.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Index;
using ir::Slot;
using ir::Type;

namespace {

bool constantFalse(Context& c, ExprId v) { return v == ir::kNoExpr || c.material.exprs.isConstantEqual(v, 0.0f); }

ir::Interface interfaceOf(Context& c, const NodeRef& n, ir::InterfaceKind kind) {
  ir::Interface i;
  i.kind = kind;
  i.origin = c.nodeOrigin(n);
  i.iorReference = ir::IorReference::Ambient;  // a pbrlib BSDF's IOR is relative to its outside
  return i;
}

void setSlot(Context& c, ir::Interface& i, Slot slot, const NodeRef& n, std::string_view input) {
  ir::Param p = c.param(n, input);
  if (p.present()) i.slots.set(slot, p);
}

void microfacet(Context& c, ir::Interface& i, const NodeRef& n) {
  setSlot(c, i, Slot::Alpha, n, "roughness");
  setSlot(c, i, Slot::Normal, n, "normal");
  setSlot(c, i, Slot::Tangent, n, "tangent");
  std::string distribution = c.stringInput(n, "distribution");
  if (!distribution.empty() && distribution != "ggx") {
    c.error(c.origin(n, "distribution").location,
            fmt::format("microfacet distribution '{}' is not supported (only ggx)", distribution));
  }
  // Thin film (MaterialX 1.39 thinfilm_thickness / thinfilm_ior; OpenPBR "Thin-film iridescence").
  ir::Param thickness = c.param(n, "thinfilm_thickness");
  if (thickness.present() && !c.material.exprs.isConstantEqual(thickness.value, 0.0f)) {
    i.thinFilm.thickness = thickness;
    i.thinFilm.ior = c.param(n, "thinfilm_ior");
    i.thinFilm.origin = thickness.origin;
  }
}

ir::ScatterMode scatterMode(Context& c, const NodeRef& n) {
  std::string mode = c.stringInput(n, "scatter_mode");
  if (mode == "T") return ir::ScatterMode::T;
  if (mode == "RT") return ir::ScatterMode::RT;
  return ir::ScatterMode::R;
}

Closure scatter(Index index) { return {Closure::Kind::Scatter, index, {}}; }

Closure dielectric(Context& c, const NodeRef& n, std::string_view) {
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::Dielectric);
  i.scatter = scatterMode(c, n);
  setSlot(c, i, Slot::Ior, n, "ior");
  // The tint applies to the lobes the node has: reflection, transmission, or both.
  if (i.scatter != ir::ScatterMode::T) setSlot(c, i, Slot::ReflectionTint, n, "tint");
  if (i.scatter != ir::ScatterMode::R) setSlot(c, i, Slot::TransmissionTint, n, "tint");
  microfacet(c, i, n);
  if (!constantFalse(c, c.input(n, "retroreflective"))) {
    c.error(c.origin(n, "retroreflective").location, "retroreflective dielectric_bsdf is not supported");
  }
  return scatter(interfaceSlab(c, std::move(i), c.param(n, "weight")));
}

Closure conductor(Context& c, const NodeRef& n, std::string_view) {
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::Conductor);
  i.scatter = ir::ScatterMode::R;
  setSlot(c, i, Slot::ComplexIor, n, "ior");
  setSlot(c, i, Slot::Extinction, n, "extinction");
  microfacet(c, i, n);
  return scatter(interfaceSlab(c, std::move(i), c.param(n, "weight")));
}

Closure generalizedSchlick(Context& c, const NodeRef& n, std::string_view) {
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::Schlick);
  i.scatter = scatterMode(c, n);
  setSlot(c, i, Slot::F0, n, "color0");
  setSlot(c, i, Slot::F82, n, "color82");
  setSlot(c, i, Slot::F90, n, "color90");
  setSlot(c, i, Slot::Exponent, n, "exponent");
  microfacet(c, i, n);
  return scatter(interfaceSlab(c, std::move(i), c.param(n, "weight")));
}

Closure orenNayar(Context& c, const NodeRef& n, std::string_view) {
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::Diffuse);
  setSlot(c, i, Slot::Color, n, "color");
  setSlot(c, i, Slot::Roughness, n, "roughness");
  setSlot(c, i, Slot::Normal, n, "normal");
  i.diffuseModel = constantFalse(c, c.input(n, "energy_compensation")) ? ir::DiffuseModel::OrenNayar
                                                                       : ir::DiffuseModel::EON;
  return scatter(interfaceSlab(c, std::move(i), c.param(n, "weight")));
}

Closure burley(Context& c, const NodeRef& n, std::string_view) {
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::Burley);
  setSlot(c, i, Slot::Color, n, "color");
  setSlot(c, i, Slot::Roughness, n, "roughness");
  setSlot(c, i, Slot::Normal, n, "normal");
  return scatter(interfaceSlab(c, std::move(i), c.param(n, "weight")));
}

Closure translucent(Context& c, const NodeRef& n, std::string_view) {
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::DiffuseTransmission);
  setSlot(c, i, Slot::Color, n, "color");
  setSlot(c, i, Slot::Normal, n, "normal");
  return scatter(interfaceSlab(c, std::move(i), c.param(n, "weight")));
}

Closure sheen(Context& c, const NodeRef& n, std::string_view) {
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::Sheen);
  setSlot(c, i, Slot::Color, n, "color");
  setSlot(c, i, Slot::Roughness, n, "roughness");
  setSlot(c, i, Slot::Normal, n, "normal");
  i.sheenModel = c.stringInput(n, "mode") == "zeltner" ? ir::SheenModel::Zeltner : ir::SheenModel::ContyKulla;
  return scatter(interfaceSlab(c, std::move(i), c.param(n, "weight")));
}

Closure chiangHair(Context& c, const NodeRef& n, std::string_view) {
  // A hair fibre (Chiang et al. 2016; MaterialX chiang_hair_bsdf): one lobe holding R, TT, TRT
  // and the longer paths (mxc_hair.glsl). Its IOR is the fibre's own; its tangent input is the
  // direction of the curve.
  ir::Interface i = interfaceOf(c, n, ir::InterfaceKind::Hair);
  setSlot(c, i, Slot::ReflectionTint, n, "tint_R");
  setSlot(c, i, Slot::TransmissionTint, n, "tint_TT");
  setSlot(c, i, Slot::InternalReflectionTint, n, "tint_TRT");
  setSlot(c, i, Slot::Ior, n, "ior");
  setSlot(c, i, Slot::FibreRoughnessR, n, "roughness_R");
  setSlot(c, i, Slot::FibreRoughnessTT, n, "roughness_TT");
  setSlot(c, i, Slot::FibreRoughnessTRT, n, "roughness_TRT");
  setSlot(c, i, Slot::Absorption, n, "absorption_coefficient");
  setSlot(c, i, Slot::Normal, n, "normal");
  setSlot(c, i, Slot::Tangent, n, "curve_direction");
  // MaterialX maps cuticle_angle in [0, 1] to a tilt in [-pi/2, pi/2]: 0.5 is no tilt.
  if (ir::Param angle = c.param(n, "cuticle_angle"); angle.present()) {
    angle.value = c.b.mul(c.b.sub(angle.value, c.b.f(0.5f)), c.b.f(3.14159265f));
    i.slots.set(Slot::CuticleTilt, angle);
  }
  return scatter(interfaceSlab(c, std::move(i), {}));
}

Closure subsurface(Context& c, const NodeRef& n, std::string_view) {
  // MaterialX's subsurface_bsdf is a medium (the seed commentary, 4.1): an index-matched slab
  // holding a bulk scattering medium; a dielectric layered over it becomes its interface.
  Index medium = subsurfaceMedium(c, c.param(n, "color"), c.param(n, "radius"), c.param(n, "anisotropy"),
                                  c.nodeOrigin(n));
  ir::Param weight = c.param(n, "weight");
  if (weight.present() && c.material.exprs.isConstantEqual(weight.value, 1.0f)) weight = {};
  return scatter(c.material.slab(ir::kNone, medium, ir::kNone, weight, c.nodeOrigin(n)));
}

Closure absorptionVdf(Context& c, const NodeRef& n, std::string_view) {
  ir::Medium m;
  m.extent = ir::Medium::Extent::Bulk;
  m.origin = c.nodeOrigin(n);
  m.slots.set(Slot::Absorption, c.param(n, "absorption"));
  return {Closure::Kind::Medium, c.material.addMedium(std::move(m)), {}};
}

Closure anisotropicVdf(Context& c, const NodeRef& n, std::string_view) {
  ir::Medium m;
  m.extent = ir::Medium::Extent::Bulk;
  m.origin = c.nodeOrigin(n);
  m.slots.set(Slot::Absorption, c.param(n, "absorption"));
  m.slots.set(Slot::Scattering, c.param(n, "scattering"));
  m.slots.set(Slot::Anisotropy, c.param(n, "anisotropy"));
  return {Closure::Kind::Medium, c.material.addMedium(std::move(m)), {}};
}

Closure uniformEdf(Context& c, const NodeRef& n, std::string_view) {
  ir::Emission e;
  e.kind = ir::Emission::Kind::Uniform;
  e.origin = c.nodeOrigin(n);
  e.slots.set(Slot::Color, c.param(n, "color"));
  return {Closure::Kind::Emission, ir::kNone, {c.material.addEmission(std::move(e))}};
}

Closure conicalEdf(Context& c, const NodeRef& n, std::string_view) {
  ir::Emission e;
  e.kind = ir::Emission::Kind::Conical;
  e.origin = c.nodeOrigin(n);
  e.slots.set(Slot::Color, c.param(n, "color"));
  e.slots.set(Slot::Normal, c.param(n, "normal"));
  e.slots.set(Slot::InnerAngle, c.param(n, "inner_angle"));
  e.slots.set(Slot::OuterAngle, c.param(n, "outer_angle"));
  return {Closure::Kind::Emission, ir::kNone, {c.material.addEmission(std::move(e))}};
}

/// Scales the colour of every emitter (a copy of each).
Closure scaleEmission(Context& c, const Closure& edf, ExprId factor, const ir::Origin& origin) {
  Closure out{Closure::Kind::Emission, ir::kNone, {}};
  for (Index i : edf.emissions) {
    ir::Emission e = c.material.emissions[i];
    ir::Param* color = e.slots.find(Slot::Color);
    if (color && color->present()) color->value = c.b.mul(color->value, factor);
    else e.slots.set(Slot::Color, {factor, origin});
    out.emissions.push_back(c.material.addEmission(std::move(e)));
  }
  return out;
}

Closure generalizedSchlickEdf(Context& c, const NodeRef& n, std::string_view) {
  // A directional Fresnel-like factor on the base emission: kept on each emitter for the
  // evaluator (lerp(color0, color90, (1 - cos)^exponent) per MaterialX's definition).
  Closure base = c.closureInput(n, "base");
  Closure out{Closure::Kind::Emission, ir::kNone, {}};
  for (Index i : base.emissions) {
    ir::Emission e = c.material.emissions[i];
    e.slots.set(Slot::F0, c.param(n, "color0"));
    e.slots.set(Slot::F90, c.param(n, "color90"));
    e.slots.set(Slot::Exponent, c.param(n, "exponent"));
    out.emissions.push_back(c.material.addEmission(std::move(e)));
  }
  return out;
}

Closure layer(Context& c, const NodeRef& n, std::string_view) {
  Closure top = c.closureInput(n, "top");
  Closure base = c.closureInput(n, "base");
  if (top.kind != Closure::Kind::Scatter) return base;  // an empty top leaves the base
  if (base.kind == Closure::Kind::Medium) return scatter(attachMedium(c, top.index, base.index, c.nodeOrigin(n)));
  if (base.kind != Closure::Kind::Scatter) return top;
  return scatter(attachBase(c, top.index, base.index, c.nodeOrigin(n)));
}

Closure mix(Context& c, const NodeRef& n, std::string_view) {
  Closure fg = c.closureInput(n, "fg");
  Closure bg = c.closureInput(n, "bg");
  ir::Param w = c.param(n, "mix");
  if (fg.kind == Closure::Kind::Emission || bg.kind == Closure::Kind::Emission) {
    Closure a = scaleEmission(c, bg, c.b.oneMinus(w.value), w.origin);
    Closure b = scaleEmission(c, fg, w.value, w.origin);
    a.emissions.insert(a.emissions.end(), b.emissions.begin(), b.emissions.end());
    return a;
  }
  if (fg.kind == Closure::Kind::Medium || bg.kind == Closure::Kind::Medium) {
    c.error(c.nodeOrigin(n).location, "mixing volumes (VDFs) is not supported: mix the BSDFs that contain them");
    return bg;
  }
  // mix(fg, bg, w) = (1 - w) bg + w fg: Mix{a: bg, b: fg, weight: w}; an empty side is black.
  Index a = bg.kind == Closure::Kind::Scatter ? bg.index : c.material.leaf(ir::ScatterKind::Absorber, c.nodeOrigin(n));
  Index b = fg.kind == Closure::Kind::Scatter ? fg.index : c.material.leaf(ir::ScatterKind::Absorber, c.nodeOrigin(n));
  return scatter(c.material.mix(a, b, w, c.nodeOrigin(n)));
}

Closure add(Context& c, const NodeRef& n, std::string_view) {
  Closure a = c.closureInput(n, "in1");
  Closure b = c.closureInput(n, "in2");
  if (a.kind == Closure::Kind::Emission || b.kind == Closure::Kind::Emission) {
    a.kind = Closure::Kind::Emission;
    a.emissions.insert(a.emissions.end(), b.emissions.begin(), b.emissions.end());
    return a;
  }
  if (a.kind != Closure::Kind::Scatter) return b;
  if (b.kind != Closure::Kind::Scatter) return a;
  c.note(c.nodeOrigin(n), "<add> of BSDFs is not energy-bounded: the sum's albedo can exceed 1");
  ir::ScatterNode node;
  node.kind = ir::ScatterKind::Add;
  node.a = a.index;
  node.b = b.index;
  node.origin = c.nodeOrigin(n);
  return scatter(c.material.addNode(std::move(node)));
}

Closure multiply(Context& c, const NodeRef& n, std::string_view) {
  Closure child = c.closureInput(n, "in1");
  ir::Param factor = c.param(n, "in2");
  if (child.kind == Closure::Kind::Emission) return scaleEmission(c, child, factor.value, factor.origin);
  if (child.kind == Closure::Kind::Medium) {
    ir::Medium m = c.material.media[child.index];
    for (auto& [slot, p] : m.slots.all()) {
      if (slot == Slot::Absorption || slot == Slot::Scattering) p.value = c.b.mul(p.value, factor.value);
    }
    return {Closure::Kind::Medium, c.material.addMedium(std::move(m)), {}};
  }
  if (child.kind != Closure::Kind::Scatter) return child;
  if (c.b.type(factor.value) == Type::Float) {
    // w f is a surface covered with f over a fraction w, black elsewhere: Mix(Absorber, f, w).
    // Bounded only for w in [0, 1]: a constant outside that range is noted.
    if (c.material.exprs.isConstant(factor.value)) {
      float w = c.material.exprs.constantComponents(factor.value)[0];
      if (w < 0.0f || w > 1.0f) c.note(factor.origin, fmt::format("a BSDF scaled by {} is not energy-bounded", w));
    }
    Index black = c.material.leaf(ir::ScatterKind::Absorber, c.nodeOrigin(n));
    return scatter(c.material.mix(black, child.index, factor, c.nodeOrigin(n)));
  }
  ir::ScatterNode node;
  node.kind = ir::ScatterKind::Tint;
  node.a = child.index;
  node.weight = factor;
  node.origin = c.nodeOrigin(n);
  return scatter(c.material.addNode(std::move(node)));
}

Closure surface(Context& c, const NodeRef& n, std::string_view) {
  Closure bsdf = c.closureInput(n, "bsdf");
  Closure edf = c.closureInput(n, "edf");
  Index root = bsdf.kind == Closure::Kind::Scatter ? bsdf.index : c.material.leaf(ir::ScatterKind::Absorber, c.nodeOrigin(n));
  // MaterialX's surface emits above the whole BSDF: the emission is at the top.
  for (Index e : edf.emissions) {
    ir::ScatterNode node;
    node.kind = ir::ScatterKind::Emissive;
    node.a = root;
    node.emission = e;
    node.origin = c.nodeOrigin(n);
    root = c.material.addNode(std::move(node));
  }
  ir::Param opacity = c.param(n, "opacity");
  if (opacity.present() && !c.material.exprs.isConstantEqual(opacity.value, 1.0f)) {
    c.material.opacity = opacity;
    root = c.material.mix(c.material.leaf(ir::ScatterKind::Ambient, c.nodeOrigin(n)), root, opacity, c.nodeOrigin(n));
  }
  return scatter(root);
}

Closure surfaceUnlit(Context& c, const NodeRef& n, std::string_view) {
  // Emission plus straight-through transmission (MaterialX "surface_unlit").
  ir::Param transmission = c.param(n, "transmission");
  ir::ScatterNode tint;
  tint.kind = ir::ScatterKind::Tint;
  tint.a = c.material.leaf(ir::ScatterKind::Ambient, c.nodeOrigin(n));
  tint.weight = c.param(n, "transmission_color");
  tint.origin = c.nodeOrigin(n);
  Index passing = c.material.addNode(std::move(tint));
  Index root = c.material.mix(c.material.leaf(ir::ScatterKind::Absorber, c.nodeOrigin(n)), passing, transmission,
                              c.nodeOrigin(n));
  ir::Emission e;
  e.origin = c.nodeOrigin(n);
  e.slots.set(Slot::Color, {c.b.mul(c.input(n, "emission_color"), c.input(n, "emission")), c.origin(n, "emission")});
  ir::ScatterNode emissive;
  emissive.kind = ir::ScatterKind::Emissive;
  emissive.a = root;
  emissive.emission = c.material.addEmission(std::move(e));
  emissive.origin = c.nodeOrigin(n);
  root = c.material.addNode(std::move(emissive));
  ir::Param opacity = c.param(n, "opacity");
  if (opacity.present() && !c.material.exprs.isConstantEqual(opacity.value, 1.0f)) {
    root = c.material.mix(c.material.leaf(ir::ScatterKind::Ambient, c.nodeOrigin(n)), root, opacity, c.nodeOrigin(n));
  }
  return scatter(root);
}

Closure shadingModel(Context& c, const NodeRef& n, std::string_view output) {
  // mxc's own lowering of the shading models, unless the user asked for their node graphs.
  const std::string_view category = n.node->category();
  if (c.options.useShadingModelGraphs) {
    if (category == "open_pbr_surface" || category == "standard_surface") {
      c.material.thinWalled = c.param(n, category == "open_pbr_surface" ? "geometry_thin_walled" : "thin_walled");
    }
    if (Env* inner = c.inlineImplementation(n)) {
      if (const resolve::ResolvedInput* out = c.implementationOutput(*inner, output)) return c.closure(*out, *inner);
    }
  }
  if (category == "open_pbr_surface") return scatter(lowerOpenPbrSurface(c, n));
  if (category == "UsdPreviewSurface") return scatter(lowerUsdPreviewSurface(c, n));
  if (category == "gltf_pbr") return scatter(lowerGltfPbr(c, n));
  if (category == "disney_principled") return scatter(lowerDisneyPrincipled(c, n));
  return scatter(lowerStandardSurface(c, n));
}

using RuleTable = std::unordered_map<std::string_view, ClosureRule>;

const RuleTable& rules() {
  static const RuleTable table = {
      {"dielectric_bsdf", dielectric},
      {"conductor_bsdf", conductor},
      {"generalized_schlick_bsdf", generalizedSchlick},
      {"oren_nayar_diffuse_bsdf", orenNayar},
      {"burley_diffuse_bsdf", burley},
      {"translucent_bsdf", translucent},
      {"sheen_bsdf", sheen},
      {"chiang_hair_bsdf", chiangHair},
      {"subsurface_bsdf", subsurface},
      {"absorption_vdf", absorptionVdf},
      {"anisotropic_vdf", anisotropicVdf},
      {"uniform_edf", uniformEdf},
      {"conical_edf", conicalEdf},
      {"generalized_schlick_edf", generalizedSchlickEdf},
      {"layer", layer},
      {"mix", mix},
      {"add", add},
      {"multiply", multiply},
      {"surface", surface},
      {"surface_unlit", surfaceUnlit},
      {"open_pbr_surface", shadingModel},
      {"standard_surface", shadingModel},
      {"UsdPreviewSurface", shadingModel},
      {"gltf_pbr", shadingModel},
      {"disney_principled", shadingModel},
  };
  return table;
}

}  // namespace

ClosureRule findClosureRule(std::string_view category) {
  auto it = rules().find(category);
  return it == rules().end() ? nullptr : it->second;
}

}  // namespace mxc::lower
