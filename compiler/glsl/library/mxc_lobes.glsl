// BSDF lobes: evaluation (f times |cos theta_i|), sampling, pdf and directional albedo of each
// interface kind of the IR. Directions are in the lobe's local frame (z = shading normal).
// Only the kinds a material uses are compiled (the backend defines MXC_HAS_<KIND>).

#include "generated/mxc_lobe.glsl"

struct MxcLobeSample {
  vec3 wi;      // local
  vec3 value;   // f |cos| (for a delta: the discrete weight)
  float pdf;    // of wi, in solid angle (for a delta: the discrete probability)
  bool delta;
  bool valid;
};

// The albedo tables (computed by the harness with stages/mxc_tables.comp), MXC_TABLE_SIZE
// texels per axis, sqrt of the view cosine mu across and roughness down:
//   rows 0..n-1, at (mu, alpha): .x = A, .y = B of the GGX reflection with a Schlick Fresnel,
//     E = F0 A + F90 B; at (mu, roughness): .z = albedo of the sheen lobe with colour 1;
//   then MXC_TABLE_SLICES tables of the GGX reflection albedo with the exact dielectric Fresnel,
//     slice s for eta = 1 + 2 (s / (slices - 1))^2, at (mu, alpha): .x.
layout(set = 0, binding = MXC_TABLE_BINDING) uniform sampler2D mxc_tables;
vec4 mxc_table_at(float mu, float x, float firstRow) {
  const float n = float(MXC_TABLE_SIZE);
  const float rows = float(MXC_TABLE_SIZE * (1 + MXC_TABLE_SLICES));
  // Texel centres: sample i of a table is at (i + 0.5) / n across, so x = 0 and 1 hit the
  // first and last samples and linear filtering never reaches a neighbouring table. The view
  // axis holds sqrt(mu) (stages/mxc_tables.comp), dense near grazing.
  vec2 t = vec2(sqrt(clamp(mu, 0.0, 1.0)), clamp(x, 0.0, 1.0)) * (n - 1.0) + 0.5;
  return textureLod(mxc_tables, vec2(t.x / n, (firstRow + t.y) / rows), 0.0);
}
vec4 mxc_table(float mu, float x) { return mxc_table_at(mu, x, 0.0); }

// Reflection albedo of a GGX dielectric interface seen from the side of lower IOR (eta >= 1;
// for eta < 1 the table of 1 / eta is used: same F0, without the total internal reflection).
// IOR ratios above 3 use the table of 3.
float mxc_dielectric_albedo(float mu, float alpha, float eta) {
  float e = eta >= 1.0 ? eta : 1.0 / max(eta, 1e-3);
  float s = sqrt(clamp(0.5 * (e - 1.0), 0.0, 1.0)) * float(MXC_TABLE_SLICES - 1);  // inverse of eta(s)
  float s0 = min(floor(s), float(MXC_TABLE_SLICES - 2));
  float a = mxc_table_at(mu, alpha, float(MXC_TABLE_SIZE) * (1.0 + s0)).x;
  float b = mxc_table_at(mu, alpha, float(MXC_TABLE_SIZE) * (2.0 + s0)).x;
  return mix(a, b, s - s0);
}

// ---- Fresnel of a lobe, with its thin film ----

float mxc_lobe_eta(MxcLobe l, bool above) { return above ? l.eta : 1.0 / l.eta; }

