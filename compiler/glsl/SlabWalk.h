#pragma once
/// \file
/// The layering of the reference tier: the slab tree kept as what it is, a weighted mixture of
/// slab stacks (one per path from the root through mixes to a bottom), each a run of layers
/// (an interface over its medium, with its coverage), which the shader library walks by Monte
/// Carlo (compiler/glsl/library/mxc_walk.glsl; docs/reference-tier.md).

#include "compiler/glsl/ClosureEmitter.h"

namespace mxc::glsl {

class SlabWalk : public LayeringTier {
 public:
  void layers(const ir::Material& material, const ExprEmitter& exprs, Closure& out) const override;
};

}  // namespace mxc::glsl
