// Hair fibre scattering (Chiang, Bitterli, Tappan & Burley 2016, "A Practical and Controllable
// Hair and Fur Model for Production Path Tracing"), MaterialX's chiang_hair_bsdf: a dielectric
// cylinder scattering light by R, TT, TRT and the sum of longer paths (p = 3), each the product
// of a longitudinal lobe Mp (d'Eon et al. 2011), an attenuation Ap and an azimuthal lobe Np
// (a trimmed logistic, Chiang 2016 s. 4.1).
//
// Local frame (mxc_frame): x along the fibre (the tangent), z the fibre's normal where the ray
// hits it. So the offset across the fibre is h = sin(gamma_o), gamma_o the angle from z to wo
// in the fibre's normal plane. The lobe returns f cos in the fibre's own measure,
// sum_p Mp Ap Np, whose integral over the sphere is sum_p Ap (both lobes are normalised): with
// no absorption and white tints exactly 1 (the white furnace).
//
// Parameters (MxcHair, filled from an MxcLobe by mxc_lobes.glsl): the tints of R, TT and TRT
// (the residual p = 3 takes TRT's); the fibre's IOR; each lobe's roughness pair (v, s): its
// longitudinal variance v and its azimuthal scale s before Chiang's sqrt(pi/8) (MaterialX's
// chiang_hair_roughness outputs); the cuticle tilt alpha (radians); the absorption coefficient
// sigma_a per unit fibre radius.
struct MxcHair {
  vec3 tintR, tintTT, tintTRT;
  vec3 sigmaA;
  float eta;
  vec2 rR, rTT, rTRT;
  float tilt;
};

const float MXC_HAIR_SQRT_PI_OVER_8 = 0.626657069;  // Chiang 2016 eq. 8

// log I0(x), I0 the modified Bessel function of the first kind (d'Eon 2011 eq. 5's I0): its
// series sum_k (x^2/4)^k / (k!)^2 up to k = 24 below x = 16 (error < 1e-11 there; the terms
// grow by q / k^2 at a time, so none overflows), above it the asymptotic expansion
// x - ln(2 pi x) / 2 + 1 / (8x) + 1 / (16 x^2) (Abramowitz & Stegun 9.7.1; error < 2e-5).
float mxc_hair_log_i0(float x) {
  if (x > 16.0) return x - 0.5 * log(2.0 * MXC_PI * x) + 1.0 / (8.0 * x) + 1.0 / (16.0 * x * x);  // x > 16
  float q = 0.25 * x * x;
  float term = 1.0;
  float sum = 1.0;
  for (int k = 1; k <= 24; ++k) {
    term *= q / float(k * k);
    sum += term;
  }
  return log(sum);  // sum >= 1
}

// The longitudinal lobe (d'Eon et al. 2011 eq. 7): csch(1/v) / (2v) exp(-sin_i sin_o / v)
// I0(cos_i cos_o / v), normalised over theta_i with the cos(theta_i) measure. Evaluated as the
// exponential of its logarithm so that small variances (v down to 1e-3: 1/v = 1000) neither
// overflow sinh nor I0; csch(1/v) / 2 = exp(-1/v) / (1 - exp(-2/v)).
float mxc_hair_mp(float sinI, float cosI, float sinO, float cosO, float v) {
  float inv = 1.0 / v;  // v >= 1e-3 (mxc_hair_v)
  float a = cosI * cosO * inv;
  float b = sinI * sinO * inv;
  float logNorm = -inv - log(v) - log(1.0 - exp(-2.0 * inv));  // 1 - exp(-2/v) >= 1 - exp(-2) for v <= 1
  return exp(mxc_hair_log_i0(max(a, 0.0)) - b + logNorm);
}

