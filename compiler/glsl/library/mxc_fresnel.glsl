// Fresnel factors: exact dielectric and conductor reflectance, Schlick and the F82-tint model,
// OpenPBR's specular_weight modulation, and thin-film interference.

// Unpolarised reflectance of a dielectric interface (Born & Wolf 1999, s. 1.5.2), for the cosine
// `cosi` >= 0 on the incident side and the relative IOR eta = n_transmitted / n_incident > 0.
// Total internal reflection gives 1. An index-matched interface (eta = 1) reflects nothing at
// any angle (physics notes, case 11).
float mxc_fresnel_dielectric(float cosi, float eta) {
  if (abs(eta - 1.0) < 1e-6) return 0.0;
  float sin2t = (1.0 - cosi * cosi) / (eta * eta);  // eta > 0
  if (sin2t >= 1.0) return 1.0;
  float cost = sqrt(1.0 - sin2t);
  // Both denominators are > 0: cosi >= 0, cost > 0 (cost = 0 only under TIR, handled above).
  float rs = (cosi - eta * cost) / (cosi + eta * cost);
  float rp = (eta * cosi - cost) / (eta * cosi + cost);
  return 0.5 * (rs * rs + rp * rp);
}

// The grazing reflectance of the fast tier's Schlick Fresnel: 1, faded out as F0 falls below
// 0.02 (IOR ratios within about 1.33 of 1), so that the Fresnel goes continuously to 0 at index
// matching instead of jumping from (1 - c)^5 to 0; the real-time shortcut of Schueler 2009
// ("An efficient and physically plausible real-time shading model", ShaderX7), used by Filament.
float mxc_schlick_f90(float f0) { return clamp(50.0 * f0, 0.0, 1.0); }

// Schlick's approximation of the dielectric Fresnel (Schlick 1994), the real-time shortcut of
// the fast tier: F0 + (F90 - F0)(1 - c)^5 with F0 = ((eta - 1) / (eta + 1))^2 and F90 from
// mxc_schlick_f90, whose albedo over a GGX lobe is exactly the split sum F0 A + F90 B the tier's
// layering uses. Seen from the denser side (eta < 1) c is the transmitted cosine, so that total
// internal reflection gives 1 (Lagarde 2013, "Memo on Fresnel equations").
float mxc_fresnel_dielectric_schlick(float cosi, float eta) {
  float f0 = mxc_sqr((eta - 1.0) / (eta + 1.0));  // eta > 0
  float c = cosi;
  if (eta < 1.0) {
    float sin2t = (1.0 - cosi * cosi) / (eta * eta);
    if (sin2t >= 1.0) return 1.0;
    c = sqrt(1.0 - sin2t);
  }
  return f0 + (mxc_schlick_f90(f0) - f0) * pow(clamp(1.0 - c, 0.0, 1.0), 5.0);
}

