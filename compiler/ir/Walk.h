#pragma once
/// \file
/// Visiting what a material refers to: its parameters (every expression root) and the
/// scattering nodes reachable from its root.

#include <vector>

#include "compiler/ir/Material.h"

namespace mxc::ir {

/// Calls f(Param&) for every parameter of the material that is reachable from its root
/// (slot parameters, thin films, coverages, weights, emission), and for the material's own
/// opacity and thin-walled parameters.
template <typename F>
void forEachReachableParam(Material& m, F f);

/// Scattering nodes reachable from the root, each once, parents before children.
std::vector<Index> reachableNodes(const Material& m);

template <typename F>
void forEachSlotParam(Slots& slots, F& f) {
  for (auto& [slot, param] : slots.all()) f(param);
}

template <typename F>
void forEachReachableParam(Material& m, F f) {
  std::vector<Index> nodes = reachableNodes(m);
  std::vector<bool> seenInterface(m.interfaces.size()), seenMedium(m.media.size()), seenEmission(m.emissions.size());
  for (Index i : nodes) {
    ScatterNode& n = m.nodes[i];
    f(n.coverage);
    f(n.weight);
    if (n.top != kNone && !seenInterface[n.top]) {
      seenInterface[n.top] = true;
      Interface& iface = m.interfaces[n.top];
      forEachSlotParam(iface.slots, f);
      f(iface.thinFilm.thickness);
      f(iface.thinFilm.ior);
      f(iface.thinFilm.coverage);
    }
    if (n.medium != kNone && !seenMedium[n.medium]) {
      seenMedium[n.medium] = true;
      forEachSlotParam(m.media[n.medium].slots, f);
    }
    if (n.emission != kNone && !seenEmission[n.emission]) {
      seenEmission[n.emission] = true;
      forEachSlotParam(m.emissions[n.emission].slots, f);
    }
  }
  f(m.opacity);
  f(m.thinWalled);
}

}  // namespace mxc::ir
