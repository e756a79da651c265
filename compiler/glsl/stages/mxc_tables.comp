// The albedo tables the lobes read (library/mxc_lobes.glsl, mxc_table_at). Texel (i, j) of a
// table is at mu = i / (n - 1) and x = j / (n - 1). Rows 0..n-1:
//   .x, .y: A and B of the GGX reflection albedo with a Schlick Fresnel, E = F0 A + F90 B
//           (the split sum of Karis 2013), for alpha = x;
//   .z:     the albedo of the sheen lobe (Estevez & Kulla 2017) with colour 1, for roughness x.
// Then MXC_TABLE_SLICES tables, slice s for sqrt(F0) = 0.98 s / (slices - 1):
//   .x:     the GGX reflection albedo with the exact dielectric Fresnel, for alpha = x.
// Integrated with 64 x 64 stratified samples per texel: GGX by visible normals (Heitz 2018),
// whose reflection estimator is F G2 / G1; sheen by cosine sampling.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std430) writeonly buffer MxcOutput { vec4 mxc_out[]; };

const int MXC_STRATA = 64;

void main() {
  uvec2 id = gl_GlobalInvocationID.xy;
  const uint n = uint(MXC_TABLE_SIZE);
  if (id.x >= n || id.y >= n * uint(1 + MXC_TABLE_SLICES)) return;
  uint table = id.y / n;  // 0: split sum and sheen; s + 1: dielectric slice s
  uint row = id.y % n;
  // mu = 0 is the limit of grazing view; 1e-3 keeps the frame and the estimators finite.
  float mu = max(float(id.x) / float(n - 1u), 1e-3);
  float x = float(row) / float(n - 1u);
  vec3 wo = vec3(mxc_safe_sqrt(1.0 - mu * mu), 0.0, mu);
  float sqrtF0 = 0.98 * float(max(int(table) - 1, 0)) / float(MXC_TABLE_SLICES - 1);
  float eta = (1.0 + sqrtF0) / (1.0 - sqrtF0);  // 1 - sqrtF0 >= 0.02
  float a = 0.0, b = 0.0, sheen = 0.0, dielectric = 0.0;
  vec2 alpha = vec2(x);
  bool delta = mxc_is_delta(alpha);
  for (int i = 0; i < MXC_STRATA; ++i) {
    for (int j = 0; j < MXC_STRATA; ++j) {
      vec2 u = (vec2(i, j) + 0.5) / float(MXC_STRATA);
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
      }
      if (table == 0u) {
        vec3 wi = mxc_sample_cosine(u);
        if (wi.z > 1e-6) sheen += mxc_sheen(vec3(1.0), x, wo, wi).x * MXC_PI / wi.z;  // pdf = cos / pi
      }
    }
  }
  float count = float(MXC_STRATA * MXC_STRATA);
  if (delta) {  // a mirror: E = F(mu) exactly
    float s = pow(1.0 - mu, 5.0);
    a = (1.0 - s) * count;
    b = s * count;
    dielectric = mxc_fresnel_dielectric(mu, eta) * count;
  }
  vec4 value = table == 0u ? vec4(a / count, b / count, min(sheen / count, 1.0), 0.0) : vec4(dielectric / count, 0.0, 0.0, 0.0);
  mxc_out[id.y * n + id.x] = value;
}