// Complex helpers for conductors: vec2 = (re, im).
vec2 mxc_cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 mxc_cdiv(vec2 a, vec2 b) {
  float d = dot(b, b);  // callers divide by sums with positive real part: d > 0
  return vec2(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / d;
}
vec2 mxc_csqrt(vec2 z) {  // principal square root
  float r = length(z);
  float re = mxc_safe_sqrt(0.5 * (r + z.x));
  float im = mxc_safe_sqrt(0.5 * (r - z.x));
  return vec2(re, z.y < 0.0 ? -im : im);
}

// Complex reflection amplitudes rs, rp at an interface into a medium of complex relative IOR
// eta = n + ik (Born & Wolf 1999, s. 14.2), for the incident cosine `cosi` >= 0.
void mxc_fresnel_complex_amplitudes(float cosi, vec2 eta, out vec2 rs, out vec2 rp) {
  float sin2i = 1.0 - cosi * cosi;
  vec2 eta2 = mxc_cmul(eta, eta);
  // cos_t = sqrt(1 - sin2i / eta^2)
  vec2 cost = mxc_csqrt(vec2(1.0, 0.0) - mxc_cdiv(vec2(sin2i, 0.0), eta2));
  vec2 etaCost = mxc_cmul(eta, cost);
  vec2 ci = vec2(cosi, 0.0);
  rs = mxc_cdiv(ci - etaCost, ci + etaCost);
  vec2 etaCosi = eta * cosi;
  rp = mxc_cdiv(etaCosi - cost, etaCosi + cost);
}

// Unpolarised reflectance of a conductor with complex IOR n + ik per channel.
vec3 mxc_fresnel_conductor(float cosi, vec3 n, vec3 k) {
  vec3 f;
  for (int c = 0; c < 3; ++c) {
    vec2 rs, rp;
    mxc_fresnel_complex_amplitudes(max(cosi, 0.0), vec2(n[c], k[c]), rs, rp);
    f[c] = 0.5 * (dot(rs, rs) + dot(rp, rp));
  }
  return clamp(f, 0.0, 1.0);
}

// Generalised Schlick: F0 + (F90 - F0)(1 - mu)^exponent (Schlick 1994). pow of a value in [0, 1].
vec3 mxc_fresnel_schlick(float mu, vec3 f0, vec3 f90, float exponent) {
  return f0 + (f90 - f0) * pow(clamp(1.0 - mu, 0.0, 1.0), exponent);
}

// F82-tint (Kutz et al. 2021; OpenPBR 1.1 "Metal"): the Schlick curve corrected so that at
// mu_bar = 1/7 (about 82 degrees) it equals tint * F_Schlick(mu_bar):
//   F(mu) = F_s(mu) - mu (1 - mu)^6 / (mu_bar (1 - mu_bar)^6) * F_s(mu_bar) (1 - tint).
vec3 mxc_fresnel_f82(float mu, vec3 f0, vec3 f90, float exponent, vec3 tint) {
  const float muBar = 1.0 / 7.0;
  const float denominator = muBar * 0.396569;  // (1 - 1/7)^6 = 0.396569...
  vec3 fs = mxc_fresnel_schlick(mu, f0, f90, exponent);
  vec3 fsBar = mxc_fresnel_schlick(muBar, f0, f90, exponent);
  float m = clamp(mu, 0.0, 1.0);
  float shape = m * pow(1.0 - m, 6.0) / denominator;
  return clamp(fs - shape * fsBar * (1.0 - tint), 0.0, 1.0);
}

// OpenPBR 1.1 eq. modulated_ior: the relative IOR whose normal-incidence reflectance is
// xi * F_s, F_s = ((1 - eta) / (1 + eta))^2, with xi clamped to [0, 1 / F_s].
float mxc_modulated_eta(float eta, float xi) {
  float fs = mxc_sqr((1.0 - eta) / (1.0 + eta));  // eta > 0: 1 + eta > 1
  if (fs <= 0.0) return 1.0;
  float x = clamp(xi, 0.0, 1.0 / fs);
  // epsilon = sgn(eta - 1) sqrt(xi F_s) in [-1, 1]; kept inside (-1, 1) so 1 - eps > 0.
  float e = clamp(sign(eta - 1.0) * sqrt(x * fs), -0.9999, 0.9999);
  return (1.0 + e) / (1.0 - e);
}

#ifdef MXC_THIN_FILM
// Thin-film interference (Belcour & Barla 2017, "A Practical Extension to Microfacet Theory for
// the Modeling of Varying Iridescence"): the Airy series truncated after two orders, with the
// spectral integration done by their Gaussian fit of the CIE XYZ sensitivities, and the grey
// incoherent term kept apart so that a thick film averages to the incoherent limit.

// Their fit of the XYZ sensitivity: for an optical path difference opd (nm) and a phase shift
// psi, channel c's interference term is sum_j val_j sqrt(2 pi var_j) cos(pos_j phi + psi)
// exp(-phi^2 var_j), phi = 2 pi 1e-9 opd, over one Gaussian per channel plus a second one for X,
// normalised by 1.0685e-7 so that a zero difference gives (1, 1, 1). Order m of the Airy series
// has m opd and m psi, so its cosine is cos(m theta) with theta = pos phi + psi and its Gaussian
// exp(-phi^2 var)^(m^2): both follow from order 1 without more transcendentals (mxc_thin_film).
const vec3 MXC_FILM_VAL = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
const vec3 MXC_FILM_POS = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
const vec3 MXC_FILM_VAR = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
const float MXC_FILM_X2_VAL = 9.7470e-14;
const float MXC_FILM_X2_POS = 2.2399e+06;
const float MXC_FILM_X2_VAR = 4.5282e+09;
const float MXC_FILM_NORM = 1.0685e-7;

// XYZ to linear RGB with the equal-energy white point (CIE RGB), so that a grey stays grey
// (each row sums to 1). GLSL matrices are given column by column: these are the columns.
const mat3 MXC_XYZ_TO_RGB = mat3(2.3706743, -0.5138850, 0.0052982,
                                 -0.9000405, 1.4253036, -0.0146949,
                                 -0.4706338, 0.0885814, 1.0093968);

// Reflectance of a film of IOR eta2 and thickness d (nm) between a medium of IOR eta1 above and
// a base of complex IOR eta3 + i kappa3 (per channel; kappa 0 for a dielectric), at the incident
// cosine `cosi`. All IORs are relative to the medium above the film.
vec3 mxc_thin_film(float cosi, float eta2, vec3 eta3, vec3 kappa3, float d) {
  const float eta1 = 1.0;
  float sin2t = mxc_sqr(eta1 / eta2) * (1.0 - cosi * cosi);  // eta2 > 0
  if (sin2t >= 1.0) return vec3(1.0);  // total internal reflection at the film's top
  float cos2 = sqrt(1.0 - sin2t);
  float opd = 2.0 * eta2 * d * cos2;
  // Interface 1-2, both polarisations: real amplitudes; reflection from inside the film flips
  // the sign (a phase of pi), kept as the sign of the phase factor below.
  vec2 r12 = vec2((eta1 * cosi - eta2 * cos2) / (eta1 * cosi + eta2 * cos2),
                  (eta2 * cosi - eta1 * cos2) / (eta2 * cosi + eta1 * cos2));
  vec2 R12 = r12 * r12;
  vec2 T121 = 1.0 - R12;
  vec2 sign21 = vec2(r12.x < 0.0 ? 1.0 : -1.0, r12.y < 0.0 ? 1.0 : -1.0);  // cos of phi21 in {0, pi}
  // Interface 2-3 seen from the film, per channel: complex amplitudes (s in .xy, p in .zw). A
  // dielectric base has the same IOR in every channel: computed once.
  vec4 r23[3];
  for (int c = 0; c < 3; ++c) {
    if (c == 0 || eta3[c] != eta3[c - 1] || kappa3[c] != kappa3[c - 1]) {
      vec2 rs, rp;
      mxc_fresnel_complex_amplitudes(cos2, vec2(eta3[c], kappa3[c]) / eta2, rs, rp);
      r23[c] = vec4(rs, rp);
    } else {
      r23[c] = r23[c - 1];
    }
  }
  // The sensitivity terms of order 1 without the phase shift: their Gaussians (arguments <= 0)
  // and the cosine and sine of pos phi, per channel and for X's second Gaussian.
  float phi = 2.0 * MXC_PI * 1e-9 * opd;
  vec3 e1 = exp(-phi * phi * MXC_FILM_VAR);
  vec3 g1 = MXC_FILM_VAL * sqrt(2.0 * MXC_PI * MXC_FILM_VAR) * e1 / MXC_FILM_NORM;
  vec3 g2 = g1 * e1 * e1 * e1;  // exp(-(2 phi)^2 var) = exp(-phi^2 var)^4
  vec3 ca = cos(MXC_FILM_POS * phi), sa = sin(MXC_FILM_POS * phi);
  float ex = exp(-phi * phi * MXC_FILM_X2_VAR);
  float gx1 = MXC_FILM_X2_VAL * sqrt(2.0 * MXC_PI * MXC_FILM_X2_VAR) * ex / MXC_FILM_NORM;
  float gx2 = gx1 * ex * ex * ex;
  float cx = cos(MXC_FILM_X2_POS * phi), sx = sin(MXC_FILM_X2_POS * phi);
  vec3 grey = vec3(0.0);
  vec3 xyz = vec3(0.0);
  for (int pol = 0; pol < 2; ++pol) {
    vec3 re = pol == 0 ? vec3(r23[0].x, r23[1].x, r23[2].x) : vec3(r23[0].z, r23[1].z, r23[2].z);
    vec3 im = pol == 0 ? vec3(r23[0].y, r23[1].y, r23[2].y) : vec3(r23[0].w, r23[1].w, r23[2].w);
    vec3 R23 = re * re + im * im;
    // The phase shift psi = phi21 + arg(r23), as its cosine and sine: arg(r23) from r23 / |r23|.
    // A zero amplitude has no phase, but then r123 = 0 and its interference terms vanish whatever
    // psi is; the floor only keeps the division finite.
    vec3 inv = 1.0 / max(sqrt(R23), vec3(1e-30));
    vec3 cpsi = sign21[pol] * re * inv;
    vec3 spsi = sign21[pol] * im * inv;
    vec3 R123 = R12[pol] * R23;
    vec3 r123 = sqrt(R123);
    // 1 - R123 > 0: R12 < 1 away from grazing incidence; guarded for the grazing limit.
    vec3 Rs = T121[pol] * T121[pol] * R23 / max(1.0 - R123, vec3(1e-6));
    grey += R12[pol] + Rs;
    // Order 1: cos(pos phi + psi); order 2: cos(2 theta) = 2 cos^2 theta - 1.
    vec3 c1 = ca * cpsi - sa * spsi;
    float cx1 = cx * cpsi.x - sx * spsi.x;
    vec3 s1 = g1 * c1 + vec3(gx1 * cx1, 0.0, 0.0);
    vec3 s2 = g2 * (2.0 * c1 * c1 - 1.0) + vec3(gx2 * (2.0 * cx1 * cx1 - 1.0), 0.0, 0.0);
    vec3 cm = (Rs - T121[pol]) * r123;
    xyz += cm * 2.0 * s1;
#ifndef MXC_ACCURACY_FAST
    // The fast tier stops at the first order, the series' leading interference term.
    cm *= r123;
    xyz += cm * 2.0 * s2;
#endif
  }
  return clamp(0.5 * (grey + MXC_XYZ_TO_RGB * xyz), 0.0, 1.0);
}
#endif

// Hemispherical (cosine-weighted) average of the dielectric Fresnel factor from outside,
// E_F(eta) = integral_0^1 F(mu, eta) 2 mu dmu, by the midpoint rule in mu (16 points: within
// 3.2e-4 of the exact value for eta in [1.2, 3], checked against a 200,000-point sum).
float mxc_fresnel_average(float eta) {
  float sum = 0.0;
  for (int i = 0; i < 16; ++i) {
    float mu = (float(i) + 0.5) / 16.0;
    sum += mxc_fresnel_dielectric(mu, eta) * 2.0 * mu;
  }
  return sum / 16.0;
}

// OpenPBR "Darkening": the factor on the base under a coat. The internal reflections in a coat
// of relative IOR eta_c darken a base of normal-incidence albedo Eb by
// Delta = (1 - K) / (1 - Eb K) (eq. general_darkening_formula), K = lerp(K_s, K_r, r_b)
// (eq. internal_diffuse_reflection_coefficient_for_general_base) with K_s = F(mu_o, eta_c) and
// K_r = 1 - (1 - E_F(eta_c)) / eta_c^2. coat_darkening (delta) lerps the applied factor from 1
// (delta = 0: the base boosted by exactly 1 / Delta, eq. boost_factor) to Delta (delta = 1).
// A coat less dense than outside (eta_c < 1) traps nothing by total internal reflection: it is
// taken as index-matched (K = 0).
//
// K_r is the share of a Lambertian in the coat that the coat's top returns, by reciprocity
// 1 minus its hemispherical transmittance (1 - E_F) / eta_c^2. A dielectric base's diffuse light
// starts in the base's medium (eta_b, specular_ior): refracted into a denser coat it fills only
// the cone sin theta < eta_b / eta_c, and n sin theta is kept across the parallel interfaces,
// so what leaves is what a Lambertian in a medium of eta_b would let out, (1 - E_F) / eta_b^2 of
// it (the Fresnel of the coat's top is the same function of the angle outside):
// K_r = 1 - (1 - E_F(eta_c)) / min(eta_c, eta_b)^2. The spec's K_r assumes the coat's whole
// hemisphere; it darkened the default base under a coat of 1.6 by 0.03 more than the reference
// walk (issue 39). A metal base returns its light into the coat directly (eta_b = eta_c).
vec3 mxc_coat_darkening(float eta_c, float eta_b, vec3 Eb, float rb, float delta, float mu_o) {
  float eta = max(eta_c, 1.0);
#ifdef MXC_ACCURACY_FAST
  float cone = eta;  // the fast tier keeps the spec's K_r
#else
  float cone = min(eta, max(eta_b, 1.0));  // >= 1
#endif
  float Kr = 1.0 - (1.0 - mxc_fresnel_average(eta)) / (cone * cone);
  float Ks = mxc_fresnel_dielectric(clamp(mu_o, 0.0, 1.0), eta);
  // K < 1 keeps Delta defined: with Eb = 1 it is then exactly (1 - K) / (1 - K) = 1.
  float K = min(mix(Ks, Kr, clamp(rb, 0.0, 1.0)), 0.999);
  vec3 darkening = vec3(1.0 - K) / (vec3(1.0) - clamp(Eb, 0.0, 1.0) * K);  // denominator >= 1 - K > 0
  return mix(vec3(1.0), darkening, clamp(delta, 0.0, 1.0));
}

#ifdef MXC_ACCURACY_FAST
// The fast tier keeps OpenPBR's formula, L_e = lerp(1, T_coat, C) E: nothing returned.
vec3 mxc_coat_recycling(float eta_c, vec3 Eb, float rb, float mu_o, vec3 tau) { return vec3(1.0); }
#else
// What the coat and the base under it return of light emitted under the coat, besides the
// coat's own transmission: the part the coat reflects back down reaches the base, which
// reflects E_b of it up again, and so on: 1 / (1 - E_b K T_d^2), K as in mxc_coat_darkening
// (the darkening of light from above is this without T_d, times 1 - K, its first escape) and
// T_d the coat's transmittance for diffuse light crossing it, 2 integral_0^1 exp(-tau / mu) mu
// dmu = 2 E_3(tau) (Chandrasekhar 1960, s. 2.5), each way: 4-point Gauss-Legendre on [0, 1].
// `tau`: the coat's optical depth along the normal (0 for a clear coat: T_d = 1).
vec3 mxc_coat_recycling(float eta_c, vec3 Eb, float rb, float mu_o, vec3 tau) {
  float eta = max(eta_c, 1.0);
  float Kr = 1.0 - (1.0 - mxc_fresnel_average(eta)) / (eta * eta);  // eta >= 1
  float Ks = mxc_fresnel_dielectric(clamp(mu_o, 0.0, 1.0), eta);
  float K = min(mix(Ks, Kr, clamp(rb, 0.0, 1.0)), 0.999);
  const vec4 x = vec4(0.0694318, 0.3300095, 0.6699905, 0.9305682);  // nodes on [0, 1], > 0
  const vec4 w = vec4(0.1739274, 0.3260726, 0.3260726, 0.1739274);  // weights, summing to 1
  vec3 td = vec3(0.0);
  for (int k = 0; k < 4; ++k) td += 2.0 * w[k] * x[k] * exp(-max(tau, vec3(0.0)) / x[k]);
  return vec3(1.0) / (vec3(1.0) - clamp(Eb, 0.0, 1.0) * K * td * td);  // denominator >= 1 - K > 0
}
#endif
