#pragma once
/// \file
/// Rebuilding a material's expression graph through a rewrite function.

#include <optional>
#include <vector>

#include "compiler/ir/Material.h"
#include "compiler/ir/Walk.h"

namespace mxc::ir {

/// Copies every expression reachable from the material's parameters into a new graph, in id
/// order (arguments before users, so no recursion however deep the graph is). For each one,
/// `rewrite(graph, old, expr, newArgs)` may return a replacement built in the new graph;
/// otherwise the expression is copied. Parameters are remapped. Returns the number of
/// expressions the rewrite replaced.
template <typename Rewrite>
int rebuildExpressions(Material& m, Rewrite rewrite) {
  const ExprGraph& old = m.exprs;
  std::vector<bool> reachable(old.size());
  std::vector<ExprId> stack;
  forEachReachableParam(m, [&](Param& p) {
    if (p.present()) stack.push_back(p.value);
  });
  while (!stack.empty()) {
    ExprId id = stack.back();
    stack.pop_back();
    if (reachable[id]) continue;
    reachable[id] = true;
    for (size_t i = 0; i < old[id].argCount; ++i) stack.push_back(old.arg(id, i));
  }
  ExprGraph fresh;
  fresh.reserve(old.size());
  std::vector<ExprId> map(old.size(), kNoExpr);
  std::vector<ExprId> args;  // reused: one allocation for the whole rebuild
  int edits = 0;
  for (ExprId id = 0; id < old.size(); ++id) {
    if (!reachable[id]) continue;
    const Expr& e = old[id];
    args.clear();
    for (size_t i = 0; i < e.argCount; ++i) args.push_back(map[old.arg(id, i)]);
    if (std::optional<ExprId> replaced = rewrite(fresh, old, id, args)) {
      map[id] = *replaced;
      ++edits;
      continue;
    }
    if (e.op == Op::Constant) {
      map[id] = fresh.constant(old.constantValue(id));
    } else if (hasTextPayload(e.op)) {
      map[id] = fresh.opWithString(e.op, e.type, args, old.text(id));
    } else {
      map[id] = fresh.op(e.op, e.type, args, e.payload);
    }
  }
  forEachReachableParam(m, [&](Param& p) {
    if (p.present()) p.value = map[p.value];
  });
  m.exprs = std::move(fresh);
  return edits;
}

}  // namespace mxc::ir
