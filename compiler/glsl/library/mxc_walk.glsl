// The reference tier (--accuracy reference): the closure is the slab stacks themselves, and
// light is followed through them by a Monte Carlo random walk (docs/reference-tier.md).
//
// - Each rough microfacet interface is a random walk on its microsurface (Heitz, Hanika, d'Eon
//   and Dachsbacher 2016, "Multiple-scattering microfacet BSDFs with the Smith model"): heights
//   uniform on [-1, 1], the next height from the Smith height CDF, the microfacet a visible
//   normal of the direction the ray comes from, reflection or refraction chosen by Fresnel. A
//   smooth interface (MXC_DELTA_ALPHA) is its specular reflection and refraction.
// - The stack is walked position-free (Guo, Hasan and Zhao 2018, "Position-free Monte Carlo
//   simulation for arbitrary layered BSDFs"; the structure of pbrt-v4's LayeredBxDF, extended
//   to N layers): interfaces scatter with their sampled BSDF, media absorb and scatter with a
//   Henyey-Greenstein phase function, finite layers end at their thickness and a scattering bulk
//   has no bottom (subsurface is a volumetric walk in a half-space, not a diffuse lobe).
// - Diffuse, sheen and fuzz interfaces are their lobes (mxc_lobes.glsl); a sheen or fuzz layer
//   passes what it does not reflect straight through, 1 - E (OpenPBR "Fuzz").
// - Weights are those of flux (a white walk: a refraction keeps the weight), so that the walk
//   from wo and the reverse walks from wi satisfy detailed balance,
//   n_a^2 cos_a p(a -> b) = n_b^2 cos_b p(b -> a) (Veach 1997, s. 5.2, for the radiance form).
//
// eval(wo, wi) is an unbiased estimate of f cos by next-event estimation: once per walk, a chain
// of transmissions is sampled from wi into the stack (the reverse walks above), and every vertex
// of the walk from wo (an interface's microsurface vertex, or a medium's scattering) connects to
// the chain of its layer with its own scattering density. sample(wo) returns the walk's exit
// direction with its weight. pdf is an approximation (cosine) used only by multiple importance
// sampling. Each call runs MXC_REFERENCE_SAMPLES walks (sample: one).

#ifndef MXC_REFERENCE_SAMPLES
#define MXC_REFERENCE_SAMPLES 1
#endif

// The path length assumed inside a clear bulk under a transmitting interface (the closure sees
// one interface, not the object): as mxc_closure.glsl, so that the tiers agree on it.
const float MXC_BULK_PATH = 1.0;
// Events of one walk through the stack, and bounces on one microsurface: Russian roulette ends
// walks unbiasedly after MXC_WALK_ROULETTE events; the caps only bound the loops (walks cut by
// them are lost energy that the tests measure).
const int MXC_WALK_MAX_EVENTS = 65000;
const int MXC_WALK_ROULETTE = 8;
const int MXC_MICRO_MAX_BOUNCES = 64;
// Iterations of the walks' loops left to this invocation. Lavapipe ends a loop after 65535
// iterations in an invocation, summed over its entries, and carries on as if it had finished
// (runtime/Evaluator.h); the walks stop themselves first, so that a cut is a walk lost (energy
// the tests measure), never a silently broken caller. The harness draws one walk per invocation
// and dispatch (MaterialInterface::samplesPerDispatch).
const int MXC_WALK_BUDGET = 65000;
int mxc_walk_budget = MXC_WALK_BUDGET;

// Layer flags (MxcClosure.medium[k].w).
const int MXC_LAYER_NO_INTERFACE = 1;  // a plane without an interface (it carries emission only)
const int MXC_LAYER_EXIT = 2;          // under the interface is a clear bulk: light entering it is transmitted
const int MXC_LAYER_HALF_SPACE = 4;    // under the interface is a scattering bulk without a bottom
const int MXC_LAYER_OBSERVED = 8;      // the medium is given by its extinction (sigmaA) and observed colour (sigmaS)

struct MxcClosure {
  MxcLobe lobes[MXC_MAX_LOBES];  // each layer's interface; stacks are runs of layers, top first
  vec3 sigmaA[MXC_MAX_LOBES];    // the medium under the interface: absorption (1/length); MXC_LAYER_OBSERVED: extinction
  vec3 sigmaS[MXC_MAX_LOBES];    // scattering (1/length); MXC_LAYER_OBSERVED: the observed colour
  vec4 medium[MXC_MAX_LOBES];    // x: Henyey-Greenstein g, y: thickness (0: none), z: coverage, w: flags
  vec4 ior[MXC_MAX_LOBES];       // x: eta with the coat layer z present, y: eta without it (z < 0: x always)
  vec3 emitted[MXC_MAX_LOBES];   // radiance emitted upwards at the top of the layer
  int count;
  ivec2 stacks[MXC_MAX_STACKS];  // first layer, layer count
  vec3 stackWeight[MXC_MAX_STACKS];
  int stackCount;
  float choiceTotal;
  vec3 emission;      // radiance leaving towards wo (estimated by mxc_closure_prepare)
  vec3 transparency;  // weight of light passing straight through (opacity < 1)
};

// Every sample of the walk carries its own weight: nothing evaluates it again
// (mxc_closure_sample.glsl, stages/mxc_raster.frag).
#define MXC_SAMPLES_WEIGHTED
struct MxcSample {
  vec3 wi;
  vec3 weight;
  float pdf;
  bool delta;
  bool evaluate;  // always false: a walk's sample carries its own weight (mxc_closure.glsl)
  bool valid;
};

// ---- Random numbers: one stream per invocation, seeded by the stage ----