vec3 mxc_lobe_fresnel(MxcLobe l, float cosh, bool above) {
  vec3 f;
  if (l.kind == MXC_LOBE_DIELECTRIC) {
    f = vec3(mxc_fresnel_dielectric(cosh, mxc_lobe_eta(l, above)));
  } else if (l.kind == MXC_LOBE_CONDUCTOR) {
    f = mxc_fresnel_conductor(cosh, l.c0, l.c1);
  } else {
    f = l.p1 * mxc_fresnel_f82(cosh, l.c0, l.c2, l.p0, l.c1);
  }
#ifdef MXC_THIN_FILM
  if (l.film.z > 0.0 && above) {
    // The base under the film: the dielectric's IOR, or for a conductor its complex IOR; the
    // Schlick metal has no physical IOR, so it is taken from its F0 (Gulbrandsen 2014, n for
    // k = 0) as the spec suggests ("Thin-film iridescence").
    vec3 n3 = vec3(l.eta);
    vec3 k3 = vec3(0.0);
    if (l.kind == MXC_LOBE_CONDUCTOR) {
      n3 = l.c0;
      k3 = l.c1;
    } else if (l.kind == MXC_LOBE_SCHLICK) {
      vec3 s = sqrt(clamp(l.c0, 0.0, 0.99));
      n3 = (1.0 + s) / (1.0 - s);  // 1 - s >= 0.005
    }
    vec3 film = mxc_thin_film(cosh, max(l.film.y, 1e-3), n3, k3, max(l.film.x, 0.0));
    f = mix(f, film, clamp(l.film.z, 0.0, 1.0));
  }
#endif
  return f;
}

// ---- Microfacet lobes: dielectric (reflection and transmission), conductor, Schlick ----

#if defined(MXC_HAS_DIELECTRIC) || defined(MXC_HAS_CONDUCTOR) || defined(MXC_HAS_SCHLICK)

// f |cos| of the reflection (Walter et al. 2007, eq. 20), wo and wi above.
vec3 mxc_microfacet_reflect(MxcLobe l, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0 || wi.z <= 0.0 || mxc_is_delta(l.alpha)) return vec3(0.0);
  vec3 h = normalize(wo + wi);  // both above: the sum is not zero
  vec3 f = mxc_lobe_fresnel(l, max(dot(wo, h), 0.0), true);
  if (l.kind == MXC_LOBE_DIELECTRIC) f *= l.c0;
  return f * mxc_ggx_d(h, l.alpha) * mxc_ggx_g2(wo, wi, l.alpha) / (4.0 * wo.z);
}

// f |cos| of the transmission (Walter et al. 2007, eq. 21) with the roles arranged so that its
// integral over wi is the transmittance (1 - F) seen from wo: flux is conserved, R + T = 1.
vec3 mxc_dielectric_transmit(MxcLobe l, vec3 wo, vec3 wi) {
  if (wo.z * wi.z >= 0.0 || mxc_is_delta(l.alpha)) return vec3(0.0);
  bool above = wo.z > 0.0;
  float eta = mxc_lobe_eta(l, above);  // n(wi side) / n(wo side)
  vec3 h = -(wo + eta * wi);
  if (dot(h, h) <= 1e-20) return vec3(0.0);  // eta = 1 and wi = -wo: a delta, not this lobe
  h = normalize(h) * sign(above ? 1.0 : -1.0);
  if (h.z < 0.0) h = -h;
  float ho = dot(wo, h);
  float hi = dot(wi, h);
  if (ho * hi >= 0.0) return vec3(0.0);  // not a refraction pair
  float denom = mxc_sqr(ho + eta * hi);
  if (denom <= 1e-20) return vec3(0.0);
  vec3 f = 1.0 - mxc_lobe_fresnel(l, abs(ho), above);
  // Separable Smith masking-shadowing G1(o) G1(i) (Walter et al. 2007, eq. 23): the
  // height-correlated form 1 / (1 + L(o) + L(i)) holds for reflection only (Heitz 2014, s. 6).
  float g = mxc_ggx_g1(vec3(wo.xy, abs(wo.z)), l.alpha) * mxc_ggx_g1(vec3(wi.xy, abs(wi.z)), l.alpha);
  float value = abs(ho * hi) * eta * eta * mxc_ggx_d(h, l.alpha) * g / (abs(wo.z) * denom);
  return value * f * l.c1;
}

#endif

// ---- Diffuse lobes ----

