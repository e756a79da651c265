#include "compiler/glsl/AlbedoScaling.h"

#include <map>
#include <string>
#include <tuple>
#include <vector>

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
    if (m_.root != ir::kNone) node(m_.root, v_.vec3(1.0f), v_.vec3(1.0f), Above::ambient(v_));
    // The lobes' weights, summed over the paths that reach each, and the lobes stored; a lobe
    // of weight constant 0 is dropped.
    for (const PendingLobe& l : lobes_) {
      if (v_.isZero(l.weight)) continue;
      out_.lines.add(fmt::format("  {}.weight = {};", l.name, v_.glsl(v_.asVec3(l.weight))), l.at);
      out_.lines.add(fmt::format("  c.lobes[{}] = {};", out_.lobes++, l.name), l.at);
    }
  }

 private:
  std::string var(const std::string& prefix) { return fmt::format("{}{}", prefix, counter_++); }

  /// A value the generated code keeps in a variable (`vec3 name = value;`), to use it twice
  /// without computing it twice; a value kept before is that variable (the closure's code is
  /// straight-line: a variable declared earlier is in scope).
  Id keep(const std::string& prefix, Id value, SourceLocation at = {}) {
    const Id v3 = v_.asVec3(value);
    if (auto it = kept_.find(v3); it != kept_.end()) return it->second;
    const std::string name = var(prefix);
    out_.lines.add(fmt::format("  vec3 {} = {};", name, v_.glsl(v3)), at);
    return kept_[v3] = v_.local(name, Type::Vec3);
  }

  /// The lobe of an interface reached with `weight` under `above`, in `mode` (with `medium`
  /// under it when it transmits into it); returns its variable. Every path that reaches the
  /// same interface in the same place (the same mode, medium and layers above) shares one
  /// lobe, whose weight is their sum: the closure is linear in the weights, and its mixture
  /// (OpenPBR "Reduction to a mixture of lobes") is the same with fewer lobes. A slab tree
  /// distributed over its mixes (ir::distributeOverMix) repeats the layers above each mix once
  /// per branch.
  std::string lobe(Index iface, Id weight, const Above& above, int mode, Index medium) {
    const ir::Interface& f = m_.interfaces[iface];
    const LobeKey key{iface, mode, (mode & (kModeTransmit | kModeThinWall)) ? medium : ir::kNone,
                      above.coatIor, above.coatCoverage, above.tau, above.tauEta};
    const Id w = lobeWeight(v_, f, weight);
    if (auto it = lobeKeys_.find(key); it != lobeKeys_.end()) {
      PendingLobe& l = lobes_[it->second];
      l.weight = v_.add(l.weight, w);
      created_ = false;
      return l.name;
    }
    LobeFields fields = mapInterface(v_, m_, f, above, mode, v_.vec3(0.0f));
    out_.modes |= mode;
    out_.absorbs = out_.absorbs || !v_.isZero(above.tau);
    const std::string name = var("lobe");
    declareLobe(out_.lines, name, fields, f.origin.location,
                f.thinFilm.present() ? f.thinFilm.thickness.origin.location : SourceLocation{}, "weight");
    lobeKeys_.emplace(key, lobes_.size());
    lobes_.push_back({name, w, f.origin.location, {}});
    created_ = true;
    return name;
  }

  /// `weight`: what the node's lobes are weighted by; `emitted`: what an emission under it is
  /// (the light it emits crosses the layers above once, without their darkening: see below).
  void slab(const ir::ScatterNode& n, Id weight, Id emitted, const Above& above) {
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
    Id throughEmitted = v_.vec3(1.0f);  // the same for light emitted under the top
    struct Recycle {
      const ir::Param* darkening = nullptr;
      const ir::Param* baseAlbedo = nullptr;
      const ir::Param* baseRoughness = nullptr;
      std::string lobe;
    } recycle;  // set when a coat darkens what is under it
    const Id floor = v_.constant(1e-3f);  // IORs that divide are kept >= 1e-3
    const ir::Interface* top = n.top != ir::kNone ? &m_.interfaces[n.top] : nullptr;
    Id applied = v_.vec3(1.0f);     // the darkening it applies to what is under it
    Id darkeningControl = v_.constant(0.0f);
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
      const std::string l = lobe(n.top, v_.mul(weight, cov), above, mode, n.medium);
      if (thinWall && created_) {
        // A thin sheet's normal-incidence transmittance through its absorption (OpenPBR
        // "Thin-walled mode": transmission_color).
        out_.lines.add(fmt::format("  {}.c1 *= exp(-{});", l,
                                   v_.glsl(v_.mul(mediumSlot(Slot::Absorption, v_.vec3(0.0f)),
                                                  mediumSlot(Slot::Thickness, v_.constant(1.0f))))));
      } else if ((mode & kModeTransmit) && medium->slots.find(Slot::Absorption) && created_) {
        // The bulk's absorption along the refracted path, taken as MXC_BULK_PATH (one scene
        // unit, the radius of the test sphere): this closure sees one interface, not the
        // object, so the path length inside is assumed (Beer's law; OpenPBR "Translucent base").
        out_.lines.add(fmt::format("  {}.c1 *= exp(-{} * MXC_BULK_PATH);", l,
                                   v_.glsl(mediumSlot(Slot::Absorption, v_.vec3(0.0f)))),
                       medium->origin.location);
      }
      if (top->kind == InterfaceKind::Dielectric) topIor = v_.slot(top->slots, Slot::Ior, v_.constant(1.5f));
      if (below) {
        // OpenPBR "Layering": the layers below receive what the top does not reflect, 1 - E(wo)
        // (once per lobe: the albedo does not depend on the lobe's weight).
        auto [known, added] = layerAlbedo_.try_emplace(l, std::string());
        if (added) {
          known->second = var("e");
          out_.lines.add(fmt::format("  vec3 {0} = mxc_lobe_layer_albedo({1}, mxc_to_local(mxc_frame({1}.N, {1}.T), wo));",
                                     known->second, l));
        }
        through = v_.oneMinus(v_.local(known->second, Type::Vec3));
        throughEmitted = through;
        if (const ir::Param* under = top->slots.find(Slot::BaseAlbedo);
            under && top->kind == InterfaceKind::Sheen && top->sheenModel == ir::SheenModel::Zeltner) {
          // OpenPBR "Fuzz": what the base returns meets the fuzz again (mxc_fuzz_darkening).
          const std::string args = fmt::format("{}.c0, {}.p0, {}", l, l, v_.glsl(v_.asVec3(under->value)));
          through = v_.mul(through, v_.local(fmt::format("mxc_fuzz_darkening({})", args), Type::Vec3));
          if (m_.features.emission) {
            throughEmitted = v_.mul(throughEmitted, v_.local(fmt::format("mxc_fuzz_recycling({})", args), Type::Vec3));
          }
        }
        const ir::Param* darkening = top->slots.find(Slot::Darkening);
        const ir::Param* baseAlbedo = top->slots.find(Slot::BaseAlbedo);
        const ir::Param* baseRoughness = top->slots.find(Slot::BaseRoughness);
        const Id delta = darkening ? v_.param(*darkening, v_.constant(0.0f)) : v_.constant(0.0f);
        if (m_.features.emission && darkening && baseAlbedo && baseRoughness) {
          recycle = {darkening, baseAlbedo, baseRoughness, l};
        }
        if (baseAlbedo && baseRoughness && !v_.isZero(delta)) {
          // OpenPBR "Darkening": the internal reflections of the coat darken what is under it
          // (albedo scaling alone does not trap light), modulated by coat_darkening.
          auto [factor, newFactor] = darkening_.try_emplace(l, std::string());
          if (newFactor) {
            factor->second = var("dark");
            // The base's IOR: the coat's own when the lowering gives none (K_r as the spec has it).
            const ir::Param* baseIorParam = top->slots.find(Slot::BaseIor);
            const Id baseIor = baseIorParam ? v_.param(*baseIorParam, topIor) : topIor;
            out_.lines.add(fmt::format("  vec3 {} = mxc_coat_darkening({}, {}, {}, {}, {}, dot(wo, {}.N));", factor->second,
                                       v_.glsl(v_.max(topIor, floor)), v_.glsl(v_.max(baseIor, floor)),
                                       v_.glsl(v_.asVec3(baseAlbedo->value)),
                                       v_.glsl(baseRoughness->value), v_.glsl(delta), l),
                           darkening->origin.location);
          }
          applied = v_.local(factor->second, Type::Vec3);
          darkeningControl = delta;
          through = v_.mul(through, applied);
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
      const Id absorbed = v_.local(fmt::format("mxc_absorption({}, {}, clamp(dot(wo, {}), 0.0, 1.0))", v_.glsl(tauSlab),
                                               v_.glsl(v_.max(topIor, floor)), normal),
                                   Type::Vec3);
      through = v_.mul(through, absorbed);
      throughEmitted = v_.mul(throughEmitted, absorbed);
    }
    // Without emission there is nothing to carry apart (the weights stay one value, one variable).
    if (!m_.features.emission) throughEmitted = through;
    if (recycle.darkening) {
      // Emitted light crosses the coat once (OpenPBR "Emission": L_e = lerp(1, T_coat, C) E,
      // T_coat the one-way transmittance, coat_color = T_coat^2), and what the coat reflects
      // back down the base reflects again (mxc_coat_recycling): not the darkening of light that
      // came from above. The reference walk agrees: 0.468 for coat_color 0.25 over a black base,
      // where the darkening gave 0.164; 2.05 for a clear coat over base_color 0.8 (issue 39).
      auto [recycled, added] = recycling_.try_emplace(recycle.lobe, std::string());
      if (added) {
        recycled->second = var("recycled");
        out_.lines.add(fmt::format("  vec3 {} = mxc_coat_recycling({}, {}, {}, dot(wo, {}.N), {});", recycled->second,
                                   v_.glsl(v_.max(topIor, floor)), v_.glsl(v_.asVec3(recycle.baseAlbedo->value)),
                                   v_.glsl(recycle.baseRoughness->value), recycle.lobe, v_.glsl(tauSlab)),
                       recycle.darkening->origin.location);
      }
      throughEmitted = v_.mul(throughEmitted, v_.local(recycled->second, Type::Vec3));
    }
    if (top && top->kind == InterfaceKind::Dielectric) {
      under.interfaceIor = topIor;
      under.interfaceCoverage = cov;
    }
    if (top && top->kind == InterfaceKind::Dielectric && top->iorReference == ir::IorReference::MediumAbove) {
      under.coatIor = topIor;
      under.coatCoverage = cov;
      under.darkening = applied;
      under.darkeningControl = darkeningControl;
    }
    if (subsurface) {
      // Under the interface, a dense scattering bulk seen from outside: a diffuse lobe of the
      // observed albedo (OpenPBR "Subsurface" defines subsurface_color as that albedo; without
      // a subsurface transport the spec asks for it as a diffuse colour, "Flexibility of
      // implementation").
      const Id w = v_.mul(v_.mul(weight, cov), through);
      // Keyed by the medium, with no interface: one lobe per bulk and place.
      const LobeKey key{ir::kNone, kModeReflect, n.medium, above.coatIor, above.coatCoverage, above.tau, above.tauEta};
      if (auto it = lobeKeys_.find(key); it != lobeKeys_.end() && lobes_[it->second].normal == normal) {
        lobes_[it->second].weight = v_.add(lobes_[it->second].weight, w);
      } else {
        LobeFields fields;
        fields.set("kind", fmt::format("MXC_LOBE_{}", ir::lobeKindName(ir::LobeKind::EON)));
        fields.set("N", normal);
        fields.set("T", tangent);
        const Id observed = v_.asVec3(mediumSlot(Slot::ObservedAlbedo, v_.vec3(0.8f)));
        // The half-space's own angular dependence and coat darkening (mxc_subsurface.glsl),
        // under its interface, or the nearest dielectric above it (partly covering: its IOR
        // ratio mixed towards 1 by the coverage, exact at 0 and 1) as the reference walk meets
        // it. The same with an IR that keeps the two apart (a general shader) or merges them.
        const bool ownInterface = top && top->kind == InterfaceKind::Dielectric;
        const Id ior = ownInterface ? topIor : v_.mix(v_.constant(1.0f), above.interfaceIor, above.interfaceCoverage);
        if (ownInterface || !v_.isZero(above.interfaceCoverage)) {
          fields.set("c0", fmt::format("{0} * mxc_subsurface_factor({0}, {1}, dot(wo, {2}), {3}, {4}, {5}, {6})",
                                       v_.glsl(observed), v_.glsl(v_.max(ior, floor)), normal, v_.glsl(above.coatIor),
                                       v_.glsl(above.coatCoverage), v_.glsl(above.darkeningControl),
                                       v_.glsl(above.darkening)));
        } else {
          fields.set("c0", v_.glsl(observed));
        }
        fields.set("tau", v_.glsl(above.tau));
        fields.set("tauEta", v_.glsl(v_.max(above.tauEta, floor)));
        out_.modes |= kModeReflect;
        out_.absorbs = out_.absorbs || !v_.isZero(above.tau);
        const std::string name = var("lobe");
        declareLobe(out_.lines, name, fields, medium->origin.location, {}, "weight");
        lobeKeys_.insert_or_assign(key, lobes_.size());
        lobes_.push_back({name, w, medium->origin.location, normal});
      }
    }
    if (n.base == ir::kNone) return;
    if (finite) {
      under.tau = v_.add(above.tau, tauSlab);
      under.tauEta = topIor;
    }
    if (finite && !v_.isOne(cov)) {
      // Partly covered by an absorbing slab: the uncovered part sees no absorption along wi.
      node(n.base, v_.mul(weight, v_.oneMinus(cov)), v_.mul(emitted, v_.oneMinus(cov)), above);
      node(n.base, v_.mul(v_.mul(weight, cov), through), v_.mul(v_.mul(emitted, cov), throughEmitted), under);
      return;
    }
    // The base receives the uncovered part whole and the covered part through the top.
    const Id reaching = v_.add(v_.oneMinus(cov), v_.mul(cov, through));
    const Id reachingEmitted = v_.add(v_.oneMinus(cov), v_.mul(cov, throughEmitted));
    node(n.base, keep("w", v_.mul(weight, reaching)), keep("w", v_.mul(emitted, reachingEmitted)), under);
  }

  void node(Index index, Id weight, Id emitted, const Above& above) {
    const ir::ScatterNode& n = m_.nodes[index];
    switch (n.kind) {
      case ScatterKind::Slab: slab(n, weight, emitted, above); break;
      case ScatterKind::Mix: {
        const Id w = keep("m", n.weight.value, n.weight.origin.location);
        node(n.a, v_.mul(weight, v_.oneMinus(w)), v_.mul(emitted, v_.oneMinus(w)), above);
        node(n.b, v_.mul(weight, w), v_.mul(emitted, w), above);
        break;
      }
      case ScatterKind::Add:
        node(n.a, weight, emitted, above);
        node(n.b, weight, emitted, above);
        break;
      case ScatterKind::Tint: {
        const Id tint = v_.asVec3(n.weight.value);
        node(n.a, v_.mul(weight, tint), v_.mul(emitted, tint), above);
        break;
      }
      case ScatterKind::Emissive: {
        const ir::Emission& e = m_.emissions[n.emission];
        out_.lines.add(fmt::format("  c.emission += {};", emittedRadiance(v_, e, emitted)), e.origin.location);
        node(n.a, weight, emitted, above);
        break;
      }
      case ScatterKind::Ambient:
        out_.lines.add(fmt::format("  c.transparency += {};", v_.glsl(weight)), n.origin.location);
        break;
      case ScatterKind::Absorber: break;
    }
  }

  /// A lobe of the closure: its variable, the sum of the weights of the paths that reach it,
  /// where it comes from, and (a subsurface lobe) the normal it was made with.
  struct PendingLobe {
    std::string name;
    Id weight;
    SourceLocation at;
    std::string normal;
  };
  /// What makes two visits the same lobe: the interface (none for a subsurface bulk's lobe),
  /// mode, the medium it transmits into, and what lies above it.
  using LobeKey = std::tuple<Index, int, Index, Id, Id, Id, Id>;

  const ir::Material& m_;
  ClosureValues v_;
  Closure& out_;
  int counter_ = 0;
  std::vector<PendingLobe> lobes_;
  std::map<LobeKey, size_t> lobeKeys_;
  bool created_ = false;                         ///< the last lobe() made a new lobe
  std::map<std::string, std::string> layerAlbedo_;  ///< a lobe's variable -> its layer albedo's
  std::map<std::string, std::string> darkening_;    ///< a lobe's variable -> its coat darkening's
  std::map<std::string, std::string> recycling_;    ///< a lobe's variable -> its emission recycling's
  std::map<Id, Id> kept_;                        ///< keep(): a value -> its variable
};

}  // namespace

void AlbedoScaling::layers(const ir::Material& material, const ExprEmitter& exprs, Closure& out) const {
  Walk(material, exprs, out).run();
}

}  // namespace mxc::glsl
