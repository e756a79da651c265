#pragma once
/// \file
/// The values a closure computes, as IR expressions: the material's own (which the
/// ExprEmitter has already emitted as statements), the closure's weights and parameters built
/// on them here (folded as they are built, so a coverage of 1 or a weight of 0 disappears the
/// same way the constant-folding pass makes it disappear), and run-time values of the
/// generated code (a lobe's albedo, a library call), which enter as Op::Local leaves. Each is
/// printed as a GLSL expression where the closure uses it.

#include <string>
#include <vector>

#include "compiler/glsl/ExprEmitter.h"
#include "compiler/ir/Material.h"

namespace mxc::glsl {

class ClosureValues {
 public:
  ClosureValues(const ir::Material& material, const ExprEmitter& exprs);

  using Id = ir::ExprId;

  // Leaves
  Id constant(float value) { return graph_.constantFloat(value); }
  Id vec3(float value);
  /// A slot's value, or `fallback` when the slot is absent.
  Id slot(const ir::Slots& slots, ir::Slot slot, Id fallback) const;
  /// A parameter's value, or `fallback` when it is absent.
  Id param(const ir::Param& p, Id fallback) const { return p.present() ? p.value : fallback; }
  /// A run-time value of the generated code, by its GLSL (a variable, or a library call).
  Id local(const std::string& glsl, ir::Type type);

  // Operations, folded as they are built. Binary ones broadcast a float over a vec3.
  Id add(Id a, Id b);
  Id sub(Id a, Id b);
  Id mul(Id a, Id b);
  Id div(Id a, Id b);
  Id max(Id a, Id b);
  /// (1 - t) a + t b, for a float t.
  Id mix(Id a, Id b, Id t);
  /// 1 - x.
  Id oneMinus(Id x);
  /// x as a vec3 (a float is broadcast).
  Id asVec3(Id x);
  /// The ratio of two IORs seen from the lighter side: max(a, b) / min(a, b), for IORs
  /// already kept >= 1e-3 (so the divisor is not 0).
  Id iorRatio(Id below, Id above);
  Id construct3(Id x, Id y, Id z);

  bool isZero(Id x) const { return graph_.isConstantEqual(x, 0.0f); }
  bool isOne(Id x) const { return graph_.isConstantEqual(x, 1.0f); }
  ir::Type type(Id x) const { return graph_[x].type; }

  /// The GLSL of a value: a literal, the name the ExprEmitter gave a material expression, a
  /// run-time value's text, or an expression of those.
  std::string glsl(Id x) const;

 private:
  Id make(ir::Op op, ir::Type type, const std::vector<Id>& args);
  Id binary(ir::Op op, Id a, Id b);

  const ExprEmitter& exprs_;
  ir::ExprGraph graph_;       ///< a copy of the material's graph, extended with the closure's values
  ir::ExprId materialSize_;   ///< ids below this are the material's (emitted by exprs_)
};

}  // namespace mxc::glsl
