#include "compiler/glsl/AlbedoScaling.h"

#include <fmt/format.h>

#include "compiler/glsl/ClosureValues.h"
#include "compiler/glsl/Contract.h"
#include "compiler/glsl/LobeMapping.h"

namespace mxc::glsl {

namespace {

using Id = ClosureValues::Id;
using ir::Index;
using ir::InterfaceKind;
using ir::ScatterKind;
using ir::Slot;
using ir::Type;

/// One walk of a material's tree: every node visited with the weight it contributes with
/// (a vec3 of the closure's values) and what lies above it.
class Walk {
 public:
  Walk(const ir::Material& m, const ExprEmitter& x, Closure& out) : m_(m), v_(m, x), out_(out) {}

  void run() {
    if (m_.root != ir::kNone) node(m_.root, v_.vec3(1.0f), Above::ambient(v_));
  }

 private:
  std::string var(const std::string& prefix) { return fmt::format("{}{}", prefix, counter_++); }

  /// A value the generated code keeps in a variable (`vec3 name = value;`), to use it twice
  /// without computing it twice.
  Id keep(const std::string& prefix, Id value, SourceLocation at = {}) {
    const std::string name = var(prefix);
    out_.lines.add(fmt::format("  vec3 {} = {};", name, v_.glsl(v_.asVec3(value))), at);
    return v_.local(name, Type::Vec3);
  }

  /// A lobe for an interface; returns its variable.
  std::string lobe(Index iface, Id weight, const Above& above, int mode) {
    const ir::Interface& f = m_.interfaces[iface];
    LobeFields fields = mapInterface(v_, m_, f, above, mode, weight);
    const std::string name = var("lobe");
    writeLobe(out_.lines, name, out_.lobes++, fields, f.origin.location,
              f.thinFilm.present() ? f.thinFilm.thickness.origin.location : SourceLocation{});
    return name;
  }

