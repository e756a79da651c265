#pragma once
/// \file
/// The scattering tree of a material to GLSL that fills an MxcClosure for a view direction.
/// How the layers of the tree combine is the accuracy tier's (Accuracy, a LayeringTier); what
/// an interface is as a lobe (LobeMapping.h) and the algebra of the closure's weights
/// (ClosureValues.h) every tier shares.

#include "compiler/common/Accuracy.h"
#include "compiler/glsl/ExprEmitter.h"
#include "compiler/ir/Material.h"

namespace mxc::glsl {

/// The closure code of a material.
struct Closure {
  /// The body of `void mxc_material_closure(in MxcGeometry g, vec3 wo, out MxcClosure c)`
  /// after the expression statements.
  Lines lines;
  /// How many lobes it holds (MXC_MAX_LOBES). Which kinds, and whether a thin film is used,
  /// the material's features say (ir::Features).
  int lobes = 0;
  /// The reference tier: how many slab stacks it holds (MXC_MAX_STACKS); 0 for the others.
  int stacks = 0;
  /// The modes of its lobes OR'd together (kModeReflect, kModeTransmit, kModeThinWall): without
  /// kModeTransmit the library's refraction code is not compiled (MXC_TRANSMISSION).
  int modes = 0;
  /// A lobe lies under an absorbing medium (an optical depth that is not constant 0): the
  /// library computes the absorption along wi (MXC_ABSORPTION).
  bool absorbs = false;
};

/// How an accuracy tier turns a material's slab tree into lobes with weights.
class LayeringTier {
 public:
  virtual ~LayeringTier() = default;
  /// Appends to `out` the statements that fill the lobes, emission and transparency of `c`
  /// (between the closure's opening and its `c.count` and preparation), counting the lobes.
  virtual void layers(const ir::Material& material, const ExprEmitter& exprs, Closure& out) const = 0;
};

/// The tier of an accuracy level.
const LayeringTier& layeringTier(Accuracy accuracy);

/// The closure of a material at an accuracy level.
Closure buildClosure(const ir::Material& material, const ExprEmitter& exprs, Accuracy accuracy);

}  // namespace mxc::glsl