#if defined(MXC_HAS_DIFFUSE) || defined(MXC_HAS_EON) || defined(MXC_HAS_SHEET)
// Fujii's Oren-Nayar (Fujii 2012; OpenPBR eq. FON_brdf): (A + B s / t) / pi with
// A = 1 / (1 + (1/2 - 2/(3 pi)) sigma), B = sigma A, s = wi.wo - mu_i mu_o,
// t = max(mu_i, mu_o) when s > 0, else 1.
float mxc_fon(float sigma, vec3 wo, vec3 wi) {
  float a = 1.0 / (1.0 + (0.5 - 2.0 / (3.0 * MXC_PI)) * sigma);
  float s = dot(wi, wo) - wi.z * wo.z;
  float t = s > 0.0 ? max(max(wi.z, wo.z), 1e-6) : 1.0;  // s > 0 implies both cosines > 0 here
  return (a + sigma * a * s / t) * MXC_INV_PI;
}

// Its directional albedo, integrated in closed form for this project:
// E(theta) = A + (B / pi) G(theta), G = sin (theta - sin cos) + (2/3)(sin / cos)(1 - sin^3) - (2/3) sin.
float mxc_fon_albedo(float sigma, float mu) {
  float a = 1.0 / (1.0 + (0.5 - 2.0 / (3.0 * MXC_PI)) * sigma);
  float c = clamp(mu, 0.0, 1.0);
  float s = mxc_safe_sqrt(1.0 - c * c);
  float theta = acos(c);  // c in [0, 1]
  // (1 - s^3) / c -> 0 as c -> 0 (1 - s^3 ~ 3c^2/2): the guard only avoids 0/0.
  float tail = c > 1e-4 ? (1.0 - s * s * s) / c : 1.5 * c;
  float g = s * (theta - s * c) + (2.0 / 3.0) * s * tail - (2.0 / 3.0) * s;
  return a + sigma * a * g * MXC_INV_PI;
}

// EON (Portsmouth et al. 2024; OpenPBR eqs. EON_brdf, EON_comp): FON plus a reciprocal
// compensation rho_ms (1 - E(mu_i)) (1 - E(mu_o)) / pi, with
// rho_ms = rho^2 E_avg / (1 - E_avg) / (1 - rho (1 - E_avg)) and Fujii's average albedo
// E_avg = A (1 + (2/3 - 28/(15 pi)) sigma). For sigma = 0, E = 1 and the term vanishes.
vec3 mxc_eon(vec3 rho, float sigma, vec3 wo, vec3 wi) {
  vec3 f = rho * mxc_fon(sigma, wo, wi);
  float a = 1.0 / (1.0 + (0.5 - 2.0 / (3.0 * MXC_PI)) * sigma);
  float eavg = a * (1.0 + (2.0 / 3.0 - 28.0 / (15.0 * MXC_PI)) * sigma);
  if (eavg < 1.0 - 1e-6) {  // 1 - E_avg > 0 and 1 - rho (1 - E_avg) >= E_avg > 0: divisions safe
    vec3 rhoMs = rho * rho * eavg / (1.0 - eavg) / (1.0 - rho * (1.0 - eavg));
    f += rhoMs * (1.0 - mxc_fon_albedo(sigma, wi.z)) * (1.0 - mxc_fon_albedo(sigma, wo.z)) * MXC_INV_PI;
  }
  return f;
}
#endif

#ifdef MXC_HAS_BURLEY
// Burley 2012, "Physically-Based Shading at Disney", s. 5.3.
vec3 mxc_burley(vec3 rho, float roughness, vec3 wo, vec3 wi) {
  vec3 h = mxc_safe_normalize(wo + wi, vec3(0.0, 0.0, 1.0));
  float fd90 = 0.5 + 2.0 * roughness * mxc_sqr(dot(wi, h));
  float fi = 1.0 + (fd90 - 1.0) * pow(1.0 - clamp(wi.z, 0.0, 1.0), 5.0);
  float fo = 1.0 + (fd90 - 1.0) * pow(1.0 - clamp(wo.z, 0.0, 1.0), 5.0);
  return rho * MXC_INV_PI * fi * fo;
}
#endif

