#include "compiler/glsl/SlabWalk.h"

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

// The flags of a layer (mxc_walk.glsl, MXC_LAYER_*).
constexpr int kNoInterface = 1;
constexpr int kExit = 2;
constexpr int kHalfSpace = 4;
constexpr int kObserved = 8;

/// One layer of a stack, as GLSL values: the interface and the medium under it.
struct Layer {
  Layer() { lobe.set("kind", "MXC_LOBE_EON"); }  // read only when the layer has an interface
  LobeFields lobe;
  SourceLocation at;
  SourceLocation filmAt;
  std::string sigmaA = "vec3(0.0)";
  std::string sigmaS = "vec3(0.0)";
  std::string g = "0.0";
  std::string thickness = "0.0";  // 0: no medium; < 0: a half-space
  std::string coverage = "1.0";
  int flags = 0;
  std::string etaCovered = "1.0";  // the interface's IOR ratio with the coat `coat` present
  std::string etaBare = "1.0";     // and without it
  int coat = -1;                   // index in the stack of the coat whose IOR is above (-1: none or always there)
  std::string emitted = "vec3(0.0)";
};

/// The coat above a layer: the nearest dielectric slab whose IOR is that of the medium under it.
struct Coat {
  int index = -1;  // in the stack
  Id ior;
  Id coverage;
  bool always = false;  // coverage constant 1
};

class Walk {
 public:
  Walk(const ir::Material& m, const ExprEmitter& x, Closure& out) : m_(m), v_(m, x), out_(out) {}

  void run() {
    if (m_.root != ir::kNone) node(m_.root, v_.vec3(1.0f), {}, Coat{});
    out_.lines.add(fmt::format("  c.stackCount = {};", out_.stacks));
  }

 private:
  /// The IOR ratio of a dielectric under a coat of IOR `above` (kNoExpr: outside), with
  /// specular_weight's modulation (OpenPBR eq. modulated_ior). The walk needs the physical
  /// ratio, total internal reflection included, not the spec's TIR fix for albedo scaling.
  std::string eta(const ir::Interface& f, Id above) {
    const Id floor = v_.constant(1e-3f);
    const Id nb = v_.max(v_.slot(f.slots, Slot::Ior, v_.constant(1.5f)), floor);
    Id ratio = nb;
    if (above != ir::kNoExpr && f.iorReference == ir::IorReference::MediumAbove) ratio = v_.div(nb, v_.max(above, floor));
    std::string text = v_.glsl(ratio);
    if (const ir::Param* xi = f.slots.find(Slot::FresnelScale); xi && xi->present()) {
      text = fmt::format("mxc_modulated_eta({}, {})", text, v_.glsl(xi->value));
    }
    return text;
  }

  /// A medium defined by the colour it is observed to have (OpenPBR "Subsurface", eq.
  /// subsurface_albedo_constraint): the layer carries its extinction (sigmaA) and the colour
  /// (sigmaS) with kObserved, and the walk gives it the single-scattering albedo with which it
  /// returns that colour through the interface over it as that walk sees it
  /// (mxc_walk_subsurface_albedo; the IR's is van de Hulst's for an index-matched boundary).
  void observedMedium(Layer& layer, const ir::Medium& medium, const ir::Param& colour) {
    layer.sigmaA = v_.glsl(v_.add(v_.asVec3(v_.slot(medium.slots, Slot::Absorption, v_.vec3(0.0f))),
                                  v_.asVec3(v_.slot(medium.slots, Slot::Scattering, v_.vec3(0.0f)))));
    layer.sigmaS = fmt::format("clamp({}, 0.0, 1.0)", v_.glsl(v_.asVec3(colour.value)));
    layer.flags |= kObserved;
  }

