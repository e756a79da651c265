#pragma once
/// \file
/// Folding one expression: its value when its arguments are constants, or an algebraic
/// identity that makes it one of its operands (x * 1 = x, mix(a, b, 0) = a, ...). The
/// constant-folding pass applies it to a material's graph; the back end applies it to the
/// closure's weights as it builds them.

#include <optional>
#include <string>
#include <vector>

#include "compiler/ir/Expr.h"

namespace mxc::ir {

/// The folded form of `e` with (already folded) arguments `args` in `g` (`text` is e's text
/// payload), or nullopt when it does not fold. Only identities that hold for every finite
/// input are used, and only when the result keeps e's type.
std::optional<ExprId> foldExpression(ExprGraph& g, const Expr& e, const std::vector<ExprId>& args, const std::string& text);

}  // namespace mxc::ir
