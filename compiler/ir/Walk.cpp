#include "compiler/ir/Walk.h"

namespace mxc::ir {

std::vector<Index> reachableNodes(const Material& m) {
  std::vector<Index> order;
  if (m.root == kNone) return order;
  std::vector<bool> seen(m.nodes.size());
  std::vector<Index> stack{m.root};
  while (!stack.empty()) {
    Index i = stack.back();
    stack.pop_back();
    if (i == kNone || seen[i]) continue;
    seen[i] = true;
    order.push_back(i);
    const ScatterNode& n = m.nodes[i];
    // Push children in reverse so the first child is visited first.
    for (Index child : {n.b, n.a, n.base}) {
      if (child != kNone) stack.push_back(child);
    }
  }
  return order;
}

}  // namespace mxc::ir
