#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

int collapseMix(Material& m, const PassContext&) {
  std::vector<Index> replacement(m.nodes.size(), kNone);
  Index absorber = kNone;
  auto isAbsorber = [&](Index i) { return i != kNone && m.nodes[i].kind == ScatterKind::Absorber; };
  for (Index i : reachableNodes(m)) {
    const ScatterNode& n = m.nodes[i];
    switch (n.kind) {
      case ScatterKind::Mix:
        if (m.exprs.isConstantEqual(n.weight.value, 0.0f)) replacement[i] = n.a;
        else if (m.exprs.isConstantEqual(n.weight.value, 1.0f)) replacement[i] = n.b;
        else if (n.a == n.b) replacement[i] = n.a;
        else if (isAbsorber(n.a) && isAbsorber(n.b)) replacement[i] = n.a;
        break;
      case ScatterKind::Add:
        if (isAbsorber(n.a)) replacement[i] = n.b;
        else if (isAbsorber(n.b)) replacement[i] = n.a;
        break;
      case ScatterKind::Tint:
        if (m.exprs.isConstantEqual(n.weight.value, 1.0f)) {
          replacement[i] = n.a;
        } else if (m.exprs.isConstantEqual(n.weight.value, 0.0f)) {
          if (absorber == kNone) absorber = m.leaf(ScatterKind::Absorber, n.origin);
          replacement[i] = absorber;
        }
        break;
      default:
        break;
    }
  }
  replacement.resize(m.nodes.size(), kNone);
  return redirect(m, replacement);
}

}  // namespace mxc::ir