uint mxc_walk_state = 1u;
void mxc_closure_seed(uint seed) {
  mxc_walk_state = mxc_pcg(seed ^ 0x68bc21ebu);
  mxc_walk_budget = MXC_WALK_BUDGET;
}
// In (0, 1): logarithms and negative powers of it stay finite.
float mxc_walk_u() {
  // A PCG stream: the LCG state advances with full period 2^32 and its output is permuted
  // (O'Neill 2014); iterating the hash itself would fall into short cycles.
  mxc_walk_state = mxc_walk_state * 747796405u + 2891336453u;
  uint word = ((mxc_walk_state >> ((mxc_walk_state >> 28u) + 4u)) ^ mxc_walk_state) * 277803737u;
  word = (word >> 22u) ^ word;
  return (float(word >> 8) + 0.5) * (1.0 / 16777216.0);
}

// ---- One rough interface: the microsurface walk ----

// The Smith height CDF of uniform heights on [-1, 1].
float mxc_micro_c1(float h) { return clamp(0.5 * (h + 1.0), 0.0, 1.0); }

// The projected area of the microsurface seen from direction v (towards the viewer, any z):
// (1 + Lambda) v.z above the horizon; Lambda |v.z| below it, where only the backs of rising
// microfacets face v (Heitz et al. 2016, s. 3.2).
float mxc_micro_area(vec3 v, vec2 alpha) {
  float l = mxc_ggx_lambda(v, alpha);
  return v.z > 0.0 ? (1.0 + l) * v.z : l * (-v.z);
}

// A visible normal for a direction v of any z (Heitz 2018's warp: below the horizon it covers
// the half disk outside the horizon's ellipse, the backs of microfacets that face v).
vec3 mxc_micro_vndf(vec3 v, vec2 alpha, vec2 u) {
  alpha = mxc_rough_alpha(alpha);
  vec3 vh = normalize(vec3(alpha.x * v.x, alpha.y * v.y, v.z));  // |v| = 1 and alpha > 0: not zero
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0 * MXC_PI * u.y;
  float p1 = r * cos(phi);
  float s = 0.5 * (1.0 + vh.z);
  float p2 = (1.0 - s) * mxc_safe_sqrt(1.0 - p1 * p1) + s * r * sin(phi);
  vec3 nh = p1 * t1 + p2 * t2 + mxc_safe_sqrt(1.0 - p1 * p1 - p2 * p2) * vh;
  return normalize(vec3(alpha.x * nh.x, alpha.y * nh.y, max(nh.z, 1e-7)));  // z > 0: not zero
}

// The Fresnel of a microfacet seen at cosine `cosm` from the lobe's upper side (`upper`) or
// its lower side, and whether light crosses: dielectrics refract; a Schlick lobe that transmits
// passes what it does not reflect straight through (an IOR ratio of 1); conductors only reflect.
vec3 mxc_micro_fresnel(MxcLobe l, float cosm, bool upper) { return mxc_lobe_fresnel(l, clamp(cosm, 0.0, 1.0), upper); }
bool mxc_micro_crosses(MxcLobe l) {
  return l.kind == MXC_LOBE_DIELECTRIC || (l.kind == MXC_LOBE_SCHLICK && (l.mode & MXC_TRANSMIT) != 0);
}
float mxc_micro_eta(MxcLobe l, bool upper) {
  if (l.kind != MXC_LOBE_DIELECTRIC) return 1.0;
  return mxc_lobe_eta(l, upper);  // far side over near side
}

// The density of leaving towards `o` (the ray's side of the surface, o.z > 0) after scattering
// on a microfacet visible from `i` (towards where the ray came from): F D_i(m) / (4 i.m).
vec3 mxc_micro_reflect_density(MxcLobe l, vec3 i, vec3 o, bool upper) {
  vec3 m = i + o;
  if (dot(m, m) < 1e-12) return vec3(0.0);
  m = normalize(m);
  float im = dot(i, m);
  float area = mxc_micro_area(i, l.alpha);
  if (m.z <= 0.0 || im <= 0.0 || area <= 1e-12) return vec3(0.0);
  float dvis = im * mxc_ggx_d(m, l.alpha) / area;  // D_i(m) = <i, m> D(m) / area
  return mxc_micro_fresnel(l, im, upper) * dvis / (4.0 * im);  // im > 0
}

// The density of crossing to `o` on the far side (o.z < 0 in the ray's frame): (1 - F) D_i(m)
// times the Jacobian of refraction e^2 |o.m| / (i.m + e o.m)^2 (Walter et al. 2007, eq. 17),
// with e the IOR ratio far over near. A ratio of 1 crosses straight: a delta, density 0.
vec3 mxc_micro_cross_density(MxcLobe l, vec3 i, vec3 o, bool upper) {
  float e = mxc_micro_eta(l, upper);
  if (abs(e - 1.0) < 1e-4) return vec3(0.0);
  vec3 m = i + e * o;
  if (dot(m, m) < 1e-12) return vec3(0.0);
  m = normalize(m);
  if (m.z < 0.0) m = -m;
  float im = dot(i, m), om = dot(o, m);
  float area = mxc_micro_area(i, l.alpha);
  float denom = im + e * om;
  if (im <= 0.0 || om >= 0.0 || area <= 1e-12 || abs(denom) < 1e-6) return vec3(0.0);
  float dvis = im * mxc_ggx_d(m, l.alpha) / area;
  return (1.0 - mxc_micro_fresnel(l, im, upper)) * dvis * e * e * (-om) / (denom * denom);
}

// The result of a crossing of one interface.
struct MxcCross {
  vec3 w;       // the direction the light leaves in (travel, lobe frame)
  vec3 weight;
  bool delta;
  bool valid;
};

