// Sheen (Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF"): the "Charlie"
// distribution with their fitted shadowing. Local frame, z = normal.

// The "Charlie" distribution D = (2 + 1/r) sin^(1/r)(theta_h) / (2 pi), r clamped to >= 0.01
// (so 1/r stays finite).
float mxc_sheen_d(float r, float cosh) {
  float inv = 1.0 / max(r, 0.01);
  float sin2 = max(1.0 - cosh * cosh, 0.0);
  return (2.0 + inv) * pow(sin2, 0.5 * inv) / (2.0 * MXC_PI);
}
// Their fitted shadowing: L(x) = a / (1 + b x^c) + d x + e with parameters interpolated
// between r = 0 and r = 1 by (1 - r)^2 (paper, table 1 and eq. 3).
float mxc_sheen_l(float x, float r) {
  float t = mxc_sqr(1.0 - r);
  float a = mix(21.5473, 25.3245, t);
  float b = mix(3.82987, 3.32435, t);
  float c = mix(0.19823, 0.16801, t);
  float d = mix(-1.97760, -1.27393, t);
  float e = mix(-4.32054, -4.85967, t);
  return a / (1.0 + b * pow(max(x, 0.0), c)) + d * x + e;
}
float mxc_sheen_lambda(float mu, float r) {
  return mu < 0.5 ? exp(mxc_sheen_l(mu, r)) : exp(2.0 * mxc_sheen_l(0.5, r) - mxc_sheen_l(1.0 - mu, r));
}
// f |cos theta_i| of the lobe as published (its albedo may exceed 1 near grazing; the lobe
// interface in mxc_lobes.glsl normalises it).
vec3 mxc_sheen_unnormalized(vec3 color, float r, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float g = 1.0 / (1.0 + mxc_sheen_lambda(wo.z, r) + mxc_sheen_lambda(wi.z, r));
  return color * mxc_sheen_d(r, h.z) * g / (4.0 * wo.z);  // f |cos| = D G / (4 mu_o), F = 1
}
