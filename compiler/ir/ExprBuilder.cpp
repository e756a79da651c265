#include "compiler/ir/ExprBuilder.h"

#include <algorithm>
#include <stdexcept>

namespace mxc::ir {

ExprId ExprBuilder::vec(Type type, float value) {
  const int n = std::max(1, componentCount(type));
  return g_.constantVector(type, std::vector<float>(static_cast<size_t>(n), value));
}

ExprId ExprBuilder::splat(ExprId scalar, Type t) {
  if (t == Type::Float || type(scalar) == t) return scalar;
  return g_.op(Op::Splat, t, {scalar});
}

ExprId ExprBuilder::convert(ExprId e, Type to) {
  const Type from = type(e);
  if (from == to) return e;
  if (from == Type::Float || from == Type::Int || from == Type::Bool) {
    ExprId scalar = from == Type::Float ? e : g_.op(Op::Construct, Type::Float, {e});
    return to == Type::Float ? scalar : splat(scalar, to);
  }
  const int n = componentCount(from);
  const int m = componentCount(to);
  if (to == Type::Float) return extract(e, 0);
  std::vector<ExprId> parts;
  for (int i = 0; i < std::min(n, m); ++i) parts.push_back(extract(e, i));
  // vec3 -> vec4 gains w = 1 (an opaque colour, a point); other widenings pad with 0.
  for (int i = n; i < m; ++i) parts.push_back(f(n == 3 && m == 4 ? 1.0f : 0.0f));
  return construct(to, parts);
}

ExprId ExprBuilder::binary(Op op, ExprId a, ExprId b) {
  Type ta = type(a);
  Type tb = type(b);
  Type result = ta;
  if (ta != tb) {
    // Broadcast a float over the other operand; matrices times vectors use MatMul, not this.
    if (ta == Type::Float) result = tb;
    else if (tb == Type::Float) result = ta;
    else throw std::logic_error("ExprBuilder: mismatched operand types");
  }
  if (op == Op::Atan2 || op == Op::Pow || op == Op::Min || op == Op::Max || op == Op::Mod) {
    // Component-wise ops with an explicit splat, so the backend sees equal types.
    return g_.op(op, result, {splat(a, result), splat(b, result)});
  }
  return g_.op(op, result, {a, b});
}

ExprId ExprBuilder::lerp(ExprId a, ExprId b, ExprId t) {
  Type ta = type(a);
  Type tb = type(b);
  Type result = ta == Type::Float ? tb : ta;
  return g_.op(Op::Mix, result, {splat(a, result), splat(b, result), t});
}

ExprId ExprBuilder::clamp(ExprId x, ExprId lo, ExprId hi) {
  Type t = type(x);
  return g_.op(Op::Clamp, t, {x, splat(lo, t), splat(hi, t)});
}

ExprId ExprBuilder::safeDiv(ExprId a, ExprId b, float epsilon) {
  return div(a, max(b, vec(type(b), epsilon)));
}

ExprId ExprBuilder::select(ExprId condition, ExprId ifTrue, ExprId ifFalse) {
  Type t = type(ifTrue) == Type::Float ? type(ifFalse) : type(ifTrue);
  return g_.op(Op::Select, t, {condition, splat(ifTrue, t), splat(ifFalse, t)});
}

ExprId ExprBuilder::maxComponent(ExprId v) {
  const int n = componentCount(type(v));
  if (n <= 1) return v;
  ExprId m = extract(v, 0);
  for (int i = 1; i < n; ++i) m = max(m, extract(v, i));
  return m;
}

ExprId ExprBuilder::minComponent(ExprId v) {
  const int n = componentCount(type(v));
  if (n <= 1) return v;
  ExprId m = extract(v, 0);
  for (int i = 1; i < n; ++i) m = min(m, extract(v, i));
  return m;
}

}  // namespace mxc::ir
