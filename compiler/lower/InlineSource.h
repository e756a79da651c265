#pragma once
/// \file
/// Nodes implemented by inline source code: an <implementation> whose `sourcecode` is a GLSL
/// expression over the node's inputs, written {{name}} (MaterialX 1.39 "Implementation
/// Elements"; MaterialX's own genglsl library writes most of its math nodes so, and custom
/// nodes such as a struct member access `{{in}}.ss` too).
///
/// The expression is parsed and lowered into IR ops, not pasted into the shader: it is type
/// checked here, folds with the rest of the material, and every back end emits it. The
/// language is GLSL's expression grammar: literals, {{input}}, unary and binary operators,
/// comparisons, && || !, ?:, swizzles and struct members (.name), [index], and calls of GLSL
/// built-ins, vector constructors and MaterialX's mx_ math helpers (mx_mod, mx_atan, ...).

#include "compiler/document/Elements.h"
#include "compiler/lower/Context.h"

namespace mxc::lower {

/// The value of output `output` (of IR type `type`) of `n`, computed by `implementation`'s
/// source code; kNoExpr after reporting an expression mxc cannot lower.
ir::ExprId lowerInlineSource(Context& c, const NodeRef& n, const doc::Implementation& implementation,
                             std::string_view output, ir::Type type);

}  // namespace mxc::lower