// The microsurface walk of a rough microfacet lobe. `w`: the arriving direction of travel in
// the lobe's frame (w.z < 0 from above, > 0 from below). `conn`: a direction of travel to
// connect to (0: none); `nee` gains the density of leaving the surface in it, summed over the
// walk's vertices, each with the weight before it and the probability of escaping from its
// height (Heitz et al. 2016, s. 5: the estimator of the BSDF by next-event estimation).
MxcCross mxc_micro_walk(MxcLobe l, vec3 w, vec3 conn, inout vec3 nee) {
  // Every member is set before any use: an undefined value reaching a branch is undefined
  // behaviour in the compiled code (LLVM's poison, on lavapipe), not merely a wrong value.
  MxcCross x;
  x.w = w;
  x.delta = false;
  x.valid = false;
  x.weight = vec3(1.0);
  bool upper = w.z < 0.0;  // the ray starts in the lobe's upper medium
  // The walk's frame has the ray's medium above: from below, heights and z are mirrored.
  if (!upper) {
    w.z = -w.z;
    conn.z = -conn.z;
  }
  bool connect = dot(conn, conn) > 0.5;
  float h = 1.0;  // above every microfacet: nothing masks the first approach
  bool crosses = mxc_micro_crosses(l);
  bool flipped = !upper;  // whether the current frame is mirrored against the lobe's
  for (int bounce = 0; bounce < MXC_MICRO_MAX_BOUNCES; ++bounce) {
    if (--mxc_walk_budget < 0) return x;
    float lam = mxc_ggx_lambda(w, l.alpha);
    float c;
    if (w.z > 0.0) {
      // Going up from height h: unmasked up to C1(h') with probability (C1(h) / C1(h'))^Lambda.
      if (lam < 1e-6) {
        c = 2.0;  // straight up: nothing masks
      } else {
        c = mxc_micro_c1(h) * pow(mxc_walk_u(), -1.0 / lam);  // u in (0, 1): finite
      }
      if (c >= 1.0) {
        x.w = flipped ? vec3(w.xy, -w.z) : w;
        x.valid = true;
        return x;
      }
    } else {
      c = mxc_micro_c1(h) * pow(mxc_walk_u(), 1.0 / (1.0 + lam));  // 1 + Lambda >= 1
    }
    h = 2.0 * c - 1.0;
    vec3 i = -w;  // towards where the ray came from
    if (connect) {
      // Leave towards conn from this vertex: the phase function, then the escape from h on
      // conn's side (its own frame for a crossing: height -h).
      if (conn.z > 0.0) {
        float escape = pow(mxc_micro_c1(h), mxc_ggx_lambda(conn, l.alpha));
        nee += x.weight * mxc_micro_reflect_density(l, i, conn, !flipped) * escape;
      } else if (crosses && conn.z < 0.0) {
        float escape = pow(mxc_micro_c1(-h), mxc_ggx_lambda(conn, l.alpha));
        nee += x.weight * mxc_micro_cross_density(l, i, conn, !flipped) * escape;
      }
    }
    vec3 m = mxc_micro_vndf(i, l.alpha, vec2(mxc_walk_u(), mxc_walk_u()));
    float cosm = dot(i, m);
    bool side = !flipped;  // the ray is in the lobe's upper medium
    vec3 f = mxc_micro_fresnel(l, cosm, side);
    if (!crosses) {
      x.weight *= f;
      w = reflect(w, m);
      continue;
    }
    float pr = clamp(mxc_mean(f), 0.0, 1.0);
    if (mxc_walk_u() < pr) {
      x.weight *= f / max(pr, 1e-6);  // pr > 0 when chosen
      w = reflect(w, m);
      continue;
    }
    x.weight *= (1.0 - f) / max(1.0 - pr, 1e-6);  // pr < 1 when not chosen
    // Refraction (Snell in vector form; cosm > 0 and no total internal reflection here, since F = 1 there).
    float r = 1.0 / mxc_micro_eta(l, side);  // ratio >= 1e-3 (the generator's floor)
    float cost = mxc_safe_sqrt(1.0 - r * r * (1.0 - cosm * cosm));
    w = normalize(r * w + (r * max(cosm, 0.0) - cost) * m);
    // The other medium's frame: heights and directions mirrored.
    w.z = -w.z;
    conn.z = -conn.z;
    h = -h;
    flipped = !flipped;
  }
  return x;  // cut at the bounce cap: lost
}

// ---- One interface of the stack ----

bool mxc_is_microfacet(MxcLobe l) {
  return l.kind == MXC_LOBE_DIELECTRIC || l.kind == MXC_LOBE_CONDUCTOR || l.kind == MXC_LOBE_SCHLICK;
}

