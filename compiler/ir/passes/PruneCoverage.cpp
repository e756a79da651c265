#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

int pruneCoverage(Material& m, const PassContext&) {
  int edits = 0;
  std::vector<Index> replacement(m.nodes.size(), kNone);
  Index absorber = kNone;
  for (Index i : reachableNodes(m)) {
    ScatterNode& n = m.nodes[i];
    if (n.kind != ScatterKind::Slab || !n.coverage.present()) continue;
    if (m.exprs.isConstantEqual(n.coverage.value, 0.0f)) {
      // Absent slab: what is under it shows; with nothing under it, nothing is reflected.
      if (n.base != kNone) {
        replacement[i] = n.base;
      } else {
        if (absorber == kNone) absorber = m.leaf(ScatterKind::Absorber, n.origin);
        replacement[i] = absorber;
      }
    } else if (m.exprs.isConstantEqual(n.coverage.value, 1.0f)) {
      n.coverage = {};  // full coverage is the default
      ++edits;
    }
  }
  replacement.resize(m.nodes.size(), kNone);
  return edits + redirect(m, replacement);
}

}  // namespace mxc::ir
