#include "compiler/glsl/ClosureValues.h"

#include <stdexcept>

#include <fmt/format.h>

#include "compiler/ir/Fold.h"

namespace mxc::glsl {

using ir::ExprId;
using ir::Op;
using ir::Type;

ClosureValues::ClosureValues(const ir::Material& material, const ExprEmitter& exprs)
    : exprs_(exprs), graph_(material.exprs), materialSize_(static_cast<ExprId>(material.exprs.size())) {}

ExprId ClosureValues::vec3(float value) { return graph_.constantVector(Type::Vec3, {value, value, value}); }

ExprId ClosureValues::slot(const ir::Slots& slots, ir::Slot s, ExprId fallback) const {
  const ir::Param* p = slots.find(s);
  return p && p->present() ? p->value : fallback;
}

ExprId ClosureValues::local(const std::string& glsl, Type type) { return graph_.named(Op::Local, type, glsl); }

ExprId ClosureValues::make(Op op, Type type, const std::vector<ExprId>& args) {
  ir::Expr e;
  e.op = op;
  e.type = type;
  if (std::optional<ExprId> folded = ir::foldExpression(graph_, e, args, {})) return *folded;
  return graph_.op(op, type, args);
}

ExprId ClosureValues::binary(Op op, ExprId a, ExprId b) {
  const Type result = type(a) == Type::Float ? type(b) : type(a);
  return make(op, result, {a, b});
}

ExprId ClosureValues::add(ExprId a, ExprId b) { return binary(Op::Add, a, b); }
ExprId ClosureValues::sub(ExprId a, ExprId b) { return binary(Op::Sub, a, b); }

ExprId ClosureValues::mul(ExprId a, ExprId b) {
  // x * 1 = x keeps the product's type: a float times vec3(1) is the float broadcast.
  const Type result = type(a) == Type::Float ? type(b) : type(a);
  if (isOne(a)) return result == Type::Vec3 ? asVec3(b) : b;
  if (isOne(b)) return result == Type::Vec3 ? asVec3(a) : a;
  return binary(Op::Mul, a, b);
}

ExprId ClosureValues::div(ExprId a, ExprId b) { return binary(Op::Div, a, b); }

ExprId ClosureValues::max(ExprId a, ExprId b) {
  const Type result = type(a) == Type::Float ? type(b) : type(a);
  return make(Op::Max, result, {result == Type::Vec3 ? asVec3(a) : a, result == Type::Vec3 ? asVec3(b) : b});
}

ExprId ClosureValues::mix(ExprId a, ExprId b, ExprId t) {
  const Type result = type(a) == Type::Float ? type(b) : type(a);
  return make(Op::Mix, result, {result == Type::Vec3 ? asVec3(a) : a, result == Type::Vec3 ? asVec3(b) : b, t});
}

ExprId ClosureValues::oneMinus(ExprId x) {
  return sub(type(x) == Type::Vec3 ? vec3(1.0f) : constant(1.0f), x);
}

ExprId ClosureValues::asVec3(ExprId x) {
  if (type(x) == Type::Vec3) return x;
  return make(Op::Splat, Type::Vec3, {x});
}

ExprId ClosureValues::iorRatio(ExprId below, ExprId above) {
  // Both IORs are >= 1e-3 where this is called, so neither division is by 0.
  return make(Op::Select, Type::Float,
              {make(Op::Greater, Type::Bool, {above, below}), div(above, below), div(below, above)});
}

ExprId ClosureValues::construct3(ExprId x, ExprId y, ExprId z) { return make(Op::Construct, Type::Vec3, {x, y, z}); }

std::string ClosureValues::glsl(ExprId x) const {
  if (x < materialSize_) return exprs_.ref(x);  // a literal or the ExprEmitter's name
  const ir::Expr& e = graph_[x];
  if (graph_.isConstant(x)) {
    const std::vector<float> c = graph_.constantComponents(x);
    if (e.type == Type::Bool) return c.at(0) != 0.0f ? "true" : "false";
    if (c.size() == 1) return glslFloat(c[0]);
    bool same = true;
    for (float v : c) same = same && v == c[0];
    std::vector<std::string> parts;
    for (float v : same ? std::vector<float>{c[0]} : c) parts.push_back(glslFloat(v));
    return fmt::format("{}({})", glslType(e.type), fmt::join(parts, ", "));
  }
  std::vector<ExprId> args = graph_.argsOf(x);
  auto a = [&](size_t i) { return glsl(args.at(i)); };
  switch (e.op) {
    case Op::Local: return graph_.text(x);
    case Op::Add: return fmt::format("({} + {})", a(0), a(1));
    case Op::Sub: return fmt::format("({} - {})", a(0), a(1));
    case Op::Mul: return fmt::format("({} * {})", a(0), a(1));
    case Op::Div: return fmt::format("({} / {})", a(0), a(1));
    case Op::Max: return fmt::format("max({}, {})", a(0), a(1));
    case Op::Mix: return fmt::format("mix({}, {}, {})", a(0), a(1), a(2));
    case Op::Greater: return fmt::format("({} > {})", a(0), a(1));
    case Op::Select: return fmt::format("({} ? {} : {})", a(0), a(1), a(2));
    case Op::Splat: return fmt::format("{}({})", glslType(e.type), a(0));
    case Op::Construct: {
      std::vector<std::string> parts;
      for (size_t i = 0; i < args.size(); ++i) parts.push_back(a(i));
      return fmt::format("{}({})", glslType(e.type), fmt::join(parts, ", "));
    }
    default: break;
  }
  // The closure builds only the operations above (a back-end bug otherwise).
  throw std::logic_error(fmt::format("the closure cannot print operation {}", ir::opName(e.op)));
}

}  // namespace mxc::glsl
