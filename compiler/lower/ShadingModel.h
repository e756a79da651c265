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

  /// A GGX dielectric reflecting and transmitting, its IOR relative to the outside (as the
  /// shading models that are not layered on an OpenPBR coat give it).
  ir::Interface dielectricInterface(const ir::Param& ior, const ir::Param& alpha) {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Dielectric;
    i.scatter = ir::ScatterMode::RT;
    i.iorReference = ir::IorReference::Ambient;
    i.origin = c.nodeOrigin(n);
    i.slots.set(ir::Slot::Ior, ior);
    i.slots.set(ir::Slot::Alpha, alpha);
    return i;
  }
  /// A GGX reflection with a Schlick Fresnel from `f0` to a white edge.
  ir::Interface schlickInterface(const ir::Param& f0, const ir::Param& alpha) {
    ir::Interface i;
    i.kind = ir::InterfaceKind::Schlick;
    i.scatter = ir::ScatterMode::R;
    i.origin = c.nodeOrigin(n);
    i.slots.set(ir::Slot::F0, f0);
    i.slots.set(ir::Slot::F90, {b.vec(ir::Type::Vec3, 1.0f), f0.origin});
    i.slots.set(ir::Slot::Alpha, alpha);
    return i;
  }
};

}  // namespace mxc::lower
