#pragma once
/// \file
/// Host evaluation of IR operations on constants, for constant folding (and for tests that
/// check what an expression computes).

#include <optional>
#include <vector>

#include "compiler/ir/Expr.h"

namespace mxc::ir {

/// A constant as float components of a type (Bool and Int use one component).
struct Constant {
  Type type = Type::Float;
  std::vector<float> v;
};

/// Evaluates `op` of result type `type` on constant arguments; nullopt for operations that
/// are not folded on the host (textures, noise, geometry) or whose result would not be finite.
/// `text` is the expression's string payload (Swizzle channels), `payload` its integer one.
std::optional<Constant> evaluate(Op op, Type type, const std::vector<Constant>& args, uint32_t payload,
                                 const std::string& text);

/// Evaluates a whole expression whose leaves are all constants (nullopt otherwise).
std::optional<Constant> evaluateExpr(const ExprGraph& graph, ExprId id);

}  // namespace mxc::ir
