#include "compiler/ir/Features.h"

#include "compiler/ir/Material.h"
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

std::string_view lobeKindName(LobeKind kind) {
  switch (kind) {
    case LobeKind::Dielectric: return "DIELECTRIC";
    case LobeKind::Conductor: return "CONDUCTOR";
    case LobeKind::Schlick: return "SCHLICK";
    case LobeKind::Diffuse: return "DIFFUSE";
    case LobeKind::EON: return "EON";
    case LobeKind::Burley: return "BURLEY";
    case LobeKind::Translucent: return "TRANSLUCENT";
    case LobeKind::Sheet: return "SHEET";
    case LobeKind::Sheen: return "SHEEN";
    case LobeKind::Fuzz: return "FUZZ";
    case LobeKind::Hair: return "HAIR";
    case LobeKind::Count: break;
  }
  return "?";
}

LobeKind lobeKindOf(const Interface& f) {
  switch (f.kind) {
    case InterfaceKind::Dielectric: return LobeKind::Dielectric;
    case InterfaceKind::Conductor: return LobeKind::Conductor;
    case InterfaceKind::Schlick: return LobeKind::Schlick;
    case InterfaceKind::Diffuse: return f.diffuseModel == DiffuseModel::EON ? LobeKind::EON : LobeKind::Diffuse;
    case InterfaceKind::Burley: return LobeKind::Burley;
    case InterfaceKind::DiffuseTransmission: return LobeKind::Translucent;
    case InterfaceKind::DiffuseSheet: return LobeKind::Sheet;
    case InterfaceKind::Sheen: return f.sheenModel == SheenModel::Zeltner ? LobeKind::Fuzz : LobeKind::Sheen;
    case InterfaceKind::Hair: return LobeKind::Hair;
  }
  return LobeKind::EON;
}

std::string_view effectName(Effect effect) {
  switch (effect) {
    case Effect::Anisotropy: return "anisotropy";
    case Effect::Coat: return "coat";
    case Effect::Diffuse: return "diffuse";
    case Effect::DiffuseTransmission: return "diffuse_transmission";
    case Effect::Dispersion: return "dispersion";
    case Effect::Emission: return "emission";
    case Effect::Fuzz: return "fuzz";
    case Effect::Hair: return "hair";
    case Effect::Metal: return "metal";
    case Effect::Opacity: return "opacity";
    case Effect::Sheen: return "sheen";
    case Effect::Specular: return "specular";
    case Effect::Subsurface: return "subsurface";
    case Effect::ThinFilm: return "thin_film";
    case Effect::ThinWalled: return "thin_walled";
    case Effect::Transmission: return "transmission";
    case Effect::UnboundedSum: return "unbounded_sum";
    case Effect::Volume: return "volume";
    case Effect::Count: break;
  }
  return "?";
}

