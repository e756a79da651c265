#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/ir/passes/ScatterRewrite.h"

namespace mxc::ir {

namespace {

// The normal form can grow as the product of the mixes under each slab; a material beyond
// this many nodes keeps its factored form (and says so).
constexpr size_t kMaxNodes = 4096;

}  // namespace

int distributeOverMix(Material& m, const PassContext&) {
  std::vector<Index> nodes = reachableNodes(m);
  if (nodes.size() > kMaxNodes) {
    // A string object, not a literal, is copied in: GCC 12 inlines the copy of a long literal
    // into a std::string and then warns of bounds it does not exceed (-Warray-bounds).
    static const std::string kTooLarge = "the scattering tree is too large to distribute into slab stacks; it stays factored";
    bool noted = false;
    for (const Note& note : m.notes) noted = noted || note.message == kTooLarge;
    if (!noted) m.notes.push_back(Note{kTooLarge, m.origin});
    return 0;
  }
  std::vector<Index> replacement(m.nodes.size(), kNone);
  for (Index i : nodes) {
    const ScatterNode n = m.nodes[i];
    Index child = n.kind == ScatterKind::Slab ? n.base
                  : (n.kind == ScatterKind::Emissive || n.kind == ScatterKind::Tint) ? n.a
                                                                                      : kNone;
    if (child == kNone || m.nodes[child].kind != ScatterKind::Mix) continue;
    const ScatterNode mix = m.nodes[child];
    // X(mix(a, b, w)) = mix(X(a), X(b), w) for X linear in its child (slab, emissive, tint).
    ScatterNode left = n;
    ScatterNode right = n;
    if (n.kind == ScatterKind::Slab) {
      left.base = mix.a;
      right.base = mix.b;
    } else {
      left.a = mix.a;
      right.a = mix.b;
    }
    Index l = m.addNode(std::move(left));
    Index r = m.addNode(std::move(right));
    replacement[i] = m.mix(l, r, mix.weight, mix.origin);
  }
  replacement.resize(m.nodes.size(), kNone);
  return redirect(m, replacement);
}

}  // namespace mxc::ir
