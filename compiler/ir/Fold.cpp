#include "compiler/ir/Fold.h"

#include <algorithm>

#include "compiler/ir/Evaluate.h"

namespace mxc::ir {

namespace {

bool isConst(const ExprGraph& g, ExprId id, float value) { return g.isConstantEqual(id, value); }

/// An identity that makes `args` of `e` equal to one of its operands, or nullopt.
/// Only identities that hold for every finite input are used, and only when the operand has
/// the result's type (a broadcast scalar is not the vector result).
std::optional<ExprId> simplify(const ExprGraph& g, const Expr& e, const std::vector<ExprId>& a) {
  auto same = [&](ExprId x) -> std::optional<ExprId> {
    if (g[x].type == e.type) return x;
    return std::nullopt;
  };
  switch (e.op) {
    case Op::Add:
      if (isConst(g, a[1], 0.0f)) return same(a[0]);
      if (isConst(g, a[0], 0.0f)) return same(a[1]);
      break;
    case Op::Sub:
      if (isConst(g, a[1], 0.0f)) return same(a[0]);
      break;
    case Op::Mul:
      if (isConst(g, a[1], 1.0f)) return same(a[0]);
      if (isConst(g, a[0], 1.0f)) return same(a[1]);
      // x * 0 = 0: the IR's values are finite (inputs are finite by the parser, and the
      // shader library guards its divisions), so no NaN * 0 is lost.
      if (isConst(g, a[0], 0.0f) || isConst(g, a[1], 0.0f)) return std::nullopt;  // handled by the caller
      break;
    case Op::Div:
      if (isConst(g, a[1], 1.0f)) return same(a[0]);
      break;
    case Op::Pow:
      if (isConst(g, a[1], 1.0f)) return same(a[0]);
      break;
    case Op::Min:
      if (a[0] == a[1]) return same(a[0]);
      // min(clamp(x, lo, hi), c) = clamp(x, lo, hi) when c >= hi (and symmetrically).
      for (int k = 0; k < 2; ++k) {
        ExprId c = a[1 - k];
        if (g[a[k]].op == Op::Clamp && g.isConstant(c) && g.isConstant(g.arg(a[k], 2))) {
          auto hi = g.constantComponents(g.arg(a[k], 2));
          auto cc = g.constantComponents(c);
          if (hi.size() == cc.size() || cc.size() == 1) {
            bool above = true;
            for (size_t i = 0; i < hi.size(); ++i) above = above && cc[cc.size() == 1 ? 0 : i] >= hi[i];
            if (above) return same(a[k]);
          }
        }
      }
      break;
    case Op::Max:
      if (a[0] == a[1]) return same(a[0]);
      break;
    case Op::Mix:
      if (isConst(g, a[2], 0.0f)) return same(a[0]);
      if (isConst(g, a[2], 1.0f)) return same(a[1]);
      if (a[0] == a[1]) return same(a[0]);
      break;
    case Op::Select:
      if (isConst(g, a[0], 1.0f)) return same(a[1]);
      if (isConst(g, a[0], 0.0f)) return same(a[2]);
      if (a[1] == a[2]) return same(a[1]);
      break;
    case Op::Neg:
      if (g[a[0]].op == Op::Neg) return g.arg(a[0], 0);
      break;
    case Op::Normalize: {
      // Normals, tangents and bitangents from the geometry are unit vectors (the harness
      // provides them normalised), and normalising twice changes nothing.
      const Expr& x = g[a[0]];
      if (x.op == Op::Normalize) return a[0];
      if (x.op == Op::GeomProp && x.argCount == 0) {
        const std::string& name = g.text(a[0]);
        if (!name.empty() && (name[0] == 'N' || name[0] == 'T' || name[0] == 'B')) return a[0];
      }
      break;
    }
    case Op::Splat:
    case Op::Construct:
      if (a.size() == 1 && g[a[0]].type == e.type) return a[0];
      break;
    default:
      break;
  }
  return std::nullopt;
}

}  // namespace

std::optional<ExprId> foldExpression(ExprGraph& g, const Expr& e, const std::vector<ExprId>& args, const std::string& text) {
  if (e.op == Op::Constant || e.op == Op::Local || args.empty()) return std::nullopt;
  bool allConstant = true;
  std::vector<Constant> values;
  for (ExprId a : args) {
    if (!g.isConstant(a) || g[a].type == Type::String) {
      allConstant = false;
      break;
    }
    values.push_back({g[a].type, g.constantComponents(a)});
  }
  if (allConstant) {
    std::optional<Constant> c = evaluate(e.op, e.type, values, e.payload, text);
    if (c) return g.constantVector(e.type, c->v);
  }
  if (e.op == Op::Mul && (g.isConstantEqual(args[0], 0.0f) || g.isConstantEqual(args[1], 0.0f))) {
    return g.constantVector(e.type, std::vector<float>(static_cast<size_t>(std::max(1, componentCount(e.type))), 0.0f));
  }
  return simplify(g, e, args);
}

}  // namespace mxc::ir