// The logistic distribution of scale s, its cumulative distribution, and its restriction to
// [-pi, pi] (Chiang 2016 eqs. 10-12). s >= 1e-3 sqrt(pi/8) (mxc_hair_s).
float mxc_hair_logistic(float x, float s) {
  float e = exp(-abs(x) / s);  // symmetric; the negative exponent cannot overflow
  return e / (s * mxc_sqr(1.0 + e));
}
float mxc_hair_logistic_cdf(float x, float s) { return 1.0 / (1.0 + exp(-x / s)); }
float mxc_hair_np_trimmed(float x, float s) {
  // The mass of [-pi, pi]: > 0.5 for every s > 0.
  return mxc_hair_logistic(x, s) / (mxc_hair_logistic_cdf(MXC_PI, s) - mxc_hair_logistic_cdf(-MXC_PI, s));
}

// Roughness guards, after MaterialX's clamp of the roughness pairs to [0.001, 1].
float mxc_hair_v(float v) { return clamp(v, 1e-3, 1.0); }
float mxc_hair_s(float s) { return clamp(s, 1e-3, 1.0) * MXC_HAIR_SQRT_PI_OVER_8; }

float mxc_hair_wrap(float x) {  // to [-pi, pi]
  return x - 2.0 * MXC_PI * floor((x + MXC_PI) / (2.0 * MXC_PI));
}

// What is shared by every evaluation at one wo: the angles of wo and the lobes' attenuations.
struct MxcHairView {
  float sinO, cosO;
  float phiO;     // azimuth of wo in the fibre's normal plane, from z towards y
  float gammaO;   // = phiO: the hit point's normal is z (|gammaO| <= pi/2 for wo.z >= 0)
  float gammaT;   // the refracted azimuth (Bravais: the modified IOR eta')
  vec3 a[4];      // Ap times the tint, p = 0..3
};

// The fibre seen from a direction with wo.z < 0 is the fibre seen from the other side: the frame
// turned by pi about the fibre (y, z -> -y, -z), which changes nothing physical.
vec3 mxc_hair_side(vec3 w, bool flip) { return flip ? vec3(w.x, -w.y, -w.z) : w; }

MxcHairView mxc_hair_view(MxcHair l, vec3 wo) {
  MxcHairView h;
  h.sinO = clamp(wo.x, -1.0, 1.0);
  h.cosO = mxc_safe_sqrt(1.0 - h.sinO * h.sinO);
  // Along the fibre (no projection onto its normal plane) any azimuth is the same: 0.
  h.phiO = wo.y * wo.y + wo.z * wo.z > 1e-12 ? atan(wo.y, wo.z) : 0.0;
  h.gammaO = h.phiO;
  float eta = max(l.eta, 1e-3);  // IORs are kept >= 1e-3 (as the generator does)
  // Bravais' modified IOR for the projection into the normal plane (Chiang 2016 s. 4.2):
  // sqrt(eta^2 - sin^2 theta_o) / cos theta_o; cos theta_o >= 1e-4 (grazing along the fibre)
  // and eta' >= 1e-3 (an IOR below 1 seen at a steep longitudinal angle).
  float etaP = max(mxc_safe_sqrt(eta * eta - h.sinO * h.sinO) / max(h.cosO, 1e-4), 1e-3);
  float sinGammaT = clamp(sin(h.gammaO) / etaP, -1.0, 1.0);
  h.gammaT = asin(sinGammaT);  // |argument| <= 1
  float sinT = h.sinO / eta;
  float cosT = max(mxc_safe_sqrt(1.0 - sinT * sinT), 1e-4);  // 1e-4: eta = 1 at a grazing theta_o
  // Attenuation (Chiang 2016 eq. 3 and s. 4.2): Fresnel at the cosine cos(theta_o) cos(gamma_o),
  // transmittance along a chord of length 2 cos(gamma_t) / cos(theta_t), and the geometric
  // series of the paths longer than TRT.
  float f = mxc_fresnel_dielectric(clamp(h.cosO * cos(h.gammaO), 0.0, 1.0), eta);
  vec3 t = exp(-max(l.sigmaA, vec3(0.0)) * (2.0 * cos(h.gammaT) / cosT));
  vec3 a1 = mxc_sqr(1.0 - f) * t;
  vec3 a2 = a1 * t * f;
  // 1 - t f > 0 unless t = f = 1, where a2 = 0 (f = 1 leaves nothing to transmit).
  vec3 a3 = a2 * t * f / max(vec3(1.0) - t * f, vec3(1e-4));
  h.a[0] = vec3(f) * clamp(l.tintR, 0.0, 1.0);
  h.a[1] = a1 * clamp(l.tintTT, 0.0, 1.0);
  h.a[2] = a2 * clamp(l.tintTRT, 0.0, 1.0);
  h.a[3] = a3 * clamp(l.tintTRT, 0.0, 1.0);
  return h;
}

