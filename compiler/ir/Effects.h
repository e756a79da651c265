#pragma once
/// \file
/// The effect summary of a material: which lobes, media and features remain after the
/// passes, each with the input that keeps it alive.

#include "compiler/ir/Material.h"

namespace mxc::ir {

/// Fills Material::effects (sorted by name): metal, specular, diffuse, subsurface,
/// transmission, volume, coat, fuzz, sheen, thin_film, emission, anisotropy, dispersion,
/// opacity, thin_walled, diffuse_transmission, layering (non-energy-bounded sums: see notes).
void summarizeEffects(Material& m);

}  // namespace mxc::ir
