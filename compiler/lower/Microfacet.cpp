#include "compiler/lower/Microfacet.h"

namespace mxc::lower {

using ir::ExprId;
using ir::Type;

ExprId openPbrAlpha(ir::ExprBuilder& b, ExprId roughness, ExprId anisotropy) {
  ExprId r = b.clamp01(roughness);
  ExprId oneMinusA = b.oneMinus(b.clamp01(anisotropy));
  ExprId r2 = b.mul(r, r);
  ExprId alphaT = b.mul(r2, b.sqrt(b.div(b.f(2.0f), b.add(b.f(1.0f), b.mul(oneMinusA, oneMinusA)))));
  return b.construct(Type::Vec2, {alphaT, b.mul(oneMinusA, alphaT)});
}

ExprId burleyAlpha(ir::ExprBuilder& b, ExprId roughness, ExprId anisotropy) {
  ExprId alpha = b.clamp(b.mul(roughness, roughness), b.f(1e-7f), b.f(1.0f));
  ExprId aspect = b.sqrt(b.oneMinus(b.clamp(anisotropy, b.f(0.0f), b.f(0.98f))));
  return b.construct(Type::Vec2, {b.min(b.div(alpha, aspect), b.f(1.0f)), b.mul(alpha, aspect)});
}

std::pair<ExprId, ExprId> gulbrandsenIor(ir::ExprBuilder& b, ExprId reflectivity, ExprId edgeTint) {
  ExprId r = b.clamp(reflectivity, b.f(0.0f), b.f(0.99f));
  ExprId one = b.vec(Type::Vec3, 1.0f);
  ExprId sqrtR = b.sqrt(r);
  ExprId nMin = b.div(b.oneMinus(r), b.add(one, r));
  ExprId nMax = b.div(b.add(one, sqrtR), b.oneMinus(sqrtR));
  // g is the weight between the two bounds of n (Gulbrandsen eq. 8): in [0, 1], n stays in
  // [nMin, nMax] (> 0); an edge tint above 1 (a colour taken to another working space) would
  // push n below nMin, even negative.
  ExprId n = b.lerp(nMax, nMin, b.clamp01(edgeTint));
  ExprId np1 = b.add(n, one);
  ExprId nm1 = b.sub(n, one);
  ExprId k2 = b.div(b.sub(b.mul(b.mul(np1, np1), r), b.mul(nm1, nm1)), b.oneMinus(r));
  return {n, b.sqrt(b.nonNegative(k2))};
}

}  // namespace mxc::lower
