#pragma once
/// \file
/// The media (VDFs) of the shading models, from their artist-facing parameters.

#include "compiler/lower/Context.h"

namespace mxc::lower {

/// OpenPBR 1.1 "Subsurface": extinction mu_t = 1 / mean free path (per channel), the
/// single-scattering albedo from van de Hulst's relation inverted for the observed colour C
/// (OpenPBR eq. after [subsurface_albedo_constraint]), Henyey-Greenstein anisotropy g.
/// `meanFreePath` is a vec3 (radius * radius_scale). A semi-infinite (bulk) medium.
ir::Index subsurfaceMedium(Context& c, const ir::Param& color, const ir::Param& meanFreePath,
                           const ir::Param& anisotropy, const ir::Origin& origin);

/// OpenPBR 1.1 "Translucent base": mu_t = -ln(T) / depth, mu_s = S / depth, mu_a = mu_t - mu_s
/// shifted by grey when negative. Depth 0 means no medium (the caller tints the interface
/// instead); the coefficients are then 0 and the RemoveEmptyMedia pass removes the medium.
/// The medium also carries the bulk dielectric's IOR and, when given, its Abbe number (the
/// VDF includes "the index of refraction and dispersion of the embedding dielectric medium",
/// OpenPBR "Slabs"), so a clear glass is still an interface over a medium.
ir::Index transmissionMedium(Context& c, const ir::Param& color, const ir::Param& depth, const ir::Param& scatter,
                             const ir::Param& anisotropy, const ir::Param& ior, const ir::Param& abbeNumber,
                             const ir::Origin& origin);

/// A purely absorbing coat medium of unit thickness whose normal-incidence round trip
/// transmittance is `color` (OpenPBR "Coat": coat_color = T^2): mu_a = -ln(color) / 2.
ir::Index coatMedium(Context& c, const ir::Param& color, const ir::Origin& origin);

}  // namespace mxc::lower
