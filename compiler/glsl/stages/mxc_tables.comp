// The albedo tables the lobes read (library/mxc_lobes.glsl, mxc_table_at). Run once by
// scripts/generate-tables, which commits its output under generated/tables (the harness loads
// that file; nothing computes tables at start-up). Texel (i, j) of a table is at
// mu = (i / (n - 1))^2 (dense near grazing, where albedos change fastest) and x = j / (n - 1), the
// roughness: alpha = x^2 for the GGX tables (dense at low roughness, where most materials are).
// Rows 0..n-1:
//   .x, .y: A and B of the GGX reflection albedo with a Schlick Fresnel, E = F0 A + F90 B
//           (the split sum of Karis 2013), for alpha = x^2;
//   .z:     the albedo of the sheen lobe (Estevez & Kulla 2017) with colour 1, for roughness x.
// Then MXC_TABLE_SLICES tables, slice s for the relative IOR eta = 1 + 2 (s / (slices - 1))^2
// (denser near 1, where the albedo changes fastest near grazing incidence), for alpha = x^2:
//   .x:     the GGX reflection albedo with the exact dielectric Fresnel, seen from outside;
//   .y:     the single-scattering albedo R + T of the dielectric lobe seen from outside (eta):
//           reflection with height-correlated G2 (Heitz 2014, eq. 99), refraction with its
//           height-correlated form (mxc_ggx_g2_transmit), each weighted by its Fresnel factor;
//   .z:     the same seen from inside (1 / eta), total internal reflection included.
// Integrated with stratified samples per texel (64 x 64 for the first table, 32 x 32 for the
// slices): GGX by visible normals (Heitz 2018), whose estimators are F G2 / G1 for reflection and
// (1 - F) G2 / G1 for refraction (the lobe's transmission is arranged so that its integral is
// the transmittance); sheen by half vectors drawn from its distribution, which keeps grazing
// views (where the lobe is concentrated) accurate.

#include "generated/mxc_tables_stage.glsl"


// One visible normal m's share of the single-scattering albedo R + T of a dielectric interface
// of IOR ratio eta (far side over near side) seen from wo (wo.z > 0, m drawn from wo's visible
// normals): F G2 / G1 for the reflection and (1 - F) G2_T / G1 for the refraction, each when its
// direction leaves on its own side.
float mxc_single_scattering(vec3 wo, vec3 m, vec2 alpha, float eta) {
  float cosh = clamp(dot(wo, m), 0.0, 1.0);
  float f = mxc_fresnel_dielectric(cosh, eta);
  float g1 = mxc_ggx_g1(wo, alpha);  // > 0 for wo.z > 0
  float sum = 0.0;
  vec3 r = reflect(-wo, m);
  if (r.z > 0.0) sum += f * mxc_ggx_g2(wo, r, alpha) / g1;
  if (f < 1.0) {
    vec3 t = refract(-wo, m, 1.0 / eta);  // f < 1: not total internal reflection
    if (t.z < 0.0) sum += (1.0 - f) * mxc_ggx_g2_transmit(wo, vec3(t.xy, -t.z), alpha) / g1;
  }
  return sum;
}

void main() {
  uvec2 id = gl_GlobalInvocationID.xy;
  const uint n = uint(MXC_TABLE_SIZE);
  if (id.x >= n || id.y >= n * uint(1 + MXC_TABLE_SLICES)) return;
  uint table = id.y / n;  // 0: split sum and sheen; s + 1: dielectric slice s
  uint row = id.y % n;
  // mu = 0 is the limit of grazing view; 1e-4 keeps the frame and the estimators finite.
  float mu = max(mxc_sqr(float(id.x) / float(n - 1u)), 1e-4);
  float x = float(row) / float(n - 1u);
  vec3 wo = vec3(mxc_safe_sqrt(1.0 - mu * mu), 0.0, mu);
  float slice = float(max(int(table) - 1, 0)) / float(MXC_TABLE_SLICES - 1);
  float eta = 1.0 + 2.0 * slice * slice;
  const int strata = table == 0u ? 64 : 32;
  float a = 0.0, b = 0.0, sheen = 0.0, dielectric = 0.0, outside = 0.0, inside = 0.0;
  vec2 alpha = vec2(x * x);
  bool delta = mxc_is_delta(alpha);
  for (int i = 0; i < strata; ++i) {
    for (int j = 0; j < strata; ++j) {
      vec2 u = (vec2(i, j) + 0.5) / float(strata);
      if (!delta) {
        vec3 m = mxc_ggx_sample_vndf(wo, alpha, u);
        vec3 wi = reflect(-wo, m);
        if (wi.z > 0.0) {
          float w = mxc_ggx_g2(wo, wi, alpha) / mxc_ggx_g1(wo, alpha);  // G1 > 0 for wo.z > 0
          float cosh = clamp(dot(wo, m), 0.0, 1.0);
          float s = pow(1.0 - cosh, 5.0);
          a += w * (1.0 - s);
          b += w * s;
          dielectric += w * mxc_fresnel_dielectric(cosh, eta);
        }
        if (table != 0u) {
          outside += mxc_single_scattering(wo, m, alpha, eta);
          inside += mxc_single_scattering(wo, m, alpha, 1.0 / eta);
        }
      }
      if (table == 0u) {
        // Half vectors from D(h) cos(theta_h): with s = sin(theta_h), pdf(s) ~ s^(1/r + 1), so
        // s = u^(1 / (1/r + 2)) (r as clamped in mxc_sheen_d). The reflection about h has
        // pdf D cos(theta_h) / (4 |wo.h|), and the estimator f cos / pdf = D G / (4 mu_o) / pdf.
        float inv = 1.0 / max(x, 0.01);
        float sinh = pow(u.x, 1.0 / (inv + 2.0));
        float cosh = mxc_safe_sqrt(1.0 - sinh * sinh);
        float phi = 2.0 * MXC_PI * u.y;
        vec3 h = vec3(sinh * cos(phi), sinh * sin(phi), cosh);
        float oh = dot(wo, h);
        vec3 wi = reflect(-wo, h);
        if (wi.z > 0.0 && oh > 0.0 && cosh > 1e-6) {
          float pdf = mxc_sheen_d(x, cosh) * cosh / (4.0 * oh);  // > 0: D > 0 for sin > 0
          if (pdf > 0.0) sheen += mxc_sheen_unnormalized(vec3(1.0), x, wo, wi).x / pdf;
        }
      }
    }
  }
  float count = float(strata * strata);
  if (delta) {  // a mirror: E = F(mu) exactly
    float s = pow(1.0 - mu, 5.0);
    a = (1.0 - s) * count;
    b = s * count;
    dielectric = mxc_fresnel_dielectric(mu, eta) * count;
    outside = count;  // a smooth interface reflects F and refracts 1 - F: nothing is lost
    inside = count;
  }
  vec4 value = table == 0u ? vec4(a / count, b / count, sheen / count, 0.0)
                           : vec4(dielectric / count, outside / count, inside / count, 0.0);
  mxc_out[id.y * n + id.x] = value;
}