  Layer interfaceLayer(Index iface, const Coat& coat, const std::string& coverage) {
    const ir::Interface& f = m_.interfaces[iface];
    Above above = Above::ambient(v_);
    if (coat.index >= 0) {
      above.coatIor = coat.ior;
      above.coatCoverage = coat.coverage;  // the thin film's IOR ratio: blended, as in the other tiers
    }
    int mode = 0;
    if (f.kind == InterfaceKind::Dielectric || f.kind == InterfaceKind::Schlick) {
      if (f.scatter != ir::ScatterMode::T) mode |= kModeReflect;
      if (f.scatter != ir::ScatterMode::R) mode |= kModeTransmit;
    }
    Layer layer;
    layer.lobe = mapInterface(v_, m_, f, above, mode, v_.vec3(1.0f));
    layer.at = f.origin.location;
    if (f.thinFilm.present()) layer.filmAt = f.thinFilm.thickness.origin.location;
    layer.coverage = coverage;
    if (f.kind == InterfaceKind::Dielectric) {
      layer.etaCovered = eta(f, coat.index >= 0 ? coat.ior : ir::kNoExpr);
      layer.etaBare = eta(f, ir::kNoExpr);
      if (coat.index >= 0 && !coat.always) layer.coat = coat.index;
      layer.lobe.set("eta", layer.etaCovered);
      layer.lobe.set("etaAbove", "1.0");  // the walk refracts its directions through the coat itself
    }
    if (f.kind == InterfaceKind::Hair) {
      // A fibre: its IOR is its own, not a ratio to a layer above, and what passes through it
      // leaves on its far side (a fibre is not layered over anything).
      layer.etaCovered = layer.etaBare = v_.glsl(v_.slot(f.slots, Slot::Ior, v_.constant(1.55f)));
      layer.flags |= kExit;
    }
    return layer;
  }

  void slab(const ir::ScatterNode& n, Id weight, std::vector<Layer> stack, Coat coat) {
    const Id cov = v_.param(n.coverage, v_.constant(1.0f));
    const std::string coverage = v_.glsl(cov);
    const ir::Medium* medium = n.medium != ir::kNone ? &m_.media[n.medium] : nullptr;
    Layer layer;
    if (n.top != ir::kNone) {
      layer = interfaceLayer(n.top, coat, coverage);
    } else {
      layer.flags |= kNoInterface;  // an index-matched slab: only its medium
      layer.coverage = coverage;
    }
    const ir::Interface* top = n.top != ir::kNone ? &m_.interfaces[n.top] : nullptr;
    Layer mirrored;
    bool thinWall = false;
    if (medium) {
      auto slot = [&](Slot s, const char* fallback) {
        const ir::Param* p = medium->slots.find(s);
        return p && p->present() ? v_.glsl(v_.asVec3(p->value)) : std::string(fallback);
      };
      layer.sigmaA = slot(Slot::Absorption, "vec3(0.0)");
      layer.sigmaS = slot(Slot::Scattering, "vec3(0.0)");
      if (const ir::Param* g = medium->slots.find(Slot::Anisotropy); g && g->present()) layer.g = v_.glsl(g->value);
      if (const ir::Param* c = medium->slots.find(Slot::ObservedAlbedo); c && c->present()) observedMedium(layer, *medium, *c);
      const bool scattering = medium->slots.find(Slot::Scattering) != nullptr;
      switch (medium->extent) {
        case ir::Medium::Extent::Bulk:
          if (scattering) {
            layer.thickness = "-1.0";
            layer.flags |= kHalfSpace;
          } else {
            layer.flags |= kExit;  // a clear bulk: what enters it is transmitted
          }
          break;
        case ir::Medium::Extent::Finite:
          layer.thickness = fmt::format("max({}, 0.0)", v_.glsl(v_.slot(medium->slots, Slot::Thickness, v_.constant(1.0f))));
          break;
        case ir::Medium::Extent::ThinWall:
          // A sheet: its medium, then the same interface seen from inside, under which the far
          // side is outside (OpenPBR "Thin-walled mode").
          layer.thickness = fmt::format("max({}, 0.0)", v_.glsl(v_.slot(medium->slots, Slot::Thickness, v_.constant(1.0f))));
          if (top) {
            thinWall = true;
            mirrored = layer;
            mirrored.sigmaA = "vec3(0.0)";
            mirrored.sigmaS = "vec3(0.0)";
            mirrored.thickness = "0.0";
            mirrored.flags = kExit;
            mirrored.coat = -1;
            mirrored.coverage = coverage;
            if (top->kind == InterfaceKind::Dielectric) {
              mirrored.etaCovered = mirrored.etaBare = fmt::format("1.0 / max({}, 1e-3)", layer.etaBare);
              mirrored.lobe.set("eta", mirrored.etaCovered);
            }
            mirrored.lobe.set("film", "vec3(0.0)");
          }
          break;
      }
    }
    Coat under = coat;
    if (top && top->kind == InterfaceKind::Dielectric && top->iorReference == ir::IorReference::MediumAbove) {
      under.index = static_cast<int>(stack.size());
      under.ior = v_.slot(top->slots, Slot::Ior, v_.constant(1.5f));
      under.coverage = cov;
      under.always = v_.isOne(cov);
    }
    stack.push_back(std::move(layer));
    if (thinWall) stack.push_back(std::move(mirrored));
    if (n.base == ir::kNone) {
      emitStack(stack, weight);
      return;
    }
    node(n.base, weight, std::move(stack), under);
  }

