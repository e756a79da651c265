#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/ExprRewrite.h"
#include "compiler/ir/passes/Pass.h"

namespace mxc::ir {

int deadCode(Material& m, const PassContext&) {
  // Expressions: a rebuild keeps only what reachable parameters use.
  const size_t before = m.exprs.size();
  rebuildExpressions(m, [](ExprGraph&, const ExprGraph&, ExprId, const std::vector<ExprId>&) -> std::optional<ExprId> {
    return std::nullopt;
  });
  int edits = static_cast<int>(before - m.exprs.size());

  // Scattering entries: keep the reachable ones, in their order, and renumber references.
  std::vector<Index> nodes = reachableNodes(m);
  std::vector<bool> keepNode(m.nodes.size());
  for (Index i : nodes) keepNode[i] = true;
  std::vector<Index> nodeMap(m.nodes.size(), kNone), ifaceMap(m.interfaces.size(), kNone),
      mediumMap(m.media.size(), kNone), emissionMap(m.emissions.size(), kNone);
  std::vector<ScatterNode> newNodes;
  std::vector<Interface> newInterfaces;
  std::vector<Medium> newMedia;
  std::vector<Emission> newEmissions;
  for (Index i = 0; i < m.nodes.size(); ++i) {
    if (!keepNode[i]) continue;
    nodeMap[i] = static_cast<Index>(newNodes.size());
    newNodes.push_back(m.nodes[i]);
    const ScatterNode& n = m.nodes[i];
    if (n.top != kNone && ifaceMap[n.top] == kNone) {
      ifaceMap[n.top] = static_cast<Index>(newInterfaces.size());
      newInterfaces.push_back(m.interfaces[n.top]);
    }
    if (n.medium != kNone && mediumMap[n.medium] == kNone) {
      mediumMap[n.medium] = static_cast<Index>(newMedia.size());
      newMedia.push_back(m.media[n.medium]);
    }
    if (n.emission != kNone && emissionMap[n.emission] == kNone) {
      emissionMap[n.emission] = static_cast<Index>(newEmissions.size());
      newEmissions.push_back(m.emissions[n.emission]);
    }
  }
  auto map = [](const std::vector<Index>& table, Index i) { return i == kNone ? kNone : table[i]; };
  for (ScatterNode& n : newNodes) {
    n.a = map(nodeMap, n.a);
    n.b = map(nodeMap, n.b);
    n.base = map(nodeMap, n.base);
    n.top = map(ifaceMap, n.top);
    n.medium = map(mediumMap, n.medium);
    n.emission = map(emissionMap, n.emission);
  }
  edits += static_cast<int>((m.nodes.size() - newNodes.size()) + (m.interfaces.size() - newInterfaces.size()) +
                            (m.media.size() - newMedia.size()) + (m.emissions.size() - newEmissions.size()));
  m.root = map(nodeMap, m.root);
  m.nodes = std::move(newNodes);
  m.interfaces = std::move(newInterfaces);
  m.media = std::move(newMedia);
  m.emissions = std::move(newEmissions);
  return edits;
}

}  // namespace mxc::ir
