// Fuzz (OpenPBR "Fuzz"; Zeltner, Burley & Chiang 2022, "Practical Multiple-Scattering Sheen
// Using Linearly Transformed Cosines"): a unit-thickness, non-absorbing volume of fibre-like SGGX
// microflakes, approximated by a linearly transformed cosine (Heitz et al. 2016) whose inverse
// matrix and reflectance R depend on the view cosine mu and the roughness r:
//
//   mu_i f(wo, wi) = R(mu, r) D(wi),  D(w) = D_cos(M^-1 w / |M^-1 w|) |M^-1| / |M^-1 w|^3,
//   M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]]   in the frame whose x axis is wo's tangent part.
//
// a, b and R are smooth fits of Zeltner's 32 x 32 table by Hill (the coefficients MaterialX 1.39
// publishes for its sheen_bsdf "zeltner" mode): a and b rational in (mu, r), R a Gaussian in mu
// whose centre, width and offset are rational in r. Against the table's alpha = 1 row, R is within
// 0.005 (tests/runtime/EvaluatorTest.cpp). The fit covers r in [0.01, 1]; roughness is
// clamped to it, as in the original table.
//
// D is a normalised density over the upper hemisphere (M^-1 keeps w.z, so nothing maps below the
// horizon): the lobe's albedo is exactly R, and sampling D is exact importance sampling.

float mxc_fuzz_roughness(float r) { return clamp(r, 0.01, 1.0); }

// R(mu, r). The denominators are positive for r in [0.01, 1]: 0.0379 + r (1.322 + r) > 0;
// 0.0464 + r > 0; r^2 - 1.920 r + 1.263 has no real root. s > 0 for r > 0.
float mxc_fuzz_albedo(float mu, float r) {
  float s = r * (0.0206607 + 1.58491 * r) / (0.0379424 + r * (1.32227 + r));
  float m = r * (-0.193854 + r * (-1.14885 + r * (1.7932 - 0.95943 * r * r))) / (0.046391 + r);
  float o = r * (0.000654023 + (-0.0207818 + 0.119681 * r) * r) / (1.26264 + r * (-1.92021 + r));
  float g = exp(-0.5 * mxc_sqr((mu - m) / s)) / (s * sqrt(2.0 * MXC_PI));
  // The fit dips to -2e-5 near r = 0.1 and peaks at 0.745 (mu = 0, r = 1): clamped to [0, 1].
  return clamp(g + o, 0.0, 1.0);
}

// (a, b) of M^-1 at (mu, r). a > 0: both terms of its numerator are >= 0 and 0.8137 r^2 > 0,
// the denominator is >= 1. b's denominator 2.5e-5 + mu (1.712 - 1.715 r) + 1.342 r^2 stays
// >= 1.5e-4 over mu, r in [0, 1] x [0.01, 1].
vec2 mxc_fuzz_ltc(float mu, float r) {
  float a = (2.58126 * mu + 0.813703 * r) * r / (1.0 + 0.310327 * mu * mu + 2.60994 * mu * r);
  float b = sqrt(1.0 - mu) * (r - 1.0) * r * r * r /
            (0.0000254053 + 1.71228 * mu - 1.71506 * mu * r + 1.34174 * r * r);
  return vec2(a, b);
}

// The x axis of the LTC frame: wo's tangent part, or any tangent when wo is the normal (the lobe
// is then rotationally symmetric: b = 0 at mu = 1).
vec2 mxc_fuzz_axis(vec3 wo) {
  float len2 = dot(wo.xy, wo.xy);
  return len2 > 1e-12 ? wo.xy * inversesqrt(len2) : vec2(1.0, 0.0);
}

// A local direction in the LTC frame of wo (a rotation about the normal), and back.
vec3 mxc_fuzz_to_ltc(vec3 wo, vec3 w) {
  vec2 x = mxc_fuzz_axis(wo);
  return vec3(dot(w.xy, x), dot(w.xy, vec2(-x.y, x.x)), w.z);
}
vec3 mxc_fuzz_from_ltc(vec3 wo, vec3 w) {
  vec2 x = mxc_fuzz_axis(wo);
  return vec3(w.x * x.x - w.y * x.y, w.x * x.y + w.y * x.x, w.z);
}

