#include "compiler/glsl/LobeMapping.h"

#include <stdexcept>

#include <fmt/format.h>

#include "compiler/glsl/Contract.h"

namespace mxc::glsl {

using ir::InterfaceKind;
using ir::Slot;

LobeFields::LobeFields() {
  for (const Member& m : lobeMembers()) values_.emplace_back(m.name, std::string(m.initial));
}

void LobeFields::set(std::string_view member, std::string value) {
  for (auto& [name, v] : values_) {
    if (name == member) {
      v = std::move(value);
      return;
    }
  }
  throw std::logic_error(fmt::format("MxcLobe has no member '{}'", member));  // the contract and the back end disagree
}

std::string unitNormal(const ClosureValues& values, const ir::Material& m, const ir::Param* normal) {
  if (!normal || !normal->present()) return "g.N";
  const std::string value = values.glsl(normal->value);
  const ir::Expr& e = m.exprs[normal->value];
  if (e.op == ir::Op::GeomProp && m.exprs.text(normal->value) == "Nworld") return value;  // unit already
  return fmt::format("mxc_safe_normalize({}, g.N)", value);
}

LobeFields mapInterface(ClosureValues& v, const ir::Material& m, const ir::Interface& f, const Above& above, int mode,
                        ClosureValues::Id weight) {
  // A slot's GLSL, or the fallback the library reads as "absent".
  auto slot = [&](Slot s, const std::string& fallback) {
    const ir::Param* p = f.slots.find(s);
    return p && p->present() ? v.glsl(p->value) : fallback;
  };
  LobeFields fields;
  fields.set("kind", fmt::format("MXC_LOBE_{}", ir::lobeKindName(ir::lobeKindOf(f))));
  fields.set("mode", std::to_string(mode));
  fields.set("N", unitNormal(v, m, f.slots.find(Slot::Normal)));
  fields.set("T", slot(Slot::Tangent, "g.T"));
  fields.set("alpha", slot(Slot::Alpha, "vec2(0.0)"));
  fields.set("tau", v.glsl(above.tau));
  // IORs are kept >= 1e-3 wherever they divide or are divided by.
  const ClosureValues::Id floor = v.constant(1e-3f);
  fields.set("tauEta", v.glsl(v.max(above.tauEta, floor)));
  switch (f.kind) {
    case InterfaceKind::Dielectric: {
      fields.set("c0", slot(Slot::ReflectionTint, "vec3(1.0)"));
      fields.set("c1", slot(Slot::TransmissionTint, "vec3(1.0)"));
      // The IOR ratio across the interface. For an absolute IOR under a coat of coverage C,
      // OpenPBR eq. specular_ior_ratio: lerp(n_b / n_a, n_b / n_c, C), with the TIR fix of eq.
      // specular_ior_ratio_with_tir_fix (n_c / n_b when the coat is denser).
      const ClosureValues::Id nb = v.max(v.slot(f.slots, Slot::Ior, v.constant(1.5f)), floor);
      ClosureValues::Id eta = nb;
      if (f.iorReference == ir::IorReference::MediumAbove && !v.isZero(above.coatCoverage)) {
        eta = v.mix(nb, v.iorRatio(nb, v.max(above.coatIor, floor)), above.coatCoverage);
        // The view reaches the base refracted by the coat (OpenPBR eq. refracted_coat_dir);
        // mixed to 1 by the coverage like the ratio, exact at 0 and 1.
        fields.set("etaAbove", v.glsl(v.mix(v.constant(1.0f), v.max(above.coatIor, floor), above.coatCoverage)));
      }
      std::string etaGlsl = v.glsl(eta);
      // OpenPBR eq. modulated_ior: specular_weight scales F0, a library function of eta.
      if (const ir::Param* xi = f.slots.find(Slot::FresnelScale); xi && xi->present()) {
        etaGlsl = fmt::format("mxc_modulated_eta({}, {})", etaGlsl, v.glsl(xi->value));
      }
      fields.set("eta", etaGlsl);
      break;
    }
    case InterfaceKind::Conductor:
      fields.set("c0", slot(Slot::ComplexIor, "vec3(1.0)"));
      fields.set("c1", slot(Slot::Extinction, "vec3(0.0)"));
      break;
    case InterfaceKind::Schlick:
      fields.set("c0", slot(Slot::F0, "vec3(1.0)"));
      fields.set("c1", slot(Slot::F82, "vec3(1.0)"));
      fields.set("c2", slot(Slot::F90, "vec3(1.0)"));
      fields.set("p0", slot(Slot::Exponent, "5.0"));
      fields.set("p1", slot(Slot::FresnelScale, "1.0"));
      break;
    case InterfaceKind::Diffuse:
    case InterfaceKind::Burley:
    case InterfaceKind::Sheen:
      fields.set("c0", slot(Slot::Color, "vec3(1.0)"));
      fields.set("p0", slot(Slot::Roughness, "0.0"));
      break;
    case InterfaceKind::DiffuseTransmission: fields.set("c0", slot(Slot::Color, "vec3(1.0)")); break;
    case InterfaceKind::DiffuseSheet:
      fields.set("c0", slot(Slot::Color, "vec3(1.0)"));
      fields.set("p0", slot(Slot::Anisotropy, "0.0"));
      break;
    case InterfaceKind::Hair: {
      // mxc_hair.glsl: tints of R, TT and TRT; the IOR of the fibre (not relative to a layer:
      // a fibre is not layered); the lobes' roughness pairs; the cuticle tilt; sigma_a.
      fields.set("c0", slot(Slot::ReflectionTint, "vec3(1.0)"));
      fields.set("c1", slot(Slot::TransmissionTint, "vec3(1.0)"));
      fields.set("c2", slot(Slot::InternalReflectionTint, "vec3(1.0)"));
      fields.set("c3", slot(Slot::Absorption, "vec3(0.0)"));
      fields.set("eta", slot(Slot::Ior, "1.55"));
      fields.set("alpha", slot(Slot::FibreRoughnessR, "vec2(0.1)"));
      fields.set("q", fmt::format("vec4({}, {})", slot(Slot::FibreRoughnessTT, "vec2(0.05)"),
                                  slot(Slot::FibreRoughnessTRT, "vec2(0.2)")));
      fields.set("p0", slot(Slot::CuticleTilt, "0.0"));
      break;
    }
  }
  if (f.thinFilm.present()) {
    // OpenPBR "Thin-film iridescence": the film's IOR relative to what is above it (the coat
    // where present).
    const ClosureValues::Id aboveIor = v.mix(v.constant(1.0f), v.max(above.coatIor, floor), above.coatCoverage);
    const ClosureValues::Id filmIor = v.param(f.thinFilm.ior, v.constant(1.5f));
    fields.set("film", v.glsl(v.construct3(v.param(f.thinFilm.thickness, v.constant(0.0f)), v.div(filmIor, aboveIor),
                                           v.param(f.thinFilm.coverage, v.constant(1.0f)))));
  }
  fields.set("weight", v.glsl(lobeWeight(v, f, weight)));
  return fields;
}

ClosureValues::Id lobeWeight(ClosureValues& v, const ir::Interface& f, ClosureValues::Id weight) {
  if (const ir::Param* scale = f.slots.find(Slot::Weight); scale && scale->present()) return v.mul(weight, scale->value);
  return weight;
}

std::string emittedRadiance(ClosureValues& v, const ir::Emission& e, ClosureValues::Id weight) {
  const ClosureValues::Id color = v.slot(e.slots, Slot::Color, v.vec3(0.0f));
  ClosureValues::Id shape = v.constant(1.0f);
  if (e.kind == ir::Emission::Kind::Conical) {
    // Inside the cone of half-angle `inner` (degrees) fully, fading to `outer` (MaterialX
    // conical_edf; its defaults 60 and 0: a hard edge).
    const ir::Param* normal = e.slots.find(Slot::Normal);
    shape = v.local(fmt::format("mxc_cone_falloff(dot({}, wo), {}, {})", normal ? v.glsl(normal->value) : "g.N",
                                v.glsl(v.slot(e.slots, Slot::InnerAngle, v.constant(60.0f))),
                                v.glsl(v.slot(e.slots, Slot::OuterAngle, v.constant(0.0f)))),
                    ir::Type::Float);
  }
  std::string directional;
  if (const ir::Param* f0 = e.slots.find(Slot::F0)) {
    // MaterialX generalized_schlick_edf: lerp(color0, color90, (1 - cos)^exponent).
    directional = fmt::format(" * mxc_fresnel_schlick(clamp(dot(g.N, wo), 0.0, 1.0), {}, {}, {})", v.glsl(f0->value),
                              v.glsl(v.slot(e.slots, Slot::F90, v.vec3(1.0f))),
                              v.glsl(v.slot(e.slots, Slot::Exponent, v.constant(5.0f))));
  }
  return v.glsl(v.mul(v.mul(weight, color), shape)) + directional;
}

void declareLobe(Lines& out, const std::string& name, const LobeFields& fields, SourceLocation at, SourceLocation filmAt,
                 std::string_view skip) {
  out.add(fmt::format("  MxcLobe {};", name), at);
  const std::span<const Member> members = lobeMembers();  // the order of fields.values()
  std::string kind;
  for (const auto& [member, value] : fields.values()) {
    if (member == "kind") kind = value;
  }
  for (size_t i = 0; i < fields.values().size(); ++i) {
    const auto& [member, value] = fields.values()[i];
    if (member == skip) continue;
    // A member of one lobe kind only (Member::onlyFor) exists only in shaders with that kind.
    if (!members[i].onlyFor.empty() && kind != fmt::format("MXC_LOBE_{}", members[i].onlyFor)) continue;
    out.add(fmt::format("  {}.{} = {};", name, member, value), member == "film" && filmAt.valid() ? filmAt : at);
  }
}

void writeLobe(Lines& out, const std::string& name, int index, const LobeFields& fields, SourceLocation at,
               SourceLocation filmAt) {
  declareLobe(out, name, fields, at, filmAt);
  out.add(fmt::format("  c.lobes[{}] = {};", index, name), at);
}

}  // namespace mxc::glsl