// Scatters the light arriving along `w` (world, travel direction) at interface `l`; `conn`
// (world, travel direction, or 0) is a direction to connect to, and `nee` gains the density of
// leaving in it. `tinted`: apply the interface's non-physical tints (reflection tint from above,
// transmission tint crossing down); the reverse walks from wi do not.
MxcCross mxc_walk_interface(MxcLobe l, vec3 w, vec3 conn, bool tinted, inout vec3 nee) {
  mat3 frame = mxc_frame(l.N, l.T);
  vec3 wl = mxc_to_local(frame, w);
  vec3 cl = mxc_to_local(frame, conn);
  bool fromAbove = wl.z < 0.0;
  MxcCross x;
  x.w = wl;
  x.valid = false;
  x.delta = true;
  x.weight = vec3(0.0);
  if (mxc_is_microfacet(l)) {
    bool crosses = mxc_micro_crosses(l);
    if (mxc_is_delta(l.alpha)) {
      // A smooth interface: specular reflection, or refraction chosen by Fresnel.
      vec3 f = mxc_micro_fresnel(l, abs(wl.z), fromAbove);
      float pr = crosses ? clamp(mxc_mean(f), 0.0, 1.0) : 1.0;
      if (mxc_walk_u() < pr) {
        x.w = vec3(wl.xy, -wl.z);
        x.weight = f / max(pr, 1e-6);
      } else {
        float r = 1.0 / mxc_micro_eta(l, fromAbove);
        float cosi = abs(wl.z);
        float cost = mxc_safe_sqrt(1.0 - r * r * (1.0 - cosi * cosi));
        x.w = vec3(r * wl.xy, sign(wl.z) * cost);
        x.weight = (1.0 - f) / max(1.0 - pr, 1e-6);
      }
      x.valid = true;
    } else {
      x = mxc_micro_walk(l, wl, cl, nee);
    }
    bool reflected = (x.w.z > 0.0) == fromAbove;
    if (reflected && crosses && (l.mode & MXC_REFLECT) == 0) x.valid = false;
    if (!reflected && (l.mode & MXC_TRANSMIT) == 0) x.valid = false;
    if (tinted && l.kind == MXC_LOBE_DIELECTRIC && fromAbove) x.weight *= reflected ? l.c0 : l.c1;
  } else {
    // A lobe of the library, evaluated and sampled in its own frame seen from the side the
    // light arrives on (mirrored when from below).
    vec3 v = -wl;
    if (!fromAbove) {
      v.z = -v.z;
      cl.z = -cl.z;
    }
    if (l.kind == MXC_LOBE_SHEEN || l.kind == MXC_LOBE_FUZZ) {
      // OpenPBR "Fuzz": the fibres reflect their lobe and pass 1 - E straight through.
      vec3 e = clamp(l.weight * mxc_lobe_layer_albedo(l, v), 0.0, 1.0);
      if (cl.z > 0.0) nee += l.weight * mxc_lobe_eval(l, v, cl);
      float q = clamp(mxc_mean(e), 0.05, 0.95);
      if (mxc_walk_u() < q) {
        MxcLobeSample s = mxc_lobe_sample(l, v, vec3(mxc_walk_u(), mxc_walk_u(), mxc_walk_u()));
        if (!s.valid || !(s.pdf > 0.0)) return x;
        x.w = s.wi;
        x.weight = l.weight * s.value / (s.pdf * q);  // pdf > 0, q >= 0.05
        x.delta = s.delta;
      } else {
        x.w = -v;
        x.weight = (1.0 - e) / (1.0 - q);  // q <= 0.95
      }
    } else {
      nee += l.weight * mxc_lobe_eval(l, v, cl);
      MxcLobeSample s = mxc_lobe_sample(l, v, vec3(mxc_walk_u(), mxc_walk_u(), mxc_walk_u()));
      if (!s.valid || !(s.pdf > 0.0)) return x;
      x.w = s.wi;
      x.weight = s.delta ? l.weight * s.value / s.pdf : l.weight * s.value / s.pdf;
      x.delta = s.delta;
    }
    x.valid = true;
    if (!fromAbove) x.w.z = -x.w.z;
  }
  x.w = mxc_to_world(frame, x.w);
  x.valid = x.valid && all(lessThan(abs(x.weight), vec3(1e20)));
  return x;
}

// ---- The walk's observed-albedo tables (compiler/glsl/WalkTables.h) ----
// Rows of the albedo tables image under the computed ones, measured from this walk by
// tools/GenerateWalkFits.cpp: they turn the colours OpenPBR defines by what is observed into
// the parameters the walk needs. The host reads them the same way (WalkTables.cpp).

// mxc_walk_texel and mxc_walk_eta_index: mxc_lobes.glsl (the balanced tier reads the tables too).
// A microfacet interface's roughness as the tables' axis: sqrt of its alpha (the geometric mean
// of an anisotropic pair).
float mxc_walk_roughness(vec2 alpha) { return sqrt(sqrt(max(alpha.x * alpha.y, 0.0))); }

// OpenPBR "Glossy-diffuse", eq. glossy_diffuse_albedo_constraint: base_color C is what comes
// back of the light the gloss lets in. Under a lossless interface a Lambertian of albedo rho
// returns exactly rho (1 - r_i) / (1 - rho r_i) of it, r_i the interface's reflectance from
// inside under cosine-distributed light (the tables' gloss rows, for the walk's rough
// interface), so rho = C / (1 - r_i + C r_i). `eta`: the interface's IOR ratio, `roughness`:
// its mxc_walk_roughness.
vec3 mxc_walk_gloss_albedo(vec3 C, float eta, float roughness) {
  float ri = mxc_walk_texel(clamp(roughness, 0.0, 1.0) * float(MXC_TABLE_SIZE - 1), float(MXC_WALK_GLOSS_ROW) + mxc_walk_eta_index(eta));
  vec3 c = clamp(C, 0.0, 1.0);
  return c / (1.0 - ri + c * ri);  // >= 1 - r_i > 0: r_i < 1 for eta <= 3
}

