#include "compiler/ir/Scatter.h"

#include "compiler/ir/Material.h"

namespace mxc::ir {

std::string_view slotName(Slot slot) {
  static constexpr std::string_view names[] = {
      "ior",        "fresnel_scale", "reflection_tint", "transmission_tint", "alpha",      "normal",
      "tangent",    "color",         "roughness",       "f0",                "f82",        "f90",
      "exponent",   "extinction",    "complex_ior",     "anisotropy",        "absorption", "scattering",
      "thickness",  "observed_albedo", "abbe_number",   "darkening",         "base_albedo",
      "base_roughness", "base_ior", "weight",   "luminance",       "inner_angle",       "outer_angle",
      "internal_reflection_tint", "fibre_roughness_r", "fibre_roughness_tt", "fibre_roughness_trt", "cuticle_tilt"};
  static_assert(sizeof(names) / sizeof(names[0]) == static_cast<size_t>(Slot::Count), "every slot has a name");
  return names[static_cast<size_t>(slot)];
}

std::optional<float> slotDefault(Slot slot) {
  switch (slot) {
    case Slot::FresnelScale:
    case Slot::ReflectionTint:
    case Slot::TransmissionTint:
    case Slot::InternalReflectionTint:
    case Slot::Weight:
    case Slot::F82:
    case Slot::F90: return 1.0f;
    case Slot::AbbeNumber:
    case Slot::Absorption:
    case Slot::Scattering:
    case Slot::Anisotropy:
    case Slot::CuticleTilt: return 0.0f;
    case Slot::Exponent: return 5.0f;
    default: return std::nullopt;
  }
}

std::string_view interfaceKindName(InterfaceKind kind) {
  switch (kind) {
    case InterfaceKind::Dielectric: return "dielectric";
    case InterfaceKind::Conductor: return "conductor";
    case InterfaceKind::Schlick: return "schlick";
    case InterfaceKind::Diffuse: return "diffuse";
    case InterfaceKind::Burley: return "burley_diffuse";
    case InterfaceKind::DiffuseTransmission: return "diffuse_transmission";
    case InterfaceKind::DiffuseSheet: return "diffuse_sheet";
    case InterfaceKind::Sheen: return "sheen";
    case InterfaceKind::Hair: return "hair";
  }
  return "?";
}

std::string_view extentName(Medium::Extent extent) {
  switch (extent) {
    case Medium::Extent::Bulk: return "bulk";
    case Medium::Extent::Finite: return "finite";
    case Medium::Extent::ThinWall: return "thin_wall";
  }
  return "?";
}

std::string_view scatterKindName(ScatterKind kind) {
  switch (kind) {
    case ScatterKind::Slab: return "slab";
    case ScatterKind::Mix: return "mix";
    case ScatterKind::Add: return "add";
    case ScatterKind::Tint: return "tint";
    case ScatterKind::Emissive: return "emissive";
    case ScatterKind::Ambient: return "ambient";
    case ScatterKind::Absorber: return "absorber";
  }
  return "?";
}

void Slots::set(Slot slot, Param param) {
  if (Param* p = find(slot)) {
    *p = param;
    return;
  }
  items_.emplace_back(slot, param);
}

const Param* Slots::find(Slot slot) const {
  for (const auto& [s, p] : items_) {
    if (s == slot) return &p;
  }
  return nullptr;
}

Param* Slots::find(Slot slot) {
  for (auto& [s, p] : items_) {
    if (s == slot) return &p;
  }
  return nullptr;
}

void Slots::erase(Slot slot) {
  std::erase_if(items_, [&](const auto& item) { return item.first == slot; });
}

Index Material::slab(Index top, Index medium, Index base, Param coverage, Origin from) {
  ScatterNode n;
  n.kind = ScatterKind::Slab;
  n.top = top;
  n.medium = medium;
  n.base = base;
  n.coverage = coverage;
  n.origin = from;
  return addNode(std::move(n));
}

Index Material::mix(Index a, Index b, Param weight, Origin from) {
  ScatterNode n;
  n.kind = ScatterKind::Mix;
  n.a = a;
  n.b = b;
  n.weight = weight;
  n.origin = from;
  return addNode(std::move(n));
}

Index Material::leaf(ScatterKind kind, Origin from) {
  ScatterNode n;
  n.kind = kind;
  n.origin = from;
  return addNode(std::move(n));
}

}  // namespace mxc::ir