  void slab(const ir::ScatterNode& n, Id weight, const Above& above) {
    const Id cov = v_.param(n.coverage, v_.constant(1.0f));
    const ir::Medium* medium = n.medium != ir::kNone ? &m_.media[n.medium] : nullptr;
    auto mediumSlot = [&](Slot slot, Id fallback) { return medium ? v_.slot(medium->slots, slot, fallback) : fallback; };
    const bool subsurface = medium && medium->slots.find(Slot::ObservedAlbedo);
    const bool thinWall = medium && medium->extent == ir::Medium::Extent::ThinWall;
    const bool finite = medium && medium->extent == ir::Medium::Extent::Finite;
    const bool below = subsurface || n.base != ir::kNone;  // something under the top sees what passes it
    std::string normal = "g.N";
    std::string tangent = "g.T";
    Id topIor = v_.constant(1.0f);
    Id through = v_.vec3(1.0f);  // what passes the top and its medium, along wo
    const Id floor = v_.constant(1e-3f);  // IORs that divide are kept >= 1e-3
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
      const std::string l = lobe(n.top, v_.mul(weight, cov), above, mode);
      if (thinWall) {
        // A thin sheet's normal-incidence transmittance through its absorption (OpenPBR
        // "Thin-walled mode": transmission_color).
        out_.lines.add(fmt::format("  c.lobes[{}].c1 *= exp(-{});", out_.lobes - 1,
                                   v_.glsl(v_.mul(mediumSlot(Slot::Absorption, v_.vec3(0.0f)),
                                                  mediumSlot(Slot::Thickness, v_.constant(1.0f))))));
      } else if ((mode & kModeTransmit) && medium->slots.find(Slot::Absorption)) {
        // The bulk's absorption along the refracted path, taken as MXC_BULK_PATH (one scene
        // unit, the radius of the test sphere): this closure sees one interface, not the
        // object, so the path length inside is assumed (Beer's law; OpenPBR "Translucent base").
        out_.lines.add(fmt::format("  c.lobes[{}].c1 *= exp(-{} * MXC_BULK_PATH);", out_.lobes - 1,
                                   v_.glsl(mediumSlot(Slot::Absorption, v_.vec3(0.0f)))),
                       medium->origin.location);
      }
      if (top->kind == InterfaceKind::Dielectric) topIor = v_.slot(top->slots, Slot::Ior, v_.constant(1.5f));
      if (below) {
        // OpenPBR "Layering": the layers below receive what the top does not reflect, 1 - E(wo).
        const std::string albedo = var("e");
        out_.lines.add(fmt::format("  vec3 {0} = mxc_lobe_layer_albedo({1}, mxc_to_local(mxc_frame({1}.N, {1}.T), wo));",
                                   albedo, l));
        through = v_.oneMinus(v_.local(albedo, Type::Vec3));
        const ir::Param* darkening = top->slots.find(Slot::Darkening);
        const ir::Param* baseAlbedo = top->slots.find(Slot::BaseAlbedo);
        const ir::Param* baseRoughness = top->slots.find(Slot::BaseRoughness);
        const Id delta = darkening ? v_.param(*darkening, v_.constant(0.0f)) : v_.constant(0.0f);
        if (baseAlbedo && baseRoughness && !v_.isZero(delta)) {
          // OpenPBR "Darkening": the internal reflections of the coat darken what is under it
          // (albedo scaling alone does not trap light), modulated by coat_darkening.
          const std::string factor = var("dark");
          out_.lines.add(fmt::format("  vec3 {} = mxc_coat_darkening({}, {}, {}, {}, dot(wo, {}.N));", factor,
                                     v_.glsl(v_.max(topIor, floor)), v_.glsl(v_.asVec3(baseAlbedo->value)),
                                     v_.glsl(baseRoughness->value), v_.glsl(delta), l),
                         darkening->origin.location);
          through = v_.mul(through, v_.local(factor, Type::Vec3));
        }
      }
      normal = l + ".N";
      tangent = l + ".T";
    }
    Above under = above;
    Id tauSlab = v_.vec3(0.0f);
    if (finite && below) {
      tauSlab = keep("tau", v_.mul(mediumSlot(Slot::Absorption, v_.vec3(0.0f)), mediumSlot(Slot::Thickness, v_.constant(1.0f))));
      // OpenPBR "View-dependent absorption": the coat's transmittance along the refracted wo.
      through = v_.mul(through, v_.local(fmt::format("mxc_absorption({}, {}, clamp(dot(wo, {}), 0.0, 1.0))", v_.glsl(tauSlab),
                                                     v_.glsl(v_.max(topIor, floor)), normal),
                                         Type::Vec3));
    }
    if (top && top->kind == InterfaceKind::Dielectric && top->iorReference == ir::IorReference::MediumAbove) {
      under.coatIor = topIor;
      under.coatCoverage = cov;
    }
    if (subsurface) {
      // Under the interface, a dense scattering bulk seen from outside: a diffuse lobe of the
      // observed albedo (OpenPBR "Subsurface" defines subsurface_color as that albedo; without
      // a subsurface transport the spec asks for it as a diffuse colour, "Flexibility of
      // implementation").
      LobeFields fields;
      fields.set("kind", fmt::format("MXC_LOBE_{}", ir::lobeKindName(ir::LobeKind::EON)));
      fields.set("weight", v_.glsl(v_.mul(v_.mul(weight, cov), through)));
      fields.set("N", normal);
      fields.set("T", tangent);
      fields.set("c0", v_.glsl(mediumSlot(Slot::ObservedAlbedo, v_.vec3(0.8f))));
      fields.set("tau", v_.glsl(above.tau));
      fields.set("tauEta", v_.glsl(v_.max(above.tauEta, floor)));
      writeLobe(out_.lines, var("lobe"), out_.lobes++, fields, medium->origin.location);
    }
    if (n.base == ir::kNone) return;
    if (finite) {
      under.tau = v_.add(above.tau, tauSlab);
      under.tauEta = topIor;
    }
    if (finite && !v_.isOne(cov)) {
      // Partly covered by an absorbing slab: the uncovered part sees no absorption along wi.
      node(n.base, v_.mul(weight, v_.oneMinus(cov)), above);
      node(n.base, v_.mul(v_.mul(weight, cov), through), under);
      return;
    }
    // The base receives the uncovered part whole and the covered part through the top.
    const Id reaching = v_.add(v_.oneMinus(cov), v_.mul(cov, through));
    node(n.base, keep("w", v_.mul(weight, reaching)), under);
  }

  void node(Index index, Id weight, const Above& above) {
    const ir::ScatterNode& n = m_.nodes[index];
    switch (n.kind) {
      case ScatterKind::Slab: slab(n, weight, above); break;
      case ScatterKind::Mix: {
        const Id w = keep("m", n.weight.value, n.weight.origin.location);
        node(n.a, v_.mul(weight, v_.oneMinus(w)), above);
        node(n.b, v_.mul(weight, w), above);
        break;
      }
      case ScatterKind::Add:
        node(n.a, weight, above);
        node(n.b, weight, above);
        break;
      case ScatterKind::Tint: node(n.a, v_.mul(weight, v_.asVec3(n.weight.value)), above); break;
      case ScatterKind::Emissive: {
        const ir::Emission& e = m_.emissions[n.emission];
        out_.lines.add(fmt::format("  c.emission += {};", emittedRadiance(v_, e, weight)), e.origin.location);
        node(n.a, weight, above);
        break;
      }
      case ScatterKind::Ambient:
        out_.lines.add(fmt::format("  c.transparency += {};", v_.glsl(weight)), n.origin.location);
        break;
      case ScatterKind::Absorber: break;
    }
  }

  const ir::Material& m_;
  ClosureValues v_;
  Closure& out_;
  int counter_ = 0;
};

}  // namespace

void AlbedoScaling::layers(const ir::Material& material, const ExprEmitter& exprs, Closure& out) const {
  Walk(material, exprs, out).run();
}

}  // namespace mxc::glsl