  void node(Index index, Id weight, std::vector<Layer> stack, const Coat& coat) {
    const ir::ScatterNode& n = m_.nodes[index];
    switch (n.kind) {
      case ScatterKind::Slab: slab(n, weight, std::move(stack), coat); break;
      case ScatterKind::Mix: {
        const Id w = keep("m", n.weight.value, n.weight.origin.location);
        node(n.a, v_.mul(weight, v_.oneMinus(w)), stack, coat);
        node(n.b, v_.mul(weight, w), std::move(stack), coat);
        break;
      }
      case ScatterKind::Add:
        node(n.a, weight, stack, coat);
        node(n.b, weight, std::move(stack), coat);
        break;
      case ScatterKind::Tint: node(n.a, v_.mul(weight, v_.asVec3(n.weight.value)), std::move(stack), coat); break;
      case ScatterKind::Emissive: {
        const ir::Emission& e = m_.emissions[n.emission];
        // An emitting plane over what is under it; the walk collects it on the way down.
        Layer plane;
        plane.flags = kNoInterface;
        plane.emitted = emittedRadiance(v_, e, v_.vec3(1.0f));
        plane.at = e.origin.location;
        stack.push_back(std::move(plane));
        if (n.a == ir::kNone || m_.nodes[n.a].kind == ScatterKind::Absorber) {
          emitStack(stack, weight);
        } else {
          node(n.a, weight, std::move(stack), coat);
        }
        break;
      }
      case ScatterKind::Ambient:
        out_.lines.add(fmt::format("  c.transparency += {};", v_.glsl(weight)), n.origin.location);
        break;
      // Black under the layers above (base_weight 0): they still reflect, and what crosses the
      // last of them is lost (mxc_walk: nothing under the last layer). Dropping the stack lost
      // the specular layer and coat over it too (issue 39).
      case ScatterKind::Absorber: emitStack(stack, weight); break;
    }
  }

  Id keep(const std::string& prefix, Id value, SourceLocation at) {
    const std::string name = fmt::format("{}{}", prefix, counter_++);
    out_.lines.add(fmt::format("  vec3 {} = {};", name, v_.glsl(v_.asVec3(value))), at);
    return v_.local(name, Type::Vec3);
  }

  void emitStack(const std::vector<Layer>& stack, Id weight) {
    if (stack.empty() || v_.isZero(weight)) return;
    const int first = out_.lobes;
    for (size_t k = 0; k < stack.size(); ++k) {
      const Layer& l = stack[k];
      const int i = out_.lobes++;
      writeLobe(out_.lines, fmt::format("lobe{}", counter_++), i, l.lobe, l.at, l.filmAt);
      out_.lines.add(fmt::format("  c.sigmaA[{}] = {};", i, l.sigmaA), l.at);
      out_.lines.add(fmt::format("  c.sigmaS[{}] = {};", i, l.sigmaS), l.at);
      out_.lines.add(fmt::format("  c.medium[{}] = vec4({}, {}, clamp({}, 0.0, 1.0), {}.0);", i, l.g, l.thickness,
                                 l.coverage, l.flags),
                     l.at);
      out_.lines.add(fmt::format("  c.ior[{}] = vec4({}, {}, {}.0, 0.0);", i, l.etaCovered, l.etaBare, l.coat), l.at);
      out_.lines.add(fmt::format("  c.emitted[{}] = max({}, vec3(0.0));", i, l.emitted), l.at);
    }
    out_.lines.add(fmt::format("  c.stacks[{}] = ivec2({}, {});", out_.stacks, first, static_cast<int>(stack.size())));
    out_.lines.add(fmt::format("  c.stackWeight[{}] = {};", out_.stacks, v_.glsl(v_.asVec3(weight))));
    out_.stacks++;
  }

  const ir::Material& m_;
  ClosureValues v_;
  Closure& out_;
  int counter_ = 0;
};

}  // namespace

void SlabWalk::layers(const ir::Material& material, const ExprEmitter& exprs, Closure& out) const {
  Walk(material, exprs, out).run();
}

}  // namespace mxc::glsl
