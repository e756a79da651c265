#pragma once
/// \file
/// Typed helpers for building expressions: broadcasting of scalars over vectors, and the
/// formulas that lowering writes often (lerp, clamp, safe division).

#include "compiler/ir/Expr.h"

namespace mxc::ir {

/// Builds expressions in an ExprGraph. Binary operations take a vector and a float in either
/// order (the float is broadcast); two vectors must have the same type.
class ExprBuilder {
 public:
  explicit ExprBuilder(ExprGraph& graph) : g_(graph) {}

  ExprGraph& graph() { return g_; }
  Type type(ExprId e) const { return g_[e].type; }

  ExprId f(float value) { return g_.constantFloat(value); }
  ExprId vec(Type type, float value);  ///< a vector (or float) with every component `value`
  ExprId splat(ExprId scalar, Type type);
  /// Converts between float and vector types the way MaterialX's <convert> does (a float fills
  /// every component; vec3 to vec4 appends 1; vec4 to vec3 drops w; vec2 <-> vec3 pads with 0).
  ExprId convert(ExprId e, Type to);

  ExprId add(ExprId a, ExprId b) { return binary(Op::Add, a, b); }
  ExprId sub(ExprId a, ExprId b) { return binary(Op::Sub, a, b); }
  ExprId mul(ExprId a, ExprId b) { return binary(Op::Mul, a, b); }
  /// a / b. Callers guard b against 0 where it can be (see safeDiv).
  ExprId div(ExprId a, ExprId b) { return binary(Op::Div, a, b); }
  ExprId min(ExprId a, ExprId b) { return binary(Op::Min, a, b); }
  ExprId max(ExprId a, ExprId b) { return binary(Op::Max, a, b); }
  ExprId pow(ExprId a, ExprId b) { return binary(Op::Pow, a, b); }
  ExprId mod(ExprId a, ExprId b) { return binary(Op::Mod, a, b); }
  ExprId atan2(ExprId y, ExprId x) { return binary(Op::Atan2, y, x); }
  ExprId unary(Op op, ExprId a) { return g_.op(op, type(a), {a}); }
  ExprId neg(ExprId a) { return unary(Op::Neg, a); }
  ExprId sqrt(ExprId a) { return unary(Op::Sqrt, a); }
  ExprId ln(ExprId a) { return unary(Op::Ln, a); }
  ExprId abs(ExprId a) { return unary(Op::Abs, a); }
  ExprId sign(ExprId a) { return unary(Op::Sign, a); }
  /// 1 - a
  ExprId oneMinus(ExprId a) { return sub(vec(type(a), 1.0f), a); }
  /// (1 - t) a + t b; t may be a float or of a's type.
  ExprId lerp(ExprId a, ExprId b, ExprId t);
  ExprId clamp(ExprId x, ExprId lo, ExprId hi);
  ExprId clamp01(ExprId x) { return clamp(x, vec(type(x), 0.0f), vec(type(x), 1.0f)); }
  /// max(x, 0): a guard for values that must not be negative (colours, lengths).
  ExprId nonNegative(ExprId x) { return max(x, vec(type(x), 0.0f)); }
  /// a / max(b, epsilon): for divisors that are lengths or weights and may be zero.
  ExprId safeDiv(ExprId a, ExprId b, float epsilon);
  ExprId dot(ExprId a, ExprId b) { return g_.op(Op::Dot, Type::Float, {a, b}); }
  ExprId normalize(ExprId a) { return unary(Op::Normalize, a); }
  ExprId extract(ExprId v, int component) { return g_.op(Op::Extract, Type::Float, {v}, static_cast<uint32_t>(component)); }
  ExprId construct(Type type, const std::vector<ExprId>& parts) { return g_.op(Op::Construct, type, parts); }
  ExprId select(ExprId condition, ExprId ifTrue, ExprId ifFalse);
  ExprId greater(ExprId a, ExprId b) { return g_.op(Op::Greater, Type::Bool, {a, b}); }
  /// The largest component of a vector (a float stays as is).
  ExprId maxComponent(ExprId v);
  ExprId minComponent(ExprId v);

  ExprId binary(Op op, ExprId a, ExprId b);

 private:
  ExprGraph& g_;
};

}  // namespace mxc::ir