// ---- The lobe interface used by the closure ----

// Albedo tables are not used by the thin kinds; this keeps the sampler referenced either way.
vec3 mxc_lobe_albedo(MxcLobe l, vec3 wo) {
  float mu = clamp(wo.z, 0.0, 1.0);
  if (l.kind == MXC_LOBE_DIELECTRIC || l.kind == MXC_LOBE_CONDUCTOR || l.kind == MXC_LOBE_SCHLICK) {
    // Reflection albedo with a Schlick-shaped Fresnel between its normal and grazing values
    // (E = F0 A + F90 B, the tables' split sum); a transmitting dielectric gives what it does
    // not reflect to the layers under it.
    float alpha = sqrt(l.alpha.x * l.alpha.y);  // the table's isotropic alpha: geometric mean
    if (l.kind == MXC_LOBE_DIELECTRIC && !mxc_is_delta(l.alpha)) {
      vec3 e = vec3(mxc_dielectric_albedo(mu, alpha, l.eta));
#ifdef MXC_THIN_FILM
      if (l.film.z > 0.0) {
        // With a film, the tabulated albedo of the bare interface scaled by how much the film
        // changes the Fresnel factor at this view (exact for a smooth interface).
        float f = mxc_fresnel_dielectric(mu, l.eta);
        e *= f > 1e-6 ? mxc_lobe_fresnel(l, mu, true) / f : vec3(1.0);
      }
#endif
      return clamp(e * l.c0, 0.0, 1.0);
    }
    vec2 ab = mxc_table(mu, alpha).xy;
    vec3 f0 = mxc_lobe_fresnel(l, 1.0, true);
    vec3 f90 = mxc_lobe_fresnel(l, 0.0, true);
    vec3 tint = l.kind == MXC_LOBE_DIELECTRIC ? l.c0 : vec3(1.0);
    if (mxc_is_delta(l.alpha)) return mxc_lobe_fresnel(l, mu, true) * tint;
    return clamp((f0 * ab.x + f90 * ab.y) * tint, 0.0, 1.0);
  }
  if (l.kind == MXC_LOBE_SHEEN) return l.c0 * min(mxc_table(mu, l.p0).z, 1.0);
#ifdef MXC_HAS_FUZZ
  if (l.kind == MXC_LOBE_FUZZ) return l.c0 * mxc_fuzz_albedo(mu, mxc_fuzz_roughness(l.p0));
#endif
#if defined(MXC_HAS_DIFFUSE) || defined(MXC_HAS_EON) || defined(MXC_HAS_SHEET)
  if (l.kind == MXC_LOBE_DIFFUSE) return l.c0 * mxc_fon_albedo(l.p0, mu);
#endif
  if (l.kind == MXC_LOBE_SHEET) return l.c0;
  return l.c0;  // EON (albedo ~ rho), Burley, translucent
}

// What a lobe takes from the layers under it (albedo scaling, OpenPBR "Layering"): its albedo,
// except that a sheen or fuzz takes it untinted. Standard Surface "Sheen" passes
// 1 - sheen reflectance(sheen_brdf) and OpenPBR "Fuzz" 1 - F E_fuzz: the colour tints what the
// fibres reflect, not what passes between them.
vec3 mxc_lobe_layer_albedo(MxcLobe l, vec3 wo) {
  if (l.kind == MXC_LOBE_SHEEN || l.kind == MXC_LOBE_FUZZ) {
    MxcLobe white = l;
    white.c0 = vec3(1.0);
    return mxc_lobe_albedo(white, wo);
  }
  return mxc_lobe_albedo(l, wo);
}

