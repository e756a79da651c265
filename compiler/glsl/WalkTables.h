#pragma once
/// \file
/// The reference walk's observed-albedo tables: rows of the albedo tables image under the
/// computed ones (layout: Bindings.h, kWalkGlossRow and kWalkMediumRow), measured from the walk
/// itself by tools/GenerateWalkFits.cpp and committed as generated/tables/mxc_walk_tables.bin.
/// They turn the colours OpenPBR defines by what is observed into the parameters the walk needs:
///
/// - base_color C under the specular interface (eq. glossy_diffuse_albedo_constraint): a
///   Lambertian of albedo rho under a lossless interface returns, of what the interface lets
///   in, C = rho (1 - r_i) / (1 - rho r_i) exactly, r_i the interface's reflectance from inside
///   under cosine-distributed light (every bounce off the Lambertian is cosine-distributed), so
///   rho = C / (1 - r_i + C r_i). The gloss rows hold r_i of the walk's rough dielectric.
/// - subsurface_color C (eq. subsurface_albedo_constraint): of what the interface lets in at
///   normal incidence, the semi-infinite medium under it returns C. The medium rows hold, for a
///   grid of C, van de Hulst's s = sqrt((1 - omega) / (1 - omega g)) of the single-scattering
///   albedo omega with which the walk returns C (OpenPBR "Subsurface": "it would be more
///   appropriate to use an alpha(C) designed for this specific interface BSDF").
///
/// The lookups here are the shaders' (mxc_walk.glsl, mxc_walk_table_*) in double precision on
/// the host, for the tests and the independent walk: bilinear between texel centres, clamped
/// to the grids.

namespace mxc::glsl {

/// The grids' values (Bindings.h).
double walkTableEta(int k);
double walkTableAnisotropy(int k);
double walkTableRoughness(int k);

/// r_i of the walk's dielectric of relative IOR eta (1 to 3; outside, clamped) and specular
/// roughness (sqrt of its alpha).
double walkInternalReflectance(double eta, double roughness);
/// The Lambertian albedo rho under that interface that the walk needs for base_color C.
double walkGlossAlbedo(double c, double eta, double roughness);
/// The single-scattering albedo omega of a semi-infinite medium of HG anisotropy g under that
/// interface that the walk needs for subsurface_color C.
double walkSubsurfaceAlbedo(double c, double eta, double g, double roughness);

}  // namespace mxc::glsl
