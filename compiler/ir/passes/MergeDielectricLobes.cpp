#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

namespace {

bool isDielectric(const Material& m, Index iface, ScatterMode mode) {
  return iface != kNone && m.interfaces[iface].kind == InterfaceKind::Dielectric && m.interfaces[iface].scatter == mode;
}

/// The reflection and transmission nodes of one physical interface: same IOR, roughness,
/// normal, tangent, Fresnel scale and thin film (tints may differ: they are per lobe).
bool sameSurface(const Material& m, Index r, Index t) {
  const Interface& a = m.interfaces[r];
  const Interface& b = m.interfaces[t];
  for (Slot s : {Slot::Ior, Slot::Alpha, Slot::Normal, Slot::Tangent, Slot::FresnelScale}) {
    if (a.slots.value(s) != b.slots.value(s)) return false;
  }
  // A film on the reflection node only is the same interface: a thin film is a property of the
  // interface's Fresnel and shapes its transmission too (OpenPBR "Thin-film iridescence").
  const bool filmMatches = !b.thinFilm.present() || (a.thinFilm.thickness.value == b.thinFilm.thickness.value &&
                                                     a.thinFilm.ior.value == b.thinFilm.ior.value &&
                                                     a.thinFilm.coverage.value == b.thinFilm.coverage.value);
  return a.iorReference == b.iorReference && filmMatches;
}

}  // namespace

int mergeDielectricLobes(Material& m, const PassContext&) {
  int edits = 0;
  for (Index i : reachableNodes(m)) {
    ScatterNode n = m.nodes[i];
    if (n.kind != ScatterKind::Slab || n.base == kNone || n.medium != kNone) continue;
    const ScatterNode& under = m.nodes[n.base];
    if (under.kind != ScatterKind::Slab || under.coverage.present()) continue;
    if (isDielectric(m, n.top, ScatterMode::R) && isDielectric(m, under.top, ScatterMode::T) &&
        sameSurface(m, n.top, under.top)) {
      // layer(dielectric R, Slab(dielectric T, V)) -> Slab(dielectric RT, V).
      Interface merged = m.interfaces[n.top];
      merged.scatter = ScatterMode::RT;
      if (const Param* tint = m.interfaces[under.top].slots.find(Slot::TransmissionTint)) {
        merged.slots.set(Slot::TransmissionTint, *tint);
      }
      n.top = m.addInterface(std::move(merged));
      n.medium = under.medium;
      n.base = under.base;
      m.nodes[i] = n;
      ++edits;
    } else if (under.top == kNone && under.medium != kNone && !n.coverage.present()) {
      // layer(interface, index-matched medium) -> the medium lies under that interface. Not
      // under a layer with coverage (OpenPBR "Coverage"): where such a layer is absent the
      // medium is still there, so it cannot be that layer's (Standard Surface's sheen over
      // its subsurface bulk: with sheen 0 the bulk would go with the absent sheen).
      n.medium = under.medium;
      n.base = under.base;
      m.nodes[i] = n;
      ++edits;
    }
  }
  // A reflection-only dielectric with something under it transmits into it: layering gives
  // the transmitted light to the base (OpenPBR "Layering"), so it is the RT interface.
  for (Index i : reachableNodes(m)) {
    const ScatterNode& n = m.nodes[i];
    if (n.kind != ScatterKind::Slab || (n.base == kNone && n.medium == kNone)) continue;
    if (!isDielectric(m, n.top, ScatterMode::R)) continue;
    Interface rt = m.interfaces[n.top];
    rt.scatter = ScatterMode::RT;
    Index top = m.addInterface(std::move(rt));
    m.nodes[i].top = top;
    ++edits;
  }
  return edits;
}

}  // namespace mxc::ir