vec3 mxc_lobe_eval(MxcLobe l, vec3 wo, vec3 wi) {
  switch (l.kind) {
#if defined(MXC_HAS_DIELECTRIC) || defined(MXC_HAS_CONDUCTOR) || defined(MXC_HAS_SCHLICK)
    case MXC_LOBE_DIELECTRIC:
      if (wo.z * wi.z > 0.0) {
        if ((l.mode & MXC_REFLECT) == 0) return vec3(0.0);
        if (wo.z < 0.0) {  // seen from inside: the mirrored configuration
          MxcLobe m = l;
          m.eta = 1.0 / l.eta;
          m.c0 = vec3(1.0);
          return mxc_microfacet_reflect(m, -wo, -wi);
        }
        return mxc_microfacet_reflect(l, wo, wi);
      }
      if ((l.mode & MXC_TRANSMIT) == 0 || (l.mode & MXC_THIN_WALL) != 0) return vec3(0.0);
      return mxc_dielectric_transmit(l, wo, wi);
    case MXC_LOBE_CONDUCTOR:
    case MXC_LOBE_SCHLICK:
      return mxc_microfacet_reflect(l, wo, wi);
#endif
#ifdef MXC_HAS_DIFFUSE
    case MXC_LOBE_DIFFUSE:
      return wo.z > 0.0 && wi.z > 0.0 ? l.c0 * mxc_fon(l.p0, wo, wi) * wi.z : vec3(0.0);
#endif
#ifdef MXC_HAS_EON
    case MXC_LOBE_EON:
      return wo.z > 0.0 && wi.z > 0.0 ? mxc_eon(l.c0, l.p0, wo, wi) * wi.z : vec3(0.0);
#endif
#ifdef MXC_HAS_BURLEY
    case MXC_LOBE_BURLEY:
      return wo.z > 0.0 && wi.z > 0.0 ? mxc_burley(l.c0, l.p0, wo, wi) * wi.z : vec3(0.0);
#endif
#ifdef MXC_HAS_TRANSLUCENT
    case MXC_LOBE_TRANSLUCENT:
      return wo.z * wi.z < 0.0 ? l.c0 * MXC_INV_PI * abs(wi.z) : vec3(0.0);
#endif
#ifdef MXC_HAS_SHEET
    case MXC_LOBE_SHEET: {
      // OpenPBR eq. thin_wall_subsurface: S (1 - g) / 2 reflected, S (1 + g) / 2 transmitted.
      float g = clamp(l.p0, -1.0, 1.0);
      float share = wo.z * wi.z > 0.0 ? 0.5 * (1.0 - g) : 0.5 * (1.0 + g);
      return l.c0 * share * MXC_INV_PI * abs(wi.z);
    }
#endif
#ifdef MXC_HAS_SHEEN
    case MXC_LOBE_SHEEN:
      // Estevez & Kulla's fitted shadowing lets the lobe reflect more than it receives near
      // grazing at low roughness; the lobe is scaled down by its tabulated albedo there.
      return mxc_sheen_unnormalized(l.c0, l.p0, wo, wi) / max(mxc_table(clamp(wo.z, 0.0, 1.0), l.p0).z, 1.0);
#endif
#ifdef MXC_HAS_FUZZ
    case MXC_LOBE_FUZZ:
      return mxc_fuzz_eval(l.c0, l.p0, wo, wi);
#endif
    default:
      return vec3(0.0);
  }
}

