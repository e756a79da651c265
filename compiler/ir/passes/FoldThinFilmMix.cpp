#include "compiler/ir/ExprBuilder.h"
#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

namespace {

/// Compares two subtrees; they may differ only in that, at one interface, `b` has a thin film
/// that `a` lacks (recorded in filmA/filmB). Returns false for any other difference.
bool differByThinFilm(const Material& m, Index a, Index b, Index& filmA, Index& filmB) {
  if (a == b) return true;
  if (a == kNone || b == kNone) return false;
  const ScatterNode& x = m.nodes[a];
  const ScatterNode& y = m.nodes[b];
  if (x.kind != y.kind || x.coverage.value != y.coverage.value || x.weight.value != y.weight.value ||
      !sameMedium(m, x.medium, y.medium) || !sameEmission(m, x.emission, y.emission)) {
    return false;
  }
  if (x.top != y.top && !sameInterface(m, x.top, y.top)) {
    // The one allowed difference: the same interface, with a film only on b's side.
    const bool filmOnlyOnB = sameInterface(m, x.top, y.top, true) && !m.interfaces[x.top].thinFilm.present() &&
                             m.interfaces[y.top].thinFilm.present();
    const bool firstOrSame = filmA == kNone || (filmA == x.top && filmB == y.top);
    if (!filmOnlyOnB || !firstOrSame) return false;
    filmA = x.top;
    filmB = y.top;
  }
  return differByThinFilm(m, x.base, y.base, filmA, filmB) && differByThinFilm(m, x.a, y.a, filmA, filmB) &&
         differByThinFilm(m, x.b, y.b, filmA, filmB);
}

}  // namespace

int foldThinFilmMix(Material& m, const PassContext&) {
  std::vector<Index> replacement(m.nodes.size(), kNone);
  for (Index i : reachableNodes(m)) {
    const ScatterNode n = m.nodes[i];
    if (n.kind != ScatterKind::Mix) continue;
    // mix(without, with, w): the film's coverage is w; mix(with, without, w): it is 1 - w.
    for (bool filmOnB : {true, false}) {
      Index without = filmOnB ? n.a : n.b;
      Index with = filmOnB ? n.b : n.a;
      Index filmA = kNone, filmB = kNone;
      if (!differByThinFilm(m, without, with, filmA, filmB) || filmB == kNone) continue;
      ExprBuilder b(m.exprs);
      Interface filmed = m.interfaces[filmB];
      ExprId w = filmOnB ? n.weight.value : b.oneMinus(n.weight.value);
      ExprId coverage = filmed.thinFilm.coverage.present() ? b.mul(filmed.thinFilm.coverage.value, w) : w;
      filmed.thinFilm.coverage = {coverage, n.weight.origin};
      Index newTop = m.addInterface(std::move(filmed));
      // The subtree with the film (and only it) now uses the interface carrying the coverage.
      std::vector<Index> stack{with};
      std::vector<bool> seen(m.nodes.size());
      while (!stack.empty()) {
        Index j = stack.back();
        stack.pop_back();
        if (j == kNone || seen[j]) continue;
        seen[j] = true;
        if (m.nodes[j].top == filmB) m.nodes[j].top = newTop;
        for (Index child : {m.nodes[j].a, m.nodes[j].b, m.nodes[j].base}) stack.push_back(child);
      }
      replacement[i] = with;
      break;
    }
    if (replacement[i] != kNone) break;  // one fold per round: the tree changed under us
  }
  return redirect(m, replacement);
}

}  // namespace mxc::ir