// Lobe p's (v, s) and the tilt of its cone: theta_o turned by m alpha with m = 2, -1, -4 for
// R, TT, TRT (Chiang 2016 s. 4.1; MaterialX's sign of the cuticle angle); the residual p = 3
// is not tilted and has a uniform azimuth.
vec2 mxc_hair_roughness(MxcHair l, int p) {
  vec2 vs = p == 0 ? l.rR : (p == 1 ? l.rTT : l.rTRT);
  return vec2(mxc_hair_v(vs.x), mxc_hair_s(vs.y));
}
float mxc_hair_tilt(MxcHair l, int p) { return p == 0 ? 2.0 * l.tilt : (p == 1 ? -l.tilt : (p == 2 ? -4.0 * l.tilt : 0.0)); }

// Centre of lobe p's azimuthal lobe (Chiang 2016 eq. 5): Phi = 2 p gamma_t - 2 gamma_o + p pi.
float mxc_hair_phi(MxcHairView h, int p) { return 2.0 * float(p) * h.gammaT - 2.0 * h.gammaO + float(p) * MXC_PI; }

// Mp Np of lobe p at wi (given by sin theta_i, cos theta_i and the relative azimuth phi).
float mxc_hair_lobe(MxcHair l, MxcHairView h, int p, float sinI, float cosI, float phi) {
  vec2 vs = mxc_hair_roughness(l, p);
  float tilt = mxc_hair_tilt(l, p);
  float sinO = h.sinO * cos(tilt) + h.cosO * sin(tilt);
  float cosO = abs(h.cosO * cos(tilt) - h.sinO * sin(tilt));
  float mp = mxc_hair_mp(sinI, cosI, sinO, cosO, vs.x);
  float np = p == 3 ? 0.5 * MXC_INV_PI : mxc_hair_np_trimmed(mxc_hair_wrap(phi - mxc_hair_phi(h, p)), vs.y);
  return mp * np;
}

// How lobe p is chosen when sampling: by the luminance of its attenuation (the floor keeps the
// choice defined when everything is absorbed).
float mxc_hair_choice(MxcHairView h, int p) { return max(mxc_luminance(h.a[p]), 0.0) + 1e-6; }

vec3 mxc_hair_albedo(MxcHair l, vec3 wo) {
  MxcHairView h = mxc_hair_view(l, mxc_hair_side(wo, wo.z < 0.0));
  return h.a[0] + h.a[1] + h.a[2] + h.a[3];
}

// A direction pair seen from wo's side of the fibre (mxc_hair_side): the view's quantities and
// wi's longitudinal angle and azimuth relative to wo's.
struct MxcHairPair {
  MxcHairView h;
  float sinI, cosI, phi;
};
MxcHairPair mxc_hair_pair(MxcHair l, vec3 wo, vec3 wi) {
  bool flip = wo.z < 0.0;
  wo = mxc_hair_side(wo, flip);
  wi = mxc_hair_side(wi, flip);
  MxcHairPair x;
  x.h = mxc_hair_view(l, wo);
  x.sinI = clamp(wi.x, -1.0, 1.0);
  x.cosI = mxc_safe_sqrt(1.0 - x.sinI * x.sinI);
  x.phi = (wi.y * wi.y + wi.z * wi.z > 1e-12 ? atan(wi.y, wi.z) : 0.0) - x.h.phiO;
  return x;
}