// OpenPBR "Subsurface", eq. subsurface_albedo_constraint: the single-scattering albedo omega of
// the semi-infinite medium (HG anisotropy g) under the interface that returns subsurface_color
// C of what the interface lets in at normal incidence. The tables' medium rows hold van de
// Hulst's s = sqrt((1 - omega) / (1 - omega g)) for a grid of C, per (roughness, g, eta).
vec3 mxc_walk_subsurface_albedo(vec3 C, float eta, float g, float roughness) {
  float e = mxc_walk_eta_index(eta);
  float fg = clamp((g + 0.9) / 1.8, 0.0, 1.0) * float(MXC_WALK_ANISOTROPY_STEPS - 1);
  float fr = clamp(roughness, 0.0, 1.0) * float(MXC_WALK_ROUGHNESS_STEPS - 1);
  float g0 = min(floor(fg), float(MXC_WALK_ANISOTROPY_STEPS - 2));
  float r0 = min(floor(fr), float(MXC_WALK_ROUGHNESS_STEPS - 2));
  vec3 column = clamp(C, 0.0, 1.0) * float(MXC_TABLE_SIZE - 1);
  vec3 s = vec3(0.0);
  for (int corner = 0; corner < 4; ++corner) {
    float dg = float(corner & 1), dr = float(corner >> 1);
    float w = (dg > 0.0 ? fg - g0 : 1.0 - (fg - g0)) * (dr > 0.0 ? fr - r0 : 1.0 - (fr - r0));
    float row = float(MXC_WALK_MEDIUM_ROW) + ((r0 + dr) * float(MXC_WALK_ANISOTROPY_STEPS) + g0 + dg) * float(MXC_WALK_ETA_STEPS) + e;
    s += w * vec3(mxc_walk_texel(column.x, row), mxc_walk_texel(column.y, row), mxc_walk_texel(column.z, row));
  }
  s = clamp(s, 0.0, 1.0);
  float gc = clamp(g, -0.99, 0.99);
  return (1.0 - s * s) / (1.0 - gc * s * s);  // 1 - g s^2 >= 0.01
}

// ---- Media ----

// Henyey-Greenstein phase function (Henyey and Greenstein 1941) of the cosine between the
// directions of travel before and after; |g| <= 0.99 keeps the denominator > 0.
float mxc_hg(float cosTheta, float g) {
  g = clamp(g, -0.99, 0.99);
  float d = 1.0 + g * g - 2.0 * g * cosTheta;  // >= (1 - |g|)^2 > 0
  return (1.0 - g * g) / (4.0 * MXC_PI * d * sqrt(d));
}

// A direction from the HG phase function around the direction of travel w (inverse CDF;
// Pharr, Jakob and Humphreys 2023, s. 11.3.1).
vec3 mxc_hg_sample(vec3 w, float g, vec2 u) {
  g = clamp(g, -0.99, 0.99);
  float cosTheta;
  if (abs(g) < 1e-3) {
    cosTheta = 1.0 - 2.0 * u.x;
  } else {
    float s = (1.0 - g * g) / (1.0 + g - 2.0 * g * u.x);  // denominator >= 1 - |g| > 0
    cosTheta = (1.0 + g * g - s * s) / (2.0 * g);          // |g| >= 1e-3
  }
  cosTheta = clamp(cosTheta, -1.0, 1.0);
  float sinTheta = mxc_safe_sqrt(1.0 - cosTheta * cosTheta);
  float phi = 2.0 * MXC_PI * u.y;
  mat3 frame = mxc_frame(w, vec3(1.0, 0.0, 0.0));
  return mxc_to_world(frame, vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta));
}

// ---- The walk through a stack ----

const int MXC_WALK_EVAL = 0;      // next-event estimate of f cos towards wi
const int MXC_WALK_SAMPLE = 1;    // the exit direction and its weight
const int MXC_WALK_EMISSION = 2;  // the emission collected on the way down

struct MxcWalk {
  vec3 value;  // eval: f cos; sample: weight; emission: radiance
  vec3 wi;
  bool delta;
  bool valid;
};

