#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"

namespace mxc::ir {

int bulkUnderTransmission(Material& m, const PassContext&) {
  int edits = 0;
  const bool thinWalled = m.thinWalled.present() && m.exprs.isConstantEqual(m.thinWalled.value, 1.0f);
  for (Index i : reachableNodes(m)) {
    const ScatterNode& n = m.nodes[i];
    if (n.kind != ScatterKind::Slab || n.base != kNone || n.medium != kNone || n.top == kNone) continue;
    const Interface& top = m.interfaces[n.top];
    if (top.kind != InterfaceKind::Dielectric || top.scatter == ScatterMode::R) continue;
    // Light the interface transmits enters the bulk under it: a clear dielectric of the
    // interface's IOR (OpenPBR "Slabs": the medium carries the IOR), or a thin sheet when the
    // surface is thin-walled.
    Medium bulk;
    bulk.extent = thinWalled ? Medium::Extent::ThinWall : Medium::Extent::Bulk;
    bulk.origin = top.origin;
    if (!thinWalled) {
      if (const Param* ior = top.slots.find(Slot::Ior)) bulk.slots.set(Slot::Ior, *ior);
    }
    Index medium = m.addMedium(std::move(bulk));
    m.nodes[i].medium = medium;
    ++edits;
  }
  return edits;
}

}  // namespace mxc::ir
