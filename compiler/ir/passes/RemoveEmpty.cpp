// Small passes that drop parts with no effect: media that neither absorb nor scatter, thin
// films of no thickness or coverage, slots at their default value, and emission of no colour.

#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

namespace {

bool zeroOrAbsent(const Material& m, const Slots& slots, Slot slot) {
  ExprId v = slots.value(slot);
  return v == kNoExpr || m.exprs.isConstantEqual(v, 0.0f);
}

}  // namespace

int removeEmptyMedia(Material& m, const PassContext&) {
  int edits = 0;
  for (Index i : reachableNodes(m)) {
    ScatterNode& n = m.nodes[i];
    if (n.kind != ScatterKind::Slab || n.medium == kNone) continue;
    const Medium& medium = m.media[n.medium];
    // A thin-walled sheet keeps its meaning (un-deflected transmission) even when clear.
    if (medium.extent == Medium::Extent::ThinWall) continue;
    // A bulk dielectric keeps its medium while it refracts: it carries the IOR and dispersion.
    const bool refracting = medium.slots.find(Slot::Ior) || medium.slots.find(Slot::AbbeNumber);
    if (!refracting && zeroOrAbsent(m, medium.slots, Slot::Absorption) && zeroOrAbsent(m, medium.slots, Slot::Scattering)) {
      n.medium = kNone;
      ++edits;
    }
  }
  return edits;
}

int removeThinFilm(Material& m, const PassContext&) {
  int edits = 0;
  std::vector<bool> seen(m.interfaces.size());
  for (Index i : reachableNodes(m)) {
    Index top = m.nodes[i].top;
    if (top == kNone || seen[top]) continue;
    seen[top] = true;
    ThinFilm& film = m.interfaces[top].thinFilm;
    if (!film.present()) continue;
    if (m.exprs.isConstantEqual(film.thickness.value, 0.0f) ||
        (film.coverage.present() && m.exprs.isConstantEqual(film.coverage.value, 0.0f))) {
      film = {};
      ++edits;
    } else if (film.coverage.present() && m.exprs.isConstantEqual(film.coverage.value, 1.0f)) {
      film.coverage = {};
      ++edits;
    }
  }
  return edits;
}

int removeDefaultSlots(Material& m, const PassContext&) {
  int edits = 0;
  auto prune = [&](Slots& slots) {
    std::vector<Slot> drop;
    for (const auto& [slot, p] : slots.all()) {
      std::optional<float> d = slotDefault(slot);
      if (d && p.present() && m.exprs.isConstantEqual(p.value, *d)) drop.push_back(slot);
    }
    for (Slot s : drop) slots.erase(s);
    edits += static_cast<int>(drop.size());
  };
  std::vector<bool> seenInterface(m.interfaces.size()), seenMedium(m.media.size());
  for (Index i : reachableNodes(m)) {
    const ScatterNode& n = m.nodes[i];
    if (n.top != kNone && !seenInterface[n.top]) {
      seenInterface[n.top] = true;
      prune(m.interfaces[n.top].slots);
    }
    if (n.medium != kNone && !seenMedium[n.medium]) {
      seenMedium[n.medium] = true;
      prune(m.media[n.medium].slots);
    }
  }
  return edits;
}

int removeDarkEmission(Material& m, const PassContext&) {
  std::vector<Index> replacement(m.nodes.size(), kNone);
  for (Index i : reachableNodes(m)) {
    const ScatterNode& n = m.nodes[i];
    if (n.kind != ScatterKind::Emissive) continue;
    if (n.emission == kNone || zeroOrAbsent(m, m.emissions[n.emission].slots, Slot::Color)) replacement[i] = n.a;
  }
  return redirect(m, replacement);
}

}  // namespace mxc::ir