MxcWalk mxc_walk(MxcClosure c, int stack, vec3 wo, vec3 wi, int mode) {
  MxcWalk res;
  res.value = vec3(0.0);
  res.wi = wo;
  res.delta = true;
  res.valid = false;
  int first = c.stacks[stack].x;
  vec3 ns = c.lobes[first].N;  // the stack's up direction: its top interface's normal
  // Which layers this walk sees: a layer of coverage w is there with probability w (OpenPBR
  // "Coverage": Slab over coverage w is mix(base, layer(base, slab), w), one statistical choice
  // per path), and an absent layer is neither its interface nor its medium: the walk goes
  // straight on to the layer under it. layer[k] is the closure's index of the k-th layer seen,
  // top first, and n their count. Then each interface's IOR ratio given the coat above it, and
  // the IOR of each medium relative to outside (nAbs[k]: under the k-th layer's interface).
  int layer[MXC_MAX_LOBES];
  bool present[MXC_MAX_LOBES];  // the layer seen has an interface (else it is a medium or an emission plane only)
  float eta[MXC_MAX_LOBES];
  float nAbs[MXC_MAX_LOBES];
  bool seen[MXC_MAX_LOBES];
  int n = 0;
  for (int k = 0; k < c.stacks[stack].y; ++k) {
    vec4 med = c.medium[first + k];
    seen[k] = med.z >= 1.0 || mxc_walk_u() < med.z;
    if (!seen[k]) continue;
    layer[n] = first + k;
    present[n] = (int(med.w) & MXC_LAYER_NO_INTERFACE) == 0;
    vec4 io = c.ior[first + k];
    int coat = int(io.z);  // the coat whose IOR is above this interface, by its index in the stack
    eta[n] = coat >= 0 && coat < k && !seen[coat] ? io.y : io.x;
    n += 1;
  }
  if (n == 0) return res;
  float nAbove = 1.0;
  for (int k = 0; k < n; ++k) {
    if (present[k] && c.lobes[layer[k]].kind == MXC_LOBE_DIELECTRIC) nAbove *= max(eta[k], 1e-3);
    nAbs[k] = nAbove;
  }
  // A medium given by its observed colour (MXC_LAYER_OBSERVED: subsurface) gets the albedo that
  // returns that colour through the dielectric over it as this walk sees it: its own interface,
  // or for a layer without one the one right above (OpenPBR "Subsurface"; with a coat of the
  // same IOR over it that interface vanishes, and the coat darkens it as OpenPBR "Darkening"
  // says). Computed once per walk: one such layer per stack.
  int observed = -1;
  vec3 observedA = vec3(0.0), observedS = vec3(0.0);
  for (int k = 0; k < n; ++k) {
    if (observed >= 0 || (int(c.medium[layer[k]].w) & MXC_LAYER_OBSERVED) == 0) continue;
    observed = k;
    int above = present[k] ? k : k - 1;
    bool dielectric = above >= 0 && present[above] && c.lobes[layer[above]].kind == MXC_LOBE_DIELECTRIC;
    vec3 albedo = mxc_walk_subsurface_albedo(c.sigmaS[layer[k]], dielectric ? eta[above] : 1.0, c.medium[layer[k]].x,
                                             dielectric ? mxc_walk_roughness(c.lobes[layer[above]].alpha) : 0.0);
    vec3 extinction = c.sigmaA[layer[k]];
    observedS = extinction * albedo;
    observedA = extinction - observedS;
  }

  // The chain from wi (eval): for each medium m, the direction chainDir[m] light leaves it in
  // towards wi (the reverse of the chain's) and the chain's weight chainW[m] where the chain
  // enters it (its top for wi above, its bottom for wi below); nEnd is the IOR where wi is.
  bool up = dot(wi, ns) > 0.0;
  vec3 chainDir[MXC_MAX_LOBES];
  vec3 chainW[MXC_MAX_LOBES];
  int exitLayer = -1;  // the layer whose medium transmitted light leaves through
  for (int k = 0; k < n; ++k) {
    chainW[k] = vec3(0.0);
    chainDir[k] = -ns;
    if (present[k] && (int(c.medium[layer[k]].w) & MXC_LAYER_EXIT) != 0) exitLayer = k;
  }
  float nEnd = 1.0;
  vec3 dummy = vec3(0.0);
  if (mode == MXC_WALK_EVAL) {
    if (up) {
      vec3 w = -wi;
      vec3 W = vec3(1.0);
      for (int k = 0; k < n; ++k) {
        int flags = int(c.medium[layer[k]].w);
        if (present[k]) {
          MxcLobe l = c.lobes[layer[k]];
          l.eta = eta[k];
          MxcCross x = mxc_walk_interface(l, w, vec3(0.0), false, dummy);
          if (!x.valid || dot(x.w, ns) >= 0.0) break;
          w = x.w;
          W *= x.weight;
        }
        chainDir[k] = -w;
        chainW[k] = W;
        float d = c.medium[layer[k]].y;
        if ((flags & (MXC_LAYER_EXIT | MXC_LAYER_HALF_SPACE)) != 0 || d < 0.0) break;
        if (d > 0.0) W *= exp(-(c.sigmaA[layer[k]] + c.sigmaS[layer[k]]) * d / max(abs(dot(w, ns)), 1e-4));
      }
    } else if (exitLayer >= 0) {
      nEnd = nAbs[exitLayer];
      vec3 w = -wi;  // travelling up from where wi points
      vec3 W = exp(-c.sigmaA[layer[exitLayer]] * MXC_BULK_PATH);
      chainDir[exitLayer] = wi;
      chainW[exitLayer] = W;
      for (int k = exitLayer; k > 0; --k) {
        // Cross interface k from below into medium k - 1 (entered at its bottom).
        if (present[k]) {
          MxcLobe l = c.lobes[layer[k]];
          l.eta = eta[k];
          MxcCross x = mxc_walk_interface(l, w, vec3(0.0), false, dummy);
          if (!x.valid || dot(x.w, ns) <= 0.0) break;
          w = x.w;
          W *= x.weight;
        }
        chainDir[k - 1] = -w;
        chainW[k - 1] = W;
        float d = c.medium[layer[k - 1]].y;
        if (d < 0.0) break;
        if (d > 0.0) W *= exp(-(c.sigmaA[layer[k - 1]] + c.sigmaS[layer[k - 1]]) * d / max(abs(dot(w, ns)), 1e-4));
      }
    }
  }
  // The connection of a vertex in medium m (m = -1: outside above) at depth z to wi: its
  // direction of travel and the factor on the vertex's density (the chain's weight, the
  // medium's transmittance to where the chain enters, and detailed balance's
  // n_end^2 |cos wi| / (n_m^2 |cos d|)).
  float cosWi = abs(dot(wi, ns));

  vec3 beta = vec3(1.0);
  vec3 w = -wo;
  int k = 0;            // the layer: at its interface (inMedium false) or in its medium
  bool inMedium = false;
  float z = 0.0;        // depth in the medium, from its top
  bool firstEvent = true;
  for (int event = 0; event < MXC_WALK_MAX_EVENTS; ++event) {
    if (--mxc_walk_budget < 0) return res;
    if (event >= MXC_WALK_ROULETTE) {
      float keep = min(max(beta.x, max(beta.y, beta.z)), 1.0);
      if (!(mxc_walk_u() < keep)) return res;
      beta /= keep;  // keep > 0 when the walk survives
    }
    bool down = dot(w, ns) < 0.0;
    if (!inMedium) {
      int lk = layer[k];
      if (down && mode == MXC_WALK_EMISSION) res.value += beta * c.emitted[lk];
      if (!present[k] && down) {
        // No interface (an index-matched medium or an emission plane): straight on into the medium.
        inMedium = true;
        z = 0.0;
        continue;
      }
      if (present[k]) {
        MxcLobe l = c.lobes[lk];
        l.eta = eta[k];
        if ((l.kind == MXC_LOBE_EON || l.kind == MXC_LOBE_DIFFUSE || l.kind == MXC_LOBE_BURLEY) && k > 0 && present[k - 1] &&
            c.lobes[layer[k - 1]].kind == MXC_LOBE_DIELECTRIC) {
          // OpenPBR "Glossy-diffuse": base_color is observed through the gloss right above, as
          // this walk sees it (under a coat of its IOR, the gloss vanishes and the coat darkens
          // the base, as OpenPBR "Darkening" says).
          l.c0 = mxc_walk_gloss_albedo(l.c0, eta[k - 1], mxc_walk_roughness(c.lobes[layer[k - 1]].alpha));
        }
        // Where this vertex connects to: the medium above for wi above, the one below for wi below.
        vec3 conn = vec3(0.0);
        vec3 factor = vec3(0.0);
        // Each path is counted once, at its anchor: its last reflection or medium scattering, whose
        // own density is evaluated towards the chain of the medium it leaves into; the chain then
        // samples the transmissions from there to wi. A path of transmissions only is anchored at
        // its first event, the one crossing from wo. So an interface connects by reflection (back to
        // the side the light came from), and by transmission only at the walk's first event.
        bool reflectSide = up == down;  // wi is on the side the light arrived from
        if (mode == MXC_WALK_EVAL && (reflectSide || firstEvent)) {
          int m = up ? k - 1 : k;
          if (up && m < 0) {
            conn = wi;
            factor = vec3(1.0);
          } else if (m >= 0 && any(greaterThan(chainW[m], vec3(0.0)))) {
            conn = chainDir[m];
            float cosd = max(abs(dot(conn, ns)), 1e-4);
            float d = max(c.medium[layer[m]].y, 0.0);
            vec3 tr = (up && d > 0.0) ? exp(-(c.sigmaA[layer[m]] + c.sigmaS[layer[m]]) * d / cosd) : vec3(1.0);
            factor = chainW[m] * tr * mxc_sqr(nEnd / nAbs[m]) * (m == exitLayer ? 1.0 : cosWi / cosd);
          }
          if (!up && m != exitLayer && exitLayer >= 0 && m >= 0) {
            // Going down through a finite medium to where the chain enters it (its bottom).
            float d = max(c.medium[layer[m]].y, 0.0);
            float cosd = max(abs(dot(conn, ns)), 1e-4);
            if (d > 0.0) factor *= exp(-(c.sigmaA[layer[m]] + c.sigmaS[layer[m]]) * d / cosd);
          }
        }
        vec3 nee = vec3(0.0);
        MxcCross x = mxc_walk_interface(l, w, factor != vec3(0.0) ? conn : vec3(0.0), true, nee);
        res.value += mode == MXC_WALK_EVAL ? beta * nee * factor : vec3(0.0);
        firstEvent = false;
        if (!x.valid) break;
        beta *= x.weight;
        res.delta = res.delta && x.delta;
        w = x.w;
      }
      if (dot(w, ns) > 0.0) {  // upwards: out of the stack (a reflection), or into the medium above
        if (k == 0) {
          if (mode == MXC_WALK_SAMPLE) {
            res.value = beta;
            res.wi = w;
            res.valid = true;
          }
          break;
        }
        k -= 1;
        inMedium = true;
        z = max(c.medium[layer[k]].y, 0.0);
        continue;
      }
      if ((int(c.medium[lk].w) & MXC_LAYER_EXIT) != 0) {
        if (mode == MXC_WALK_SAMPLE) {
          res.value = beta * exp(-c.sigmaA[lk] * MXC_BULK_PATH);
          res.wi = w;
          res.valid = true;
        }
        break;
      }
      inMedium = true;
      z = 0.0;
      continue;
    }
    // In the medium under interface k.
    int lk = layer[k];
    float d = c.medium[lk].y;
    bool halfSpace = (int(c.medium[lk].w) & MXC_LAYER_HALF_SPACE) != 0;
    float cosw = max(abs(dot(w, ns)), 1e-4);
    float toBoundary = down ? (halfSpace ? 1e30 : (max(d, 0.0) - z) / cosw) : z / cosw;
    vec3 sa = k == observed ? observedA : c.sigmaA[lk];
    vec3 ss = k == observed ? observedS : c.sigmaS[lk];
    vec3 st = sa + ss;
    bool scatters = d != 0.0 && max(ss.x, max(ss.y, ss.z)) > 0.0;
    if (d != 0.0 && !scatters) {
      if (halfSpace && down) break;  // an absorbing half-space: nothing comes back
      beta *= exp(-sa * toBoundary);
    } else if (scatters) {
      // Free flight by the extinction of one channel, chosen in proportion to the path's
      // throughput, p_j = beta_j / sum(beta) (hero wavelength, Wilkie et al. 2014); every
      // channel's weight divides by the density of the choices together,
      // sum_j p_j sigma_t_j exp(-sigma_t_j t) (the one-sample balance heuristic over channels,
      // Miller, Georgiev and Jarosz 2019, s. 5). Choosing by throughput bounds the variance: at
      // a scattering event the new weights sum to
      // sum(beta) sum_c beta_c sigma_s_c T_c / sum_j beta_j sigma_t_j T_j <= sum(beta), so no
      // channel's weight can grow from event to event (a uniform choice let the least dense
      // channel's weight grow at every event: unbounded variance over long walks, issue 39).
      float total = beta.x + beta.y + beta.z;
      if (!(total > 0.0)) break;  // nothing left to carry
      vec3 pc = beta / total;      // total > 0
      float pick = mxc_walk_u();
      float sc = pick < pc.x ? st.x : (pick < pc.x + pc.y ? st.y : st.z);
      // A channel without extinction flies to the boundary (t infinite, its density 0 at any t).
      float t = sc > 0.0 ? -log(mxc_walk_u()) / sc : 1e30;
      if (t < toBoundary) {
        vec3 tr = exp(-st * t);
        beta *= ss * tr / max(dot(pc, st * tr), 1e-30);  // the mixture's density at t: > 0 for the channel chosen
        z += (down ? t : -t) * cosw;
        // A scattering vertex: connect to the chain of this medium.
        if (mode == MXC_WALK_EVAL && any(greaterThan(chainW[k], vec3(0.0))) && (up || k != exitLayer)) {
          vec3 conn = chainDir[k];
          float cosd = max(abs(dot(conn, ns)), 1e-4);
          float dist = up ? z / cosd : (max(d, 0.0) - z) / cosd;
          if (!(halfSpace && !up)) {
            res.value += beta * mxc_hg(dot(w, conn), c.medium[lk].x) * exp(-st * dist) * chainW[k] *
                         mxc_sqr(nEnd / nAbs[k]) * (cosWi / cosd);
          }
        }
        w = mxc_hg_sample(w, c.medium[lk].x, vec2(mxc_walk_u(), mxc_walk_u()));
        res.delta = false;
        continue;
      }
      vec3 tr = exp(-st * toBoundary);
      beta *= tr / max(dot(pc, tr), 1e-30);  // the probability that the chosen flight reaches the boundary
    }
    // At the boundary: the interface above, or the one below.
    inMedium = false;
    if (!down) continue;  // interface k from below
    if (k + 1 >= n) break;  // nothing under the last layer: lost
    k += 1;
  }
  return res;
}

