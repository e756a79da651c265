#include "compiler/lower/Media.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Type;

namespace {

/// -ln(T) for a transmittance, guarded: T is clamped to [1e-6, 1], so the logarithm is finite
/// (at most 13.8) and never negative.
ExprId opticalDepth(ir::ExprBuilder& b, ExprId transmittance) {
  ExprId t = b.clamp(transmittance, b.f(1e-6f), b.f(1.0f));
  return b.neg(b.ln(t));
}

}  // namespace

ir::Index subsurfaceMedium(Context& c, const ir::Param& color, const ir::Param& meanFreePath,
                           const ir::Param& anisotropy, const ir::Origin& origin) {
  ir::ExprBuilder& b = c.b;
  // mu_t = 1 / r; r is a length >= 0; max(r, 1e-6) regularises r -> 0 (OpenPBR: "may need to be
  // regularized in the limit r -> 0").
  ExprId muT = b.safeDiv(b.vec(Type::Vec3, 1.0f), b.nonNegative(meanFreePath.value), 1e-6f);
  // van de Hulst inversion; C in [0, 1] gives s in [0, 1] (s = 1 at C = 0, s = 0 at C = 1), and
  // the radicand 9.59217 + 41.6808 C + 17.7126 C^2 is positive for C >= 0.
  ExprId cc = b.clamp01(color.value);
  ExprId radicand = b.add(b.add(b.vec(Type::Vec3, 9.59217f), b.mul(cc, b.f(41.6808f))),
                          b.mul(b.mul(cc, cc), b.f(17.7126f)));
  ExprId s = b.sub(b.add(b.vec(Type::Vec3, 4.09712f), b.mul(cc, b.f(4.20863f))), b.sqrt(radicand));
  // g is clamped to [-0.99, 0.99] (the phase function degenerates at +-1), so 1 - g s^2 >= 0.01.
  ExprId g = b.clamp(anisotropy.value, b.f(-0.99f), b.f(0.99f));
  ExprId s2 = b.mul(s, s);
  ExprId albedo = b.div(b.oneMinus(s2), b.sub(b.vec(Type::Vec3, 1.0f), b.mul(s2, g)));
  ir::Medium m;
  m.extent = ir::Medium::Extent::Bulk;
  m.origin = origin;
  m.slots.set(ir::Slot::Absorption, {b.mul(muT, b.oneMinus(albedo)), meanFreePath.origin});
  m.slots.set(ir::Slot::Scattering, {b.mul(muT, albedo), color.origin});
  m.slots.set(ir::Slot::Anisotropy, {g, anisotropy.origin});
  m.slots.set(ir::Slot::ObservedAlbedo, {cc, color.origin});
  return c.material.addMedium(std::move(m));
}

ir::Index transmissionMedium(Context& c, const ir::Param& color, const ir::Param& depth, const ir::Param& scatter,
                             const ir::Param& anisotropy, const ir::Param& ior, const ir::Param& abbeNumber,
                             const ir::Origin& origin) {
  ir::ExprBuilder& b = c.b;
  // Depth 0 means "no medium": select 0 coefficients then; otherwise divide by the depth,
  // which is > 0 in that branch (guarded again with max(depth, 1e-6) so the unselected
  // branch stays finite on every backend).
  ExprId hasDepth = b.greater(depth.value, b.f(0.0f));
  ExprId muT = b.safeDiv(opticalDepth(b, color.value), depth.value, 1e-6f);
  ExprId muS = b.safeDiv(b.nonNegative(scatter.value), depth.value, 1e-6f);
  // mu_a = mu_t - mu_s, shifted by grey when a component is negative (OpenPBR "Translucent base").
  ExprId muA = b.sub(muT, muS);
  ExprId shift = b.min(b.minComponent(muA), b.f(0.0f));
  muA = b.sub(muA, shift);
  ir::Medium m;
  m.extent = ir::Medium::Extent::Bulk;
  m.origin = origin;
  m.slots.set(ir::Slot::Absorption, {b.select(hasDepth, muA, b.vec(Type::Vec3, 0.0f)), color.origin});
  m.slots.set(ir::Slot::Scattering, {b.select(hasDepth, muS, b.vec(Type::Vec3, 0.0f)), scatter.origin});
  m.slots.set(ir::Slot::Anisotropy, {b.clamp(anisotropy.value, b.f(-0.99f), b.f(0.99f)), anisotropy.origin});
  m.slots.set(ir::Slot::Ior, ior);
  if (abbeNumber.present()) m.slots.set(ir::Slot::AbbeNumber, abbeNumber);
  return c.material.addMedium(std::move(m));
}

ir::Index coatMedium(Context& c, const ir::Param& color, const ir::Origin& origin) {
  ir::ExprBuilder& b = c.b;
  ir::Medium m;
  m.extent = ir::Medium::Extent::Finite;
  m.origin = origin;
  m.slots.set(ir::Slot::Absorption, {b.mul(opticalDepth(b, color.value), b.f(0.5f)), color.origin});
  m.slots.set(ir::Slot::Thickness, {b.f(1.0f), origin});
  return c.material.addMedium(std::move(m));
}

}  // namespace mxc::lower
