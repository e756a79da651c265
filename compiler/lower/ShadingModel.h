#pragma once
/// \file
/// What every shading-model lowering (OpenPBR, Standard Surface, UsdPreviewSurface, glTF PBR)
/// reads its shading node through: inputs as IR parameters, clamped to a range the model's
/// specification states or kept non-negative, their origins, and whether one is a given
/// constant (a constant decides at compile time which parts of the model exist).

#include <string_view>

#include "compiler/lower/Context.h"

namespace mxc::lower {

struct ShadingModelInputs {
  Context& c;
  const NodeRef& n;
  ir::ExprBuilder& b;

  ir::Param p(std::string_view name) { return c.param(n, name); }
  /// The input clamped to [lo, hi]: the model's specified range (each caller cites it).
  ir::Param clamped(std::string_view name, float lo, float hi) {
    ir::Param x = p(name);
    x.value = b.clamp(x.value, b.f(lo), b.f(hi));
    return x;
  }
  ir::Param clamped01(std::string_view name) { return clamped(name, 0.0f, 1.0f); }
  ir::Param nonNegative(std::string_view name) {
    ir::Param x = p(name);
    x.value = b.nonNegative(x.value);
    return x;
  }
  ir::Origin at(std::string_view input) { return c.origin(n, input); }
  /// True when the parameter is the constant `value` as written (before any clamp: a clamped
  /// constant is folded only by the passes).
  bool isConstant(const ir::Param& x, float value) { return c.material.exprs.isConstantEqual(x.value, value); }
};

}  // namespace mxc::lower
