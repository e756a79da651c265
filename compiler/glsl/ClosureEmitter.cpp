#include "compiler/glsl/ClosureEmitter.h"

#include <stdexcept>

#include <fmt/format.h>

#include "compiler/glsl/Contract.h"

namespace mxc::glsl {

using ir::Index;
using ir::InterfaceKind;
using ir::ScatterKind;
using ir::Slot;

namespace {

/// The value of a GLSL float literal as glslFloat writes it ("1.0", "0.5", "1e-07"); false for
/// anything else.
bool literal(const std::string& text, float& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  value = std::strtof(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

bool isOne(const std::string& s) { return s == "1.0" || s == "vec3(1.0)"; }
bool isZero(const std::string& s) { return s == "0.0" || s == "vec3(0.0)"; }

/// `x` as a vec3 expression (vec3(x) of a float broadcasts; of a vec3 it is the same vector).
std::string asVec3(const std::string& x) {
  return x.rfind("vec3(", 0) == 0 || x.rfind("(vec3(", 0) == 0 ? x : fmt::format("vec3({})", x);
}

/// a * b, without multiplications by one. A vec3 one keeps the product a vec3.
std::string product(const std::string& a, const std::string& b) {
  if (a == "1.0") return b;
  if (b == "1.0") return a;
  if (a == "vec3(1.0)") return asVec3(b);
  if (b == "vec3(1.0)") return asVec3(a);
  return fmt::format("({} * {})", a, b);
}

/// max(x, lo) for an IOR, folded when x is a literal.
std::string atLeast(const std::string& x, float lo) {
  float v = 0.0f;
  if (literal(x, v)) return glslFloat(std::max(v, lo));
  return fmt::format("max({}, {})", x, glslFloat(lo));
}

/// mix(a, b, t), folded for t = 0 and t = 1.
std::string blend(const std::string& a, const std::string& b, const std::string& t) {
  if (isZero(t)) return a;
  if (isOne(t)) return b;
  return fmt::format("mix({}, {}, {})", a, b, t);
}

/// The ratio of two IORs as seen from the lighter side, folded for literals.
std::string iorRatio(const std::string& below, const std::string& above) {
  float b = 0.0f, a = 0.0f;
  if (literal(below, b) && literal(above, a)) return glslFloat(a > b ? a / b : b / a);  // both >= 1e-3
  return fmt::format("({1} > {0} ? {1} / {0} : {0} / {1})", below, above);
}

}  // namespace

/// The members of one MxcLobe with the GLSL of their values: each starts at the contract's
/// initial value (compiler/glsl/Contract.h) and is set by name.
class LobeFields {
 public:
  LobeFields() {
    for (const Member& m : lobeMembers()) values_.emplace_back(m.name, std::string(m.initial));
  }
  void set(std::string_view name, std::string value) {
    for (auto& [member, v] : values_) {
      if (member == name) {
        v = std::move(value);
        return;
      }
    }
    throw std::logic_error(fmt::format("MxcLobe has no member '{}'", name));  // the contract and the emitter disagree
  }
  const std::vector<std::pair<std::string_view, std::string>>& values() const { return values_; }

 private:
  std::vector<std::pair<std::string_view, std::string>> values_;
};

ClosureEmitter::ClosureEmitter(const ir::Material& material, const ExprEmitter& exprs) : m_(material), x_(exprs) {
  lines_.add("  c.emission = vec3(0.0);");
  lines_.add("  c.transparency = vec3(0.0);");
  if (m_.root != ir::kNone) node(m_.root, "vec3(1.0)", Above{});
  lines_.add(fmt::format("  c.count = {};", lobes_));
  lines_.add("  mxc_closure_prepare(c, wo);");
}

std::string ClosureEmitter::unitNormal(const ir::Param* normal) const {
  if (!normal || !normal->present()) return "g.N";
  const std::string value = x_.param(*normal, "g.N");
  const ir::Expr& e = m_.exprs[normal->value];
  if (e.op == ir::Op::GeomProp && m_.exprs.text(normal->value) == "Nworld") return value;  // unit already
  return fmt::format("mxc_safe_normalize({}, g.N)", value);
}

std::string ClosureEmitter::var(const std::string& prefix) { return fmt::format("{}{}", prefix, counter_++); }

std::string ClosureEmitter::lobe(Index iface, const std::string& weight, const Above& above, int mode) {
  const ir::Interface& f = m_.interfaces[iface];
  const std::string kind = fmt::format("MXC_LOBE_{}", ir::lobeKindName(ir::lobeKindOf(f)));
  const SourceLocation at = f.origin.location;
  auto slot = [&](Slot s, const std::string& fallback) {
    const ir::Param* p = f.slots.find(s);
    return p ? x_.param(*p, fallback) : fallback;
  };
  LobeFields fields;
  fields.set("kind", kind);
  fields.set("mode", std::to_string(mode));
  // A shading normal from the document may not be unit length (geometry_normal = 0.9,0,0.1).
  fields.set("N", unitNormal(f.slots.find(Slot::Normal)));
  fields.set("T", slot(Slot::Tangent, "g.T"));
  fields.set("alpha", slot(Slot::Alpha, "vec2(0.0)"));
  fields.set("tau", above.tau);
  fields.set("tauEta", atLeast(above.tauEta, 1e-3f));
  auto set = [&](std::string_view name, std::string value) { fields.set(name, std::move(value)); };
  switch (f.kind) {
    case InterfaceKind::Dielectric: {
      set("c0", slot(Slot::ReflectionTint, "vec3(1.0)"));
      set("c1", slot(Slot::TransmissionTint, "vec3(1.0)"));
      // The IOR ratio across the interface. For an absolute IOR under a coat of coverage C,
      // OpenPBR eq. specular_ior_ratio: lerp(n_b / n_a, n_b / n_c, C), with the TIR fix of eq.
      // specular_ior_ratio_with_tir_fix (n_c / n_b when the coat is denser). IORs are kept
      // >= 1e-3 so the ratios are finite.
      const std::string nb = atLeast(slot(Slot::Ior, "1.5"), 1e-3f);
      std::string eta = nb;
      if (f.iorReference == ir::IorReference::MediumAbove && !isZero(above.coatCoverage)) {
        eta = blend(nb, iorRatio(nb, atLeast(above.coatIor, 1e-3f)), above.coatCoverage);
      }
      if (const ir::Param* xi = f.slots.find(Slot::FresnelScale)) {
        eta = fmt::format("mxc_modulated_eta({}, {})", eta, x_.param(*xi, "1.0"));
      }
      set("eta", eta);
      break;
    }
    case InterfaceKind::Conductor:
      set("c0", slot(Slot::ComplexIor, "vec3(1.0)"));
      set("c1", slot(Slot::Extinction, "vec3(0.0)"));
      break;
    case InterfaceKind::Schlick:
      set("c0", slot(Slot::F0, "vec3(1.0)"));
      set("c1", slot(Slot::F82, "vec3(1.0)"));
      set("c2", slot(Slot::F90, "vec3(1.0)"));
      set("p0", slot(Slot::Exponent, "5.0"));
      set("p1", slot(Slot::FresnelScale, "1.0"));
      break;
    case InterfaceKind::Diffuse:
    case InterfaceKind::Burley:
    case InterfaceKind::Sheen:
      set("c0", slot(Slot::Color, "vec3(1.0)"));
      set("p0", slot(Slot::Roughness, "0.0"));
      break;
    case InterfaceKind::DiffuseTransmission:
      set("c0", slot(Slot::Color, "vec3(1.0)"));
      break;
    case InterfaceKind::DiffuseSheet:
      set("c0", slot(Slot::Color, "vec3(1.0)"));
      set("p0", slot(Slot::Anisotropy, "0.0"));
      break;
  }
  SourceLocation filmAt;
  if (f.thinFilm.present()) {
    // The film's IOR relative to what is above it (the coat where present).
    const std::string aboveIor = blend("1.0", atLeast(above.coatIor, 1e-3f), above.coatCoverage);
    const std::string filmIor = x_.param(f.thinFilm.ior, "1.5");
    set("film", fmt::format("vec3({}, {}, {})", x_.param(f.thinFilm.thickness, "0.0"),
                            isOne(aboveIor) ? filmIor : fmt::format("{} / {}", filmIor, aboveIor),
                            x_.param(f.thinFilm.coverage, "1.0")));
    filmAt = f.thinFilm.thickness.origin.location;
  }
  std::string w = weight;
  if (const ir::Param* scale = f.slots.find(Slot::Weight)) w = product(weight, x_.param(*scale, "1.0"));
  set("weight", w);
  return emitLobe(fields, at, filmAt);
}

std::string ClosureEmitter::emitLobe(const LobeFields& fields, SourceLocation at, SourceLocation filmAt) {
  const std::string l = var("lobe");
  lines_.add(fmt::format("  MxcLobe {};", l), at);
  for (const auto& [member, value] : fields.values()) {
    lines_.add(fmt::format("  {}.{} = {};", l, member, value), member == "film" && filmAt.valid() ? filmAt : at);
  }
  lines_.add(fmt::format("  c.lobes[{}] = {};", lobes_++, l), at);
  return l;
}

void ClosureEmitter::slab(const ir::ScatterNode& n, const std::string& weight, const Above& above) {
  const std::string cov = n.coverage.present() ? x_.ref(n.coverage.value) : "1.0";
  const ir::Medium* medium = n.medium != ir::kNone ? &m_.media[n.medium] : nullptr;
  auto mediumSlot = [&](Slot slot, const std::string& fallback) {
    const ir::Param* p = medium ? medium->slots.find(slot) : nullptr;
    return p ? x_.param(*p, fallback) : fallback;
  };
  const bool subsurface = medium && medium->slots.find(Slot::ObservedAlbedo);
  const bool thinWall = medium && medium->extent == ir::Medium::Extent::ThinWall;
  const bool finite = medium && medium->extent == ir::Medium::Extent::Finite;
  const bool below = subsurface || n.base != ir::kNone;  // something under the top sees what passes it
  std::string normal = "g.N";
  std::string tangent = "g.T";
  std::string topIor = "1.0";
  std::string through = "vec3(1.0)";  // what passes the top and its medium, along wo
  const ir::Interface* top = n.top != ir::kNone ? &m_.interfaces[n.top] : nullptr;
  if (top) {
    int mode = 0;
    const bool dielectric = top->kind == InterfaceKind::Dielectric || top->kind == InterfaceKind::Schlick;
    if (!dielectric || top->scatter != ir::ScatterMode::T) mode |= kModeReflect;
    // Transmission where light has somewhere to go: a bulk (not subsurface) or a thin sheet
    // directly under the interface; over a base, transmitted light is the base's (layering).
    if (dielectric && top->scatter != ir::ScatterMode::R && n.base == ir::kNone && medium && !subsurface && !finite) {
      mode |= kModeTransmit;
      if (thinWall) mode |= kModeThinWall;
    }
    const std::string l = lobe(n.top, product(weight, cov), above, mode);
    if (thinWall) {
      // A thin sheet's normal-incidence transmittance through its absorption (OpenPBR
      // "Thin-walled mode": transmission_color).
      lines_.add(fmt::format("  c.lobes[{}].c1 *= exp(-{});", lobes_ - 1,
                             product(mediumSlot(Slot::Absorption, "vec3(0.0)"), mediumSlot(Slot::Thickness, "1.0"))));
    } else if ((mode & kModeTransmit) && medium->slots.find(Slot::Absorption)) {
      // The bulk's absorption along the refracted path, taken as MXC_BULK_PATH (one scene unit,
      // the radius of the test sphere): this closure sees one interface, not the object, so the
      // path length inside is assumed (Beer's law; OpenPBR "Translucent base").
      lines_.add(fmt::format("  c.lobes[{}].c1 *= exp(-{} * MXC_BULK_PATH);", lobes_ - 1,
                             mediumSlot(Slot::Absorption, "vec3(0.0)")),
                 medium->origin.location);
    }
    if (top->kind == InterfaceKind::Dielectric) {
      const ir::Param* ior = top->slots.find(Slot::Ior);
      topIor = ior ? x_.param(*ior, "1.5") : "1.5";
    }
    if (below) {
      // OpenPBR "Layering": the layers below receive what the top does not reflect, 1 - E(wo).
      const std::string albedo = var("e");
      lines_.add(fmt::format("  vec3 {0} = mxc_lobe_layer_albedo({1}, mxc_to_local(mxc_frame({1}.N, {1}.T), wo));", albedo, l));
      through = fmt::format("(vec3(1.0) - {})", albedo);
      const ir::Param* darkening = top->slots.find(Slot::Darkening);
      const ir::Param* baseAlbedo = top->slots.find(Slot::BaseAlbedo);
      const ir::Param* baseRoughness = top->slots.find(Slot::BaseRoughness);
      const std::string delta = darkening ? x_.param(*darkening, "0.0") : "0.0";
      if (baseAlbedo && baseRoughness && !isZero(delta)) {
        // OpenPBR "Darkening": the internal reflections of the coat darken what is under it
        // (albedo scaling alone does not trap light), modulated by coat_darkening.
        const std::string factor = var("dark");
        lines_.add(fmt::format("  vec3 {} = mxc_coat_darkening({}, {}, {}, {}, dot(wo, {}.N));", factor,
                               atLeast(topIor, 1e-3f), asVec3(x_.param(*baseAlbedo, "vec3(0.0)")),
                               x_.param(*baseRoughness, "1.0"), delta, l),
                   darkening->origin.location);
        through = product(through, factor);
      }
    }
    normal = l + ".N";
    tangent = l + ".T";
  }
  Above under = above;
  std::string tauSlab;
  if (finite && below) {
    tauSlab = var("tau");
    lines_.add(fmt::format("  vec3 {} = {};", tauSlab,
                           product(mediumSlot(Slot::Absorption, "vec3(0.0)"), mediumSlot(Slot::Thickness, "1.0"))));
    // OpenPBR "View-dependent absorption": the coat's transmittance along the refracted wo.
    through = product(through, fmt::format("mxc_absorption({}, {}, clamp(dot(wo, {}), 0.0, 1.0))", tauSlab,
                                           atLeast(topIor, 1e-3f), normal));
  }
  if (top && top->kind == InterfaceKind::Dielectric && top->iorReference == ir::IorReference::MediumAbove) {
    under.coatIor = topIor;
    under.coatCoverage = cov;
  }
  if (subsurface) {
    // Under the interface, a dense scattering bulk seen from outside: a diffuse lobe of the
    // observed albedo (OpenPBR "Subsurface" defines subsurface_color as that albedo; without a
    // subsurface transport the spec asks for it as a diffuse colour, "Flexibility of implementation").
    LobeFields fields;
    fields.set("kind", fmt::format("MXC_LOBE_{}", ir::lobeKindName(ir::LobeKind::EON)));
    fields.set("weight", product(product(weight, cov), through));
    fields.set("N", normal);
    fields.set("T", tangent);
    fields.set("c0", mediumSlot(Slot::ObservedAlbedo, "vec3(0.8)"));
    fields.set("tau", above.tau);
    fields.set("tauEta", atLeast(above.tauEta, 1e-3f));
    emitLobe(fields, medium->origin.location, {});
  }
  if (n.base == ir::kNone) return;
  if (finite) {
    under.tau = isZero(above.tau) ? tauSlab : fmt::format("({} + {})", above.tau, tauSlab);
    under.tauEta = topIor;
  }
  if (finite && !isOne(cov)) {
    // Partly covered by an absorbing slab: the uncovered part sees no absorption along wi.
    node(n.base, product(weight, fmt::format("(1.0 - {})", cov)), above);
    node(n.base, product(product(weight, cov), through), under);
    return;
  }
  const std::string wBase = var("w");
  lines_.add(fmt::format("  vec3 {} = {};", wBase,
                         product(weight, isOne(cov) ? through : fmt::format("((1.0 - {0}) + {0} * {1})", cov, through))));
  node(n.base, wBase, under);
}

void ClosureEmitter::node(Index index, const std::string& weight, const Above& above) {
  const ir::ScatterNode& n = m_.nodes[index];
  switch (n.kind) {
    case ScatterKind::Slab: slab(n, weight, above); break;
    case ScatterKind::Mix: {
      const std::string w = var("m");
      const std::string value = x_.ref(n.weight.value);
      lines_.add(fmt::format("  vec3 {} = vec3({});", w, value), n.weight.origin.location);
      node(n.a, product(weight, fmt::format("(vec3(1.0) - {})", w)), above);
      node(n.b, product(weight, w), above);
      break;
    }
    case ScatterKind::Add:
      node(n.a, weight, above);
      node(n.b, weight, above);
      break;
    case ScatterKind::Tint:
      node(n.a, product(weight, fmt::format("vec3({})", x_.ref(n.weight.value))), above);
      break;
    case ScatterKind::Emissive: {
      const ir::Emission& e = m_.emissions[n.emission];
      std::string color = e.slots.find(Slot::Color) ? x_.param(*e.slots.find(Slot::Color), "vec3(0.0)") : "vec3(0.0)";
      std::string shape = "1.0";
      if (e.kind == ir::Emission::Kind::Conical) {
        // Inside the cone of half-angle `inner` (degrees) fully, fading to `outer` (MaterialX
        // conical_edf; its defaults 60 and 0: a hard edge).
        const ir::Param* normal = e.slots.find(Slot::Normal);
        const ir::Param* inner = e.slots.find(Slot::InnerAngle);
        const ir::Param* outer = e.slots.find(Slot::OuterAngle);
        shape = fmt::format("mxc_cone_falloff(dot({}, wo), {}, {})", normal ? x_.param(*normal, "g.N") : "g.N",
                            inner ? x_.param(*inner, "60.0") : "60.0", outer ? x_.param(*outer, "0.0") : "0.0");
      }
      std::string directional;
      if (const ir::Param* f0 = e.slots.find(Slot::F0)) {
        const ir::Param* f90 = e.slots.find(Slot::F90);
        const ir::Param* exponent = e.slots.find(Slot::Exponent);
        directional = fmt::format(" * mxc_fresnel_schlick(clamp(dot(g.N, wo), 0.0, 1.0), {}, {}, {})",
                                  x_.param(*f0, "vec3(1.0)"), f90 ? x_.param(*f90, "vec3(1.0)") : "vec3(1.0)",
                                  exponent ? x_.param(*exponent, "5.0") : "5.0");
      }
      lines_.add(fmt::format("  c.emission += {}{};", product(product(weight, color), shape), directional), e.origin.location);
      node(n.a, weight, above);
      break;
    }
    case ScatterKind::Ambient:
      lines_.add(fmt::format("  c.transparency += {};", weight), n.origin.location);
      break;
    case ScatterKind::Absorber: break;
  }
}

}  // namespace mxc::glsl