float mxc_lobe_pdf(MxcLobe l, vec3 wo, vec3 wi) {
  switch (l.kind) {
#if defined(MXC_HAS_DIELECTRIC) || defined(MXC_HAS_CONDUCTOR) || defined(MXC_HAS_SCHLICK)
    case MXC_LOBE_DIELECTRIC:
    case MXC_LOBE_CONDUCTOR:
    case MXC_LOBE_SCHLICK: {
      if (mxc_is_delta(l.alpha)) return 0.0;
      bool above = wo.z > 0.0;
      vec3 o = above ? wo : -wo;
      vec3 i = above ? wi : -wi;
      if (i.z > 0.0) {  // reflection: dwh/dwi = 1 / (4 |wo.h|)
        vec3 h = normalize(o + i);
        float p = mxc_ggx_pdf_vndf(o, h, l.alpha) / (4.0 * max(dot(o, h), 1e-6));
        if (l.kind != MXC_LOBE_DIELECTRIC) return p;
        // Reflection is chosen with probability F when the lobe also transmits (a thin sheet
        // included: its transmission is the delta straight through).
        float fr = mxc_mean(mxc_lobe_fresnel(l, max(dot(o, h), 0.0), above));
        return p * ((l.mode & MXC_TRANSMIT) != 0 && (l.mode & MXC_REFLECT) != 0 ? fr : 1.0);
      }
      if (l.kind != MXC_LOBE_DIELECTRIC || (l.mode & MXC_TRANSMIT) == 0 || (l.mode & MXC_THIN_WALL) != 0) return 0.0;
      float eta = mxc_lobe_eta(l, above);
      vec3 h = -(o + eta * i);
      if (dot(h, h) <= 1e-20) return 0.0;
      h = normalize(h);
      if (h.z < 0.0) h = -h;
      float ho = dot(o, h);
      float hi = dot(i, h);
      if (ho * hi >= 0.0) return 0.0;
      float denom = mxc_sqr(ho + eta * hi);
      if (denom <= 1e-20) return 0.0;
      float ft = 1.0 - mxc_mean(mxc_lobe_fresnel(l, abs(ho), above));
      float fr = (l.mode & MXC_REFLECT) != 0 ? 1.0 - ft : 0.0;
      // Transmission chosen with probability 1 - F (all of it when reflection is off).
      return mxc_ggx_pdf_vndf(o, h, l.alpha) * (fr > 0.0 ? ft : 1.0) * eta * eta * abs(hi) / denom;
    }
#endif
#ifdef MXC_HAS_TRANSLUCENT
    case MXC_LOBE_TRANSLUCENT:
      return wo.z * wi.z < 0.0 ? abs(wi.z) * MXC_INV_PI : 0.0;
#endif
#ifdef MXC_HAS_SHEET
    case MXC_LOBE_SHEET: {
      float g = clamp(l.p0, -1.0, 1.0);
      float share = wo.z * wi.z > 0.0 ? 0.5 * (1.0 - g) : 0.5 * (1.0 + g);
      return share * abs(wi.z) * MXC_INV_PI;
    }
#endif
#ifdef MXC_HAS_FUZZ
    case MXC_LOBE_FUZZ:
      return mxc_fuzz_pdf(l.p0, wo, wi);
#endif
    default:
      return wo.z > 0.0 && wi.z > 0.0 ? wi.z * MXC_INV_PI : 0.0;  // cosine sampling
  }
}

