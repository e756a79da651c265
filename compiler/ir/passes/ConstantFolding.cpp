#include "compiler/ir/Fold.h"
#include "compiler/ir/passes/ExprRewrite.h"
#include "compiler/ir/passes/Pass.h"

namespace mxc::ir {

int constantFolding(Material& m, const PassContext&) {
  return rebuildExpressions(m, [](ExprGraph& g, const ExprGraph& old, ExprId id,
                                  const std::vector<ExprId>& args) -> std::optional<ExprId> {
    static const std::string empty;
    const Expr& e = old[id];
    return foldExpression(g, e, args, hasTextPayload(e.op) ? old.text(id) : empty);
  });
}

}  // namespace mxc::ir
