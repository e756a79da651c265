#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

namespace {

bool sameSlots(const Slots& a, const Slots& b) {
  if (a.all().size() != b.all().size()) return false;
  for (const auto& [slot, param] : a.all()) {
    if (b.value(slot) != param.value) return false;
  }
  return true;
}

}  // namespace

int redirect(Material& m, const std::vector<Index>& replacement) {
  auto resolve = [&](Index i) {
    // Chains end because every replacement points at a node that is not replaced itself,
    // or at a strictly deeper one; the bound guards against a pass making a loop.
    for (int guard = 0; i != kNone && i < replacement.size() && replacement[i] != kNone && guard < 1 << 16; ++guard) {
      i = replacement[i];
    }
    return i;
  };
  int edits = 0;
  for (Index r : replacement) edits += r != kNone;
  for (ScatterNode& n : m.nodes) {
    n.base = resolve(n.base);
    n.a = resolve(n.a);
    n.b = resolve(n.b);
  }
  m.root = resolve(m.root);
  return edits;
}

bool sameInterface(const Material& m, Index a, Index b, bool ignoreThinFilm) {
  if (a == b) return true;
  if (a == kNone || b == kNone) return false;
  const Interface& x = m.interfaces[a];
  const Interface& y = m.interfaces[b];
  if (x.kind != y.kind || x.scatter != y.scatter || x.diffuseModel != y.diffuseModel || x.sheenModel != y.sheenModel ||
      x.iorReference != y.iorReference || !sameSlots(x.slots, y.slots)) {
    return false;
  }
  if (ignoreThinFilm) return true;
  return x.thinFilm.thickness.value == y.thinFilm.thickness.value && x.thinFilm.ior.value == y.thinFilm.ior.value &&
         x.thinFilm.coverage.value == y.thinFilm.coverage.value;
}

bool sameMedium(const Material& m, Index a, Index b) {
  if (a == b) return true;
  if (a == kNone || b == kNone) return false;
  return m.media[a].extent == m.media[b].extent && sameSlots(m.media[a].slots, m.media[b].slots);
}

bool sameEmission(const Material& m, Index a, Index b) {
  if (a == b) return true;
  if (a == kNone || b == kNone) return false;
  return m.emissions[a].kind == m.emissions[b].kind && sameSlots(m.emissions[a].slots, m.emissions[b].slots);
}

}  // namespace mxc::ir
