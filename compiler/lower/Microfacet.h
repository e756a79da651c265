#pragma once
/// \file
/// Roughness and Fresnel parametrisations shared by the shading models and pbrlib nodes.

#include <utility>

#include "compiler/ir/ExprBuilder.h"

namespace mxc::lower {

/// OpenPBR 1.1 "Microfacet model", eq. openpbr-anisotropy-formula: GGX alphas from roughness r
/// and anisotropy a, alpha_t = r^2 sqrt(2 / (1 + (1 - a)^2)), alpha_b = (1 - a) alpha_t, so that
/// alpha_t^2 + alpha_b^2 = 2 r^4. r and a are clamped to [0, 1]; then 1 + (1 - a)^2 >= 1, so the
/// division and the square root are safe. Returns a vec2.
ir::ExprId openPbrAlpha(ir::ExprBuilder& b, ir::ExprId roughness, ir::ExprId anisotropy);

/// The aspect-ratio stretch of Burley 2012 (s. B.2) as MaterialX's roughness_anisotropy applies
/// it (Standard Surface): alpha = clamp(r^2, 1e-7, 1), aspect = sqrt(1 - clamp(a, 0, 0.98)),
/// (min(alpha / aspect, 1), alpha * aspect). aspect >= sqrt(0.02), so the division is safe.
ir::ExprId burleyAlpha(ir::ExprBuilder& b, ir::ExprId roughness, ir::ExprId anisotropy);

/// Gulbrandsen 2014, "Artist Friendly Metallic Fresnel", eqs. 7-9: the complex IOR (n, k) of a
/// conductor with normal reflectivity r and edge tint g (vec3 each).
/// Guards: r clamped to [0, 0.99] keeps 1 - r and 1 - sqrt(r) >= 0.005; g clamped to [0, 1]
/// (the interpolation weight of eq. 8) keeps n between its bounds; k's radicand is clamped at 0.
std::pair<ir::ExprId, ir::ExprId> gulbrandsenIor(ir::ExprBuilder& b, ir::ExprId reflectivity, ir::ExprId edgeTint);

}  // namespace mxc::lower
