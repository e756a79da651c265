#include <algorithm>

#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

int commonSubexpressions(Material& m, const PassContext&) {
  int edits = 0;
  std::vector<Index> nodes = reachableNodes(m);
  // Interfaces, media and emissions: the first of equal ones serves all (quadratic in the
  // number of distinct entries, which stays small: tens per material).
  auto dedupe = [&](auto same, auto member) {
    std::vector<Index> seen;
    for (Index i : nodes) {
      Index& ref = m.nodes[i].*member;
      if (ref == kNone) continue;
      for (Index s : seen) {
        if (s != ref && same(m, s, ref)) {
          ref = s;
          ++edits;
          break;
        }
      }
      if (std::find(seen.begin(), seen.end(), ref) == seen.end()) seen.push_back(ref);
    }
  };
  dedupe([](const Material& mm, Index a, Index b) { return sameInterface(mm, a, b); }, &ScatterNode::top);
  dedupe(sameMedium, &ScatterNode::medium);
  dedupe(sameEmission, &ScatterNode::emission);

  // Scattering nodes, children first: equal kind, children, entries and parameters.
  std::vector<Index> replacement(m.nodes.size(), kNone);
  std::vector<Index> canonical;
  auto resolved = [&](Index i) { return i != kNone && replacement[i] != kNone ? replacement[i] : i; };
  for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
    ScatterNode& n = m.nodes[*it];
    n.a = resolved(n.a);
    n.b = resolved(n.b);
    n.base = resolved(n.base);
    for (Index c : canonical) {
      const ScatterNode& o = m.nodes[c];
      if (o.kind == n.kind && o.top == n.top && o.medium == n.medium && o.base == n.base && o.a == n.a && o.b == n.b &&
          o.emission == n.emission && o.coverage.value == n.coverage.value && o.weight.value == n.weight.value) {
        replacement[*it] = c;
        break;
      }
    }
    if (replacement[*it] == kNone) canonical.push_back(*it);
  }
  edits += redirect(m, replacement);
  return edits;
}

}  // namespace mxc::ir