MxcLobeSample mxc_lobe_sample(MxcLobe l, vec3 wo, vec3 u) {
  MxcLobeSample s;
  s.valid = false;
  s.delta = false;
  s.pdf = 0.0;
  s.value = vec3(0.0);
  s.wi = vec3(0.0, 0.0, 1.0);
  switch (l.kind) {
#if defined(MXC_HAS_DIELECTRIC) || defined(MXC_HAS_CONDUCTOR) || defined(MXC_HAS_SCHLICK)
    case MXC_LOBE_DIELECTRIC:
    case MXC_LOBE_CONDUCTOR:
    case MXC_LOBE_SCHLICK: {
      bool above = wo.z > 0.0;
      vec3 o = above ? wo : -wo;
      if (o.z <= 0.0) return s;
      bool delta = mxc_is_delta(l.alpha);
      vec3 m = delta ? vec3(0.0, 0.0, 1.0) : mxc_ggx_sample_vndf(o, l.alpha, u.xy);
      float hm = dot(o, m);
      bool transmits = l.kind == MXC_LOBE_DIELECTRIC && (l.mode & MXC_TRANSMIT) != 0;
      bool reflects = l.kind != MXC_LOBE_DIELECTRIC || (l.mode & MXC_REFLECT) != 0;
      vec3 f = mxc_lobe_fresnel(l, max(hm, 0.0), above);
      // Reflection or transmission is chosen by the mean Fresnel (a thin film colours F); the
      // sample's value keeps the colour.
      float fr = l.kind == MXC_LOBE_DIELECTRIC ? mxc_mean(f) : 1.0;
      float pReflect = transmits ? (reflects ? fr : 0.0) : 1.0;
      if (u.z < pReflect) {
        vec3 i = reflect(-o, m);
        if (i.z <= 0.0) return s;
        s.wi = above ? i : -i;
        s.delta = delta;
        if (delta) {
          vec3 tint = l.kind == MXC_LOBE_DIELECTRIC ? (above ? l.c0 : vec3(1.0)) : vec3(1.0);
          s.value = f * tint;
          s.pdf = pReflect;
        } else {
          s.value = mxc_lobe_eval(l, wo, s.wi);
          s.pdf = mxc_lobe_pdf(l, wo, s.wi);
        }
        s.valid = s.pdf > 0.0;
        return s;
      }
      // Transmission.
      if ((l.mode & MXC_THIN_WALL) != 0) {
        // A thin sheet: the ray passes straight through, attenuated by (1 - F).
        s.wi = -wo;
        s.delta = true;
        s.value = (1.0 - f) * l.c1;
        s.pdf = 1.0 - pReflect;
        s.valid = s.pdf > 0.0;
        return s;
      }
      float eta = mxc_lobe_eta(l, above);
      vec3 i = refract(-o, m, 1.0 / eta);
      if (dot(i, i) == 0.0 || i.z >= 0.0) return s;  // total internal reflection: no transmission
      s.wi = above ? i : -i;
      s.delta = delta;
      if (delta) {
        s.value = (1.0 - f) * l.c1;
        s.pdf = 1.0 - pReflect;
      } else {
        s.value = mxc_lobe_eval(l, wo, s.wi);
        s.pdf = mxc_lobe_pdf(l, wo, s.wi);
      }
      s.valid = s.pdf > 0.0;
      return s;
    }
#endif
#if defined(MXC_HAS_TRANSLUCENT) || defined(MXC_HAS_SHEET)
    case MXC_LOBE_TRANSLUCENT:
    case MXC_LOBE_SHEET: {
      float g = l.kind == MXC_LOBE_SHEET ? clamp(l.p0, -1.0, 1.0) : 1.0;
      float pReflect = 0.5 * (1.0 - g);
      vec3 d = mxc_sample_cosine(u.xy);
      s.wi = (u.z < pReflect) == (wo.z > 0.0) ? d : -d;
      s.value = mxc_lobe_eval(l, wo, s.wi);
      s.pdf = mxc_lobe_pdf(l, wo, s.wi);
      s.valid = s.pdf > 0.0;
      return s;
    }
#endif
#ifdef MXC_HAS_FUZZ
    case MXC_LOBE_FUZZ: {
      if (wo.z <= 0.0) return s;
      s.wi = mxc_fuzz_sample(l.p0, wo, u.xy);  // exact importance sampling of the LTC
      s.value = mxc_lobe_eval(l, wo, s.wi);
      s.pdf = mxc_lobe_pdf(l, wo, s.wi);
      s.valid = s.pdf > 0.0;
      return s;
    }
#endif
    default: {
      if (wo.z <= 0.0) return s;
      s.wi = mxc_sample_cosine(u.xy);
      s.value = mxc_lobe_eval(l, wo, s.wi);
      s.pdf = mxc_lobe_pdf(l, wo, s.wi);
      s.valid = s.pdf > 0.0;
      return s;
    }
  }
}