// D(w) for w in the LTC frame with w.z > 0: D_cos(t / |t|) a^2 / |t|^3 = t.z a^2 / (pi |t|^4),
// t = M^-1 w. |t|^2 >= w.z^2 > 0.
float mxc_fuzz_d(vec2 ab, vec3 w) {
  vec3 t = vec3(ab.x * w.x + ab.y * w.z, ab.x * w.y, w.z);
  float len2 = dot(t, t);
  return MXC_INV_PI * t.z * mxc_sqr(ab.x / len2);
}

// The density D of wi (local frame, z = normal): the lobe's pdf.
float mxc_fuzz_pdf(float roughness, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
  float r = mxc_fuzz_roughness(roughness);
  return mxc_fuzz_d(mxc_fuzz_ltc(min(wo.z, 1.0), r), mxc_fuzz_to_ltc(wo, wi));
}

// f |cos theta_i| with colour c: c R D.
vec3 mxc_fuzz_eval(vec3 c, float roughness, vec3 wo, vec3 wi) {
  float d = mxc_fuzz_pdf(roughness, wo, wi);
  return d > 0.0 ? c * (mxc_fuzz_albedo(min(wo.z, 1.0), mxc_fuzz_roughness(roughness)) * d) : vec3(0.0);
}

// A direction distributed as D: a cosine-distributed d mapped by M = [[1/a, 0, -b/a], [0, 1/a, 0],
// [0, 0, 1]] and normalised (|M d| >= d.z, and d is a unit vector with a > 0, so M d != 0),
// then rotated out of the LTC frame.
vec3 mxc_fuzz_sample(float roughness, vec3 wo, vec2 u) {
  float r = mxc_fuzz_roughness(roughness);
  vec2 ab = mxc_fuzz_ltc(clamp(wo.z, 0.0, 1.0), r);
  vec3 d = mxc_sample_cosine(u);
  return mxc_fuzz_from_ltc(wo, normalize(vec3((d.x - ab.y * d.z) / ab.x, d.y / ab.x, d.z)));
}

// The fuzz's reflectance averaged over cosine-distributed light, 2 integral_0^1 R(mu, r) mu dmu:
// 8-point Gauss-Legendre on [0, 1] (R is smooth in mu: a Gaussian and an offset).
float mxc_fuzz_average(float roughness) {
  float r = mxc_fuzz_roughness(roughness);
  const float x[8] = float[](0.0198551, 0.1016667, 0.2372338, 0.4082826, 0.5917174, 0.7627662, 0.8983333, 0.9801449);
  const float w[8] = float[](0.0506143, 0.1111905, 0.1568533, 0.1813419, 0.1813419, 0.1568533, 0.1111905, 0.0506143);
  float sum = 0.0;
  for (int k = 0; k < 8; ++k) sum += 2.0 * w[k] * x[k] * mxc_fuzz_albedo(x[k], r);
  return sum;
}

#ifdef MXC_ACCURACY_FAST
// The fast tier keeps OpenPBR's layering of the fuzz, f_fuzz + (1 - E_fuzz) f_base: nothing more.
vec3 mxc_fuzz_darkening(vec3 c, float roughness, vec3 Eb) { return vec3(1.0); }
vec3 mxc_fuzz_recycling(vec3 c, float roughness, vec3 Eb) { return vec3(1.0); }
#else
// OpenPBR "Fuzz" is a volume that passes what it does not reflect: light the base under it
// (albedo E_b) reflects back up meets it again, and of that diffuse light the fibres return
// c E_avg down to the base and pass 1 - E_avg. So the base's light leaves with
// (1 - E_avg) / (1 - E_b c E_avg) of what albedo scaling gives it (the interfaced-Lambertian
// form of OpenPBR "Darkening" for a fuzz), and light emitted under the fuzz with
// 1 / (1 - E_b c E_avg) besides its own transmission. The reference walk does this: albedo
// scaling alone left white fuzz over a grey base 0.03 brighter than the walk (issue 39).
vec3 mxc_fuzz_recycling(vec3 c, float roughness, vec3 Eb) {
  float e = mxc_fuzz_average(roughness);
  return vec3(1.0) / (vec3(1.0) - clamp(Eb, 0.0, 1.0) * clamp(c, 0.0, 1.0) * e);  // >= 1 - e > 0 (e <= 0.75)
}
vec3 mxc_fuzz_darkening(vec3 c, float roughness, vec3 Eb) {
  return (1.0 - mxc_fuzz_average(roughness)) * mxc_fuzz_recycling(c, roughness, Eb);
}
#endif