// ---- The closure API ----

// Picks a stack in proportion to the luminance of its weight; returns its index and probability.
int mxc_walk_pick(MxcClosure c, out float p) {
  float x = mxc_walk_u() * c.choiceTotal;
  for (int s = 0; s < c.stackCount; ++s) {
    float ps = mxc_luminance(max(c.stackWeight[s], vec3(0.0))) + 1e-6;
    if (x < ps || s == c.stackCount - 1) {
      p = ps / c.choiceTotal;  // choiceTotal >= 1e-6 per stack
      return s;
    }
    x -= ps;
  }
  p = 1.0;
  return 0;
}

void mxc_closure_prepare(inout MxcClosure c, vec3 wo) {
  c.choiceTotal = 0.0;
  for (int s = 0; s < c.stackCount; ++s) c.choiceTotal += mxc_luminance(max(c.stackWeight[s], vec3(0.0))) + 1e-6;
#ifdef MXC_WALK_EMITS
  bool emits = false;
  for (int k = 0; k < c.count; ++k) emits = emits || any(greaterThan(c.emitted[k], vec3(0.0)));
  if (!emits || c.stackCount == 0) return;
  // OpenPBR "Emission": emitted under the coat and fuzz, and attenuated by them; here by the
  // walk's own transport (the emission is given as the radiance it has once out).
  vec3 sum = vec3(0.0);
  for (int s = 0; s < MXC_REFERENCE_SAMPLES; ++s) {
    float p;
    int stack = mxc_walk_pick(c, p);
    sum += c.stackWeight[stack] / p * mxc_walk(c, stack, wo, wo, MXC_WALK_EMISSION).value;
  }
  c.emission += sum / float(MXC_REFERENCE_SAMPLES);
#endif
}