vec3 mxc_hair_eval(MxcHair l, vec3 wo, vec3 wi) {
  MxcHairPair x = mxc_hair_pair(l, wo, wi);
  vec3 f = vec3(0.0);
  for (int p = 0; p < 4; ++p) f += x.h.a[p] * mxc_hair_lobe(l, x.h, p, x.sinI, x.cosI, x.phi);
  return f;
}

float mxc_hair_pdf(MxcHair l, vec3 wo, vec3 wi) {
  MxcHairPair x = mxc_hair_pair(l, wo, wi);
  float total = 0.0;
  float pdf = 0.0;
  for (int p = 0; p < 4; ++p) {
    float c = mxc_hair_choice(x.h, p);
    total += c;
    pdf += c * mxc_hair_lobe(l, x.h, p, x.sinI, x.cosI, x.phi);
  }
  return pdf / total;  // total >= 4e-6
}

// Importance sampling (d'Eon et al. 2013, "Importance Sampling for Physically-Based Hair Fiber
// Models"; Chiang 2016 s. 4.1): a lobe p by its attenuation, theta_i from Mp exactly, the
// azimuth from the trimmed logistic exactly (uniform for p = 3). u.z chooses p and, rescaled,
// samples the azimuth.
vec3 mxc_hair_sample(MxcHair l, vec3 wo, vec3 u) {
  bool flip = wo.z < 0.0;
  vec3 o = mxc_hair_side(wo, flip);
  MxcHairView h = mxc_hair_view(l, o);
  float c[4];
  float total = 0.0;
  for (int p = 0; p < 4; ++p) {
    c[p] = mxc_hair_choice(h, p);
    total += c[p];
  }
  float x = u.z * total;
  int p = 3;
  float before = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (x < before + c[k]) {
      p = k;
      break;
    }
    before += c[k];
  }
  float uz = clamp((x - before) / c[p], 0.0, 0.99999994);  // c[p] >= 1e-6
  vec2 vs = mxc_hair_roughness(l, p);
  float tilt = mxc_hair_tilt(l, p);
  float sinO = h.sinO * cos(tilt) + h.cosO * sin(tilt);
  float cosO = abs(h.cosO * cos(tilt) - h.sinO * sin(tilt));
  // Mp: cos of the angle to the cone's axis by inverting its cdf (d'Eon 2013 eq. 6);
  // u.x >= 1e-5 keeps the logarithm finite where exp(-2/v) underflows to 0.
  float u1 = max(u.x, 1e-5);
  float cosTheta = clamp(1.0 + vs.x * log(u1 + (1.0 - u1) * exp(-2.0 / vs.x)), -1.0, 1.0);
  float sinTheta = mxc_safe_sqrt(1.0 - cosTheta * cosTheta);
  float sinI = clamp(-cosTheta * sinO + sinTheta * cos(2.0 * MXC_PI * u.y) * cosO, -1.0, 1.0);
  float cosI = mxc_safe_sqrt(1.0 - sinI * sinI);
  float dphi;
  if (p < 3) {
    // The trimmed logistic's inverse cdf: its cdf at -pi plus uz times its mass on [-pi, pi].
    float lo = mxc_hair_logistic_cdf(-MXC_PI, vs.y);
    float hi = mxc_hair_logistic_cdf(MXC_PI, vs.y);
    float y = clamp(lo + uz * (hi - lo), 1e-7, 1.0 - 1e-7);  // strictly inside (0, 1) for the log
    dphi = mxc_hair_phi(h, p) - vs.y * log(1.0 / y - 1.0);
  } else {
    dphi = 2.0 * MXC_PI * uz;
  }
  float phiI = h.phiO + dphi;
  vec3 i = vec3(sinI, cosI * sin(phiI), cosI * cos(phiI));
  return mxc_hair_side(i, flip);
}
