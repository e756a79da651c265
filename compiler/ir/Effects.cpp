#include "compiler/ir/Effects.h"

#include <algorithm>

#include "compiler/ir/Walk.h"

namespace mxc::ir {

namespace {

bool isSpecular(InterfaceKind k) {
  return k == InterfaceKind::Dielectric || k == InterfaceKind::Conductor || k == InterfaceKind::Schlick;
}

bool nonZero(const Material& m, ExprId v) { return v != kNoExpr && !m.exprs.isConstantEqual(v, 0.0f); }

/// True unless the alpha is a constant with equal components (isotropic).
bool anisotropic(const Material& m, ExprId alpha) {
  if (alpha == kNoExpr) return false;
  const Expr& e = m.exprs[alpha];
  if (e.op == Op::Construct && e.argCount == 2 && m.exprs.arg(alpha, 0) == m.exprs.arg(alpha, 1)) return false;
  if (e.op == Op::Splat) return false;
  if (!m.exprs.isConstant(alpha)) return true;
  std::vector<float> a = m.exprs.constantComponents(alpha);
  return a.size() == 2 && a[0] != a[1];
}

/// The interface at the top of a stack (following emissive and tint wrappers), or kNone.
Index topInterface(const Material& m, Index node) {
  while (node != kNone) {
    const ScatterNode& n = m.nodes[node];
    if (n.kind == ScatterKind::Slab) return n.top;
    if (n.kind != ScatterKind::Emissive && n.kind != ScatterKind::Tint) return kNone;
    node = n.a;
  }
  return kNone;
}

}  // namespace

void summarizeEffects(Material& m) {
  std::vector<Effect> effects;
  auto add = [&](std::string name, Origin origin) {
    for (const Effect& e : effects) {
      if (e.name == name) return;
    }
    effects.push_back({std::move(name), origin});
  };
  auto coverageOr = [](const ScatterNode& n) { return n.coverage.present() ? n.coverage.origin : n.origin; };
  for (Index i : reachableNodes(m)) {
    const ScatterNode& n = m.nodes[i];
    switch (n.kind) {
      case ScatterKind::Slab: {
        const Medium* medium = n.medium != kNone ? &m.media[n.medium] : nullptr;
        if (medium) {
          if (medium->slots.find(Slot::ObservedAlbedo)) {
            add("subsurface", medium->origin);
          } else if (medium->extent == Medium::Extent::ThinWall || medium->extent == Medium::Extent::Bulk) {
            if (n.top != kNone && m.interfaces[n.top].scatter != ScatterMode::R) add("transmission", medium->origin);
            if (const Param* abbe = medium->slots.find(Slot::AbbeNumber); abbe && nonZero(m, abbe->value)) {
              add("dispersion", abbe->origin);
            }
            if (nonZero(m, medium->slots.value(Slot::Absorption)) || nonZero(m, medium->slots.value(Slot::Scattering))) {
              add("volume", medium->slots.find(Slot::Absorption) ? medium->slots.find(Slot::Absorption)->origin
                                                                   : medium->origin);
            }
          }
        }
        if (n.top == kNone) break;
        const Interface& iface = m.interfaces[n.top];
        switch (iface.kind) {
          case InterfaceKind::Dielectric: {
            Index under = topInterface(m, n.base);
            const bool coat = (medium && medium->extent == Medium::Extent::Finite) ||
                              (under != kNone && isSpecular(m.interfaces[under].kind));
            if (coat) {
              add("coat", coverageOr(n));
            } else {
              add("specular", coverageOr(n));
            }
            if (!medium && n.base == kNone && iface.scatter != ScatterMode::R) add("transmission", n.origin);
            break;
          }
          case InterfaceKind::Conductor:
          case InterfaceKind::Schlick: add("metal", coverageOr(n)); break;
          case InterfaceKind::Diffuse:
          case InterfaceKind::Burley: add("diffuse", coverageOr(n)); break;
          case InterfaceKind::DiffuseTransmission: add("diffuse_transmission", coverageOr(n)); break;
          case InterfaceKind::DiffuseSheet: add("subsurface", coverageOr(n)); break;
          case InterfaceKind::Sheen: add(iface.sheenModel == SheenModel::Zeltner ? "fuzz" : "sheen", coverageOr(n)); break;
        }
        if (iface.thinFilm.present()) {
          const ThinFilm& film = iface.thinFilm;
          add("thin_film", film.coverage.present() ? film.coverage.origin
                           : film.origin.location.valid() ? film.origin
                                                          : film.thickness.origin);
        }
        if (const Param* alpha = iface.slots.find(Slot::Alpha); alpha && anisotropic(m, alpha->value)) {
          add("anisotropy", alpha->origin);
        }
        break;
      }
      case ScatterKind::Emissive:
        if (n.emission != kNone) {
          const Param* color = m.emissions[n.emission].slots.find(Slot::Color);
          add("emission", color ? color->origin : n.origin);
        }
        break;
      case ScatterKind::Mix:
        if ((n.a != kNone && m.nodes[n.a].kind == ScatterKind::Ambient) ||
            (n.b != kNone && m.nodes[n.b].kind == ScatterKind::Ambient)) {
          add("opacity", n.weight.origin);
        }
        break;
      case ScatterKind::Add:
      case ScatterKind::Tint: add("unbounded_sum", n.origin); break;
      case ScatterKind::Ambient:
      case ScatterKind::Absorber: break;
    }
  }
  if (m.thinWalled.present() && !m.exprs.isConstantEqual(m.thinWalled.value, 0.0f)) add("thin_walled", m.thinWalled.origin);
  std::sort(effects.begin(), effects.end(), [](const Effect& a, const Effect& b) { return a.name < b.name; });
  m.effects = std::move(effects);
}

}  // namespace mxc::ir
