#pragma once
/// \file
/// The layering of the fast and balanced tiers: the slab tree reduced to a weighted mixture of lobes,
/// after OpenPBR 1.1 "Reduction to a mixture of lobes": each layer passes what its top does not
/// reflect, 1 - E(wo), to the layers under it (albedo scaling), with coat darkening from the
/// coat's internal reflections (OpenPBR "Darkening") and view-dependent absorption through
/// coat media (OpenPBR "View-dependent absorption").

#include "compiler/glsl/ClosureEmitter.h"

namespace mxc::glsl {

class AlbedoScaling : public LayeringTier {
 public:
  void layers(const ir::Material& material, const ExprEmitter& exprs, Closure& out) const override;
};

}  // namespace mxc::glsl