vec3 mxc_closure_eval(MxcClosure c, vec3 wo, vec3 wi) {
  if (c.stackCount == 0) return vec3(0.0);
  vec3 sum = vec3(0.0);
  for (int s = 0; s < MXC_REFERENCE_SAMPLES; ++s) {
    float p;
    int stack = mxc_walk_pick(c, p);
    sum += c.stackWeight[stack] / p * mxc_walk(c, stack, wo, wi, MXC_WALK_EVAL).value;
  }
  vec3 f = sum / float(MXC_REFERENCE_SAMPLES);
  return all(lessThan(abs(f), vec3(1e30))) ? f : vec3(0.0);
}

// Used only for multiple importance sampling weights: cosine-weighted on both sides.
float mxc_closure_pdf(MxcClosure c, vec3 wo, vec3 wi) {
  if (c.stackCount == 0) return 0.0;
  return 0.5 * abs(dot(wi, c.lobes[0].N)) * MXC_INV_PI;
}

// The walk's sample is weighted by the walk itself: an estimate of f cos / pdf that no
// evaluation at wi reproduces, so `evaluate` stays false.
vec3 mxc_closure_eval_pdf(MxcClosure c, vec3 wo, vec3 wi, bool wantPdf, out float pdf) {
  pdf = wantPdf ? mxc_closure_pdf(c, wo, wi) : 0.0;
  return mxc_closure_eval(c, wo, wi);
}

MxcSample mxc_closure_sample_direction(MxcClosure c, vec3 wo, vec3 u) {
  MxcSample s;
  s.valid = false;
  s.delta = false;
  s.evaluate = false;
  s.pdf = 0.0;
  s.weight = vec3(0.0);
  s.wi = wo;
  if (c.stackCount == 0) return s;
  // The caller's numbers join the invocation's stream, so that equal u give different walks
  // across calls and different u never share one.
  mxc_walk_state = mxc_pcg(mxc_walk_state ^ floatBitsToUint(u.x)) ^ mxc_pcg(floatBitsToUint(u.y) + mxc_pcg(floatBitsToUint(u.z)));
  float p;
  int stack = mxc_walk_pick(c, p);
  MxcWalk walk = mxc_walk(c, stack, wo, wo, MXC_WALK_SAMPLE);
  if (!walk.valid) return s;
  s.wi = walk.wi;
  s.weight = c.stackWeight[stack] / p * walk.value;
  s.delta = walk.delta;
  s.pdf = walk.delta ? 1.0 : mxc_closure_pdf(c, wo, s.wi);
  s.valid = all(lessThan(abs(s.weight), vec3(1e30)));
  return s;
}
