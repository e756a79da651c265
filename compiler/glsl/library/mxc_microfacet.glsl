// GGX microfacet distribution (Trowbridge-Reitz; Walter et al. 2007), anisotropic
// (Heitz 2014, "Understanding the Masking-Shadowing Function"), with height-correlated Smith
// masking-shadowing and visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of
// Visible Normals"). Directions are in the local frame (z = normal).

// Smallest alpha used: below it a lobe is treated as a perfect mirror (a delta).
const float MXC_DELTA_ALPHA = 1e-4;

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
