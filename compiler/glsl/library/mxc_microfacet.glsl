// GGX microfacet distribution (Trowbridge-Reitz; Walter et al. 2007), anisotropic
// (Heitz 2014, "Understanding the Masking-Shadowing Function"), with height-correlated Smith
// masking-shadowing and visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of
// Visible Normals"). Directions are in the local frame (z = normal).

// Smallest alpha used: below MXC_DELTA_ALPHA (generated/mxc_codes.glsl, glsl::kDeltaAlpha) a lobe
// is treated as a perfect mirror (a delta).

bool mxc_is_delta(vec2 alpha) { return max(alpha.x, alpha.y) < MXC_DELTA_ALPHA; }

// A rough lobe may still have one alpha near 0 (anisotropy 1: alpha_b = 0, OpenPBR eq.
// anisotropic_roughness); both are kept >= MXC_DELTA_ALPHA so that D and its sampling stay finite.
vec2 mxc_rough_alpha(vec2 alpha) { return max(alpha, vec2(MXC_DELTA_ALPHA)); }

// D(m) for a micronormal m with m.z > 0. alpha >= MXC_DELTA_ALPHA, so the divisions are safe.
float mxc_ggx_d(vec3 m, vec2 alpha) {
  if (m.z <= 0.0) return 0.0;
  alpha = mxc_rough_alpha(alpha);
  vec3 s = vec3(m.x / alpha.x, m.y / alpha.y, m.z);
  float d = dot(s, s);  // >= m.z^2 > 0
  return 1.0 / (MXC_PI * alpha.x * alpha.y * d * d);
}

// Smith Lambda (Heitz 2014, eq. 86) of a direction v.
float mxc_ggx_lambda(vec3 v, vec2 alpha) {
  alpha = mxc_rough_alpha(alpha);
  float z2 = v.z * v.z;
  if (z2 <= 0.0) return 1e10;  // grazing or below: fully masked
  float a2 = (mxc_sqr(alpha.x * v.x) + mxc_sqr(alpha.y * v.y)) / z2;
  return 0.5 * (-1.0 + sqrt(1.0 + a2));
}

float mxc_ggx_g1(vec3 v, vec2 alpha) { return 1.0 / (1.0 + mxc_ggx_lambda(v, alpha)); }

// Height-correlated G2 (Heitz 2014, eq. 99).
float mxc_ggx_g2(vec3 wo, vec3 wi, vec2 alpha) {
  return 1.0 / (1.0 + mxc_ggx_lambda(wo, alpha) + mxc_ggx_lambda(wi, alpha));
}

// A visible normal for wo (wo.z > 0), Heitz 2018 listing 1.
vec3 mxc_ggx_sample_vndf(vec3 wo, vec2 alpha, vec2 u) {
  alpha = mxc_rough_alpha(alpha);
  vec3 vh = normalize(vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));  // wo.z > 0: not zero
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0 * MXC_PI * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * mxc_safe_sqrt(1.0 - p1 * p1) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + mxc_safe_sqrt(1.0 - p1 * p1 - p2 * p2) * vh;
  // Back to the ellipsoid; max(.., 0) keeps z >= 0 after rounding, and the vector is not zero.
  return normalize(vec3(alpha.x * nh.x, alpha.y * nh.y, max(nh.z, 0.0)));
}

// pdf of a visible normal m for wo: G1(wo) max(wo.m, 0) D(m) / wo.z (Heitz 2018, eq. 3).
float mxc_ggx_pdf_vndf(vec3 wo, vec3 m, vec2 alpha) {
  if (wo.z <= 0.0) return 0.0;
  return mxc_ggx_g1(wo, alpha) * max(dot(wo, m), 0.0) * mxc_ggx_d(m, alpha) / wo.z;
}

// log Gamma(x) for x >= 1: the recurrence Gamma(x) = Gamma(x + 6) / (x (x + 1) ... (x + 5)) and
// Stirling's series at x + 6 >= 7, whose truncation after the z^-5 term errs by under 1e-7 there
// (Abramowitz & Stegun 6.1.41). Callers pass x <= 2002: the product is at most 2007^6 ~ 7e19, far
// below float's range, and float rounding (about 1e-3 in the log at that size) bounds the accuracy.
float mxc_lgamma(float x) {
  float z = x + 6.0;
  float p = x * (x + 1.0) * (x + 2.0) * (x + 3.0) * (x + 4.0) * (x + 5.0);  // > 0 for x >= 1
  float iz = 1.0 / z;
  float iz2 = iz * iz;
  float series = iz * (1.0 / 12.0 - iz2 * (1.0 / 360.0 - iz2 / 1260.0));
  return (z - 0.5) * log(z) - z + 0.91893853 + series - log(p);  // 0.9189 = ln(2 pi) / 2
}

// Height-correlated masking-shadowing of a refraction (Heitz 2014, s. 6.2): with the heights'
// CDF C, wo sees a microfacet at height h with probability C^Lambda(wo) and wi, below the
// surface, with (1 - C)^Lambda(wi); over the heights that is the Beta function
// G2 = integral_0^1 C^Lo (1 - C)^Li dC = B(1 + Lo, 1 + Li). The Beta function is computed with
// both Lambdas capped at 1000 (keeping log Gamma's terms accurate in floats) and bounded by the
// separable product G1(o) G1(i) of the uncapped Lambdas, which it never exceeds (Chebyshev's
// integral inequality: C^Lo and (1 - C)^Li are oppositely ordered), so that past the cap it still
// falls with the grazing cosine. wo and wi as seen from their own sides (z > 0).
float mxc_ggx_g2_transmit(vec3 wo, vec3 wi, vec2 alpha) {
  float lo = mxc_ggx_lambda(wo, alpha);
  float li = mxc_ggx_lambda(wi, alpha);
  float beta = exp(mxc_lgamma(1.0 + min(lo, 1000.0)) + mxc_lgamma(1.0 + min(li, 1000.0)) -
                   mxc_lgamma(2.0 + min(lo, 1000.0) + min(li, 1000.0)));
  return min(beta, 1.0 / ((1.0 + lo) * (1.0 + li)));  // both factors >= 1
}
