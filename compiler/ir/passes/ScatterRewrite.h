#pragma once
/// \file
/// Helpers of the scattering passes: redirecting references, comparing subtrees, copying.

#include <vector>

#include "compiler/ir/Material.h"

namespace mxc::ir {

/// Redirects every reference to node i to replacement[i] (kNone keeps i), following chains.
/// Returns how many nodes were replaced.
int redirect(Material& m, const std::vector<Index>& replacement);

/// True when two interfaces have the same kind, modes and parameters. `ignoreThinFilm` leaves
/// the thin films out of the comparison.
bool sameInterface(const Material& m, Index a, Index b, bool ignoreThinFilm = false);
bool sameMedium(const Material& m, Index a, Index b);
bool sameEmission(const Material& m, Index a, Index b);

}  // namespace mxc::ir