Features computeFeatures(const Material& m) {
  Features features;
  // The first origin found for an effect is kept (parents before children).
  auto add = [&](Effect effect, Origin origin) {
    if (features.effects.has(effect)) return;
    features.effects.insert(effect);
    features.origins[static_cast<size_t>(effect)] = origin;
  };
  auto coverageOr = [](const ScatterNode& n) { return n.coverage.present() ? n.coverage.origin : n.origin; };
  for (Index i : reachableNodes(m)) {
    const ScatterNode& n = m.nodes[i];
    switch (n.kind) {
      case ScatterKind::Slab: {
        const Medium* medium = n.medium != kNone ? &m.media[n.medium] : nullptr;
        if (medium) {
          if (medium->slots.find(Slot::ObservedAlbedo)) {
            add(Effect::Subsurface, medium->origin);
            features.lobes.insert(LobeKind::EON);  // a dense bulk seen from outside: a diffuse lobe of its albedo
          } else if (medium->extent == Medium::Extent::ThinWall || medium->extent == Medium::Extent::Bulk) {
            if (n.top != kNone && m.interfaces[n.top].scatter != ScatterMode::R) add(Effect::Transmission, medium->origin);
            if (const Param* abbe = medium->slots.find(Slot::AbbeNumber); abbe && nonZero(m, abbe->value)) {
              add(Effect::Dispersion, abbe->origin);
            }
            if (nonZero(m, medium->slots.value(Slot::Absorption)) || nonZero(m, medium->slots.value(Slot::Scattering))) {
              add(Effect::Volume, medium->slots.find(Slot::Absorption) ? medium->slots.find(Slot::Absorption)->origin
                                                                   : medium->origin);
            }
          }
        }
        if (n.top == kNone) break;
        const Interface& iface = m.interfaces[n.top];
        features.lobes.insert(lobeKindOf(iface));
        features.thinFilm = features.thinFilm || iface.thinFilm.present();
        switch (iface.kind) {
          case InterfaceKind::Dielectric: {
            Index under = topInterface(m, n.base);
            const bool coat = (medium && medium->extent == Medium::Extent::Finite) ||
                              (under != kNone && isSpecular(m.interfaces[under].kind));
            if (coat) {
              add(Effect::Coat, coverageOr(n));
            } else {
              add(Effect::Specular, coverageOr(n));
            }
            if (!medium && n.base == kNone && iface.scatter != ScatterMode::R) add(Effect::Transmission, n.origin);
            break;
          }
          case InterfaceKind::Conductor: add(Effect::Metal, coverageOr(n)); break;
          // A Schlick reflection over something is a specular layer (the dielectric specular of
          // Disney's and USD's specular workflow, a layered generalized_schlick_bsdf); at the
          // bottom of its stack it is a metal.
          case InterfaceKind::Schlick: add(n.base != kNone ? Effect::Specular : Effect::Metal, coverageOr(n)); break;
          case InterfaceKind::Diffuse:
          case InterfaceKind::Burley: add(Effect::Diffuse, coverageOr(n)); break;
          case InterfaceKind::DiffuseTransmission: add(Effect::DiffuseTransmission, coverageOr(n)); break;
          case InterfaceKind::DiffuseSheet: add(Effect::Subsurface, coverageOr(n)); break;
          case InterfaceKind::Sheen: add(iface.sheenModel == SheenModel::Zeltner ? Effect::Fuzz : Effect::Sheen, coverageOr(n)); break;
          case InterfaceKind::Hair: add(Effect::Hair, coverageOr(n)); break;
        }
        if (iface.thinFilm.present()) {
          const ThinFilm& film = iface.thinFilm;
          add(Effect::ThinFilm, film.coverage.present() ? film.coverage.origin
                           : film.origin.location.valid() ? film.origin
                                                          : film.thickness.origin);
        }
        if (const Param* alpha = iface.slots.find(Slot::Alpha); alpha && anisotropic(m, alpha->value)) {
          add(Effect::Anisotropy, alpha->origin);
        }
        break;
      }
      case ScatterKind::Emissive:
        features.emission = true;
        if (n.emission != kNone) {
          const Param* color = m.emissions[n.emission].slots.find(Slot::Color);
          add(Effect::Emission, color ? color->origin : n.origin);
        }
        break;
      case ScatterKind::Mix:
        if ((n.a != kNone && m.nodes[n.a].kind == ScatterKind::Ambient) ||
            (n.b != kNone && m.nodes[n.b].kind == ScatterKind::Ambient)) {
          add(Effect::Opacity, n.weight.origin);
        }
        break;
      case ScatterKind::Add:
      case ScatterKind::Tint: add(Effect::UnboundedSum, n.origin); break;
      case ScatterKind::Ambient: features.transparency = true; break;
      case ScatterKind::Absorber: break;
    }
  }
  if (m.thinWalled.present() && !m.exprs.isConstantEqual(m.thinWalled.value, 0.0f)) add(Effect::ThinWalled, m.thinWalled.origin);
  return features;
}

}  // namespace mxc::ir
