// A material at a shading point, reduced to a weighted mixture of lobes (OpenPBR 1.1
// "Reduction to a mixture of lobes"): the generated code fills an MxcClosure for a view
// direction; these functions evaluate and sample it. World-space directions.

// The path length assumed inside a bulk medium under a transmitting interface, in scene units
// (the radius of the renderer's sphere): a closure sees one interface, not the whole object.
const float MXC_BULK_PATH = 1.0;

struct MxcClosure {
  MxcLobe lobes[MXC_MAX_LOBES];
  int count;
  float choice[MXC_MAX_LOBES];  // how often each lobe is sampled (mxc_closure_prepare), for this wo
  float choiceTotal;
  vec3 ms[MXC_MAX_LOBES];       // each lobe's multiple-scattering factor for this wo (mxc_lobe_ms_scale)
  float msT[MXC_MAX_LOBES];     // and on its refraction (mxc_lobe_ms_transmit)
  // A lobe whose multiple scattering is shaped (mxc_lobe_ms_shaped): its f_ms cos is that of
  // the broader lobes mxc_ms_lobe times msLobe in reflection and msLobeT in refraction, and a
  // sample of the lobe is one of the broader lobes with probability msPick (0: none), of the
  // reflecting one with probability msSplit among those.
  vec3 msLobe[MXC_MAX_LOBES];
  vec3 msLobeT[MXC_MAX_LOBES];
  float msPick[MXC_MAX_LOBES];
  float msSplit[MXC_MAX_LOBES];
  vec3 emission;      // radiance leaving towards wo
  vec3 transparency;  // weight of light passing straight through (opacity < 1)
};

// The closures of this file are deterministic: the stages' seed is not needed (the reference
// tier's walk, mxc_walk.glsl, uses it).
void mxc_closure_seed(uint seed) {}

struct MxcSample {
  vec3 wi;       // world space
  vec3 weight;   // f |cos| / pdf (for a delta lobe: its discrete weight / probability)
  float pdf;
  bool delta;
  // Only wi is set: weight and pdf are f cos / pdf and the pdf that mxc_closure_eval_pdf
  // gives at wi (a stage evaluating other directions too calls it once for all of them).
  bool evaluate;
  bool valid;
};

// Transmittance of absorbing media (optical depth tau at normal incidence) along a direction
// with cosine mu outside, refracted into a medium of IOR eta (OpenPBR "View-dependent
// absorption": T^(1/mu_t)). mu_t >= 0.05 bounds the path length at grazing angles.
vec3 mxc_absorption(vec3 tau, float eta, float mu) {
  if (tau == vec3(0.0)) return vec3(1.0);
  float mut = mxc_safe_sqrt(1.0 - (1.0 - mu * mu) / (eta * eta));  // eta >= 1e-3 (set by the generator)
  return exp(-tau / max(mut, 0.05));
}

// The transmittance of the absorbing media above a lobe along a direction of cosine mu. Without
// MXC_ABSORPTION no lobe of the material lies under an absorbing medium (the back end defines it
// from the lobes' optical depths), and none is computed.
#ifdef MXC_ABSORPTION
vec3 mxc_lobe_absorption(MxcLobe l, float mu) { return mxc_absorption(l.tau, l.tauEta, mu); }
#else
vec3 mxc_lobe_absorption(MxcLobe l, float mu) { return vec3(1.0); }
#endif

// How often each lobe is chosen: in proportion to the luminance of what it can return, with a
// floor so that a lobe that returns little is still sampled. A lobe of weight exactly 0 returns
// nothing and is never chosen: a shader that keeps every lobe of its shading model (`mxc
// compile --no-specialize`) then draws the very samples of one compiled without them, and its
// image is the same (tests/runtime/SpecializationTest.cpp).
// `ms`: the lobe's multiple-scattering factor at woLocal.
float mxc_lobe_choice(MxcLobe l, vec3 woLocal, vec3 ms) {
  if (l.weight == vec3(0.0)) return 0.0;
  return max(mxc_luminance(l.weight * mxc_lobe_albedo_scaled(l, woLocal, ms)), 0.0) + 1e-4;
}

// Fills the lobe choice weights and multiple-scattering factors for the closure's view
// direction; the generated closure function calls it last, so that evaluation, sampling and
// pdfs do not recompute them; the lobe choice reuses the factor (the layering's albedos, built
// before, compute their own).
void mxc_closure_prepare(inout MxcClosure c, vec3 wo) {
  c.choiceTotal = 0.0;
  for (int k = 0; k < c.count; ++k) {
    MxcLobe l = c.lobes[k];
    // A lobe that is off (an input of the general shader at 0) is never evaluated nor chosen:
    // its factor and its tables' lookups are not needed.
    c.ms[k] = vec3(1.0);
    c.msT[k] = 1.0;
    c.msLobe[k] = vec3(0.0);
    c.msLobeT[k] = vec3(0.0);
    c.msPick[k] = 0.0;
    c.msSplit[k] = 1.0;
    c.choice[k] = 0.0;
    if (l.weight == vec3(0.0)) continue;
    vec3 o = mxc_to_local(mxc_frame(l.N, l.T), wo);
    vec3 ms = mxc_lobe_ms_scale(l, o);
    c.msT[k] = mxc_lobe_ms_transmit(l, o, ms);
    c.choice[k] = mxc_lobe_choice(l, o, ms);
    c.choiceTotal += c.choice[k];
    if (mxc_lobe_ms_shaped(l, o)) {
      // The compensation's energy at wo, in reflection and (a dielectric that transmits) in
      // refraction, as lobes of their own; the single scattering unscaled.
      float alpha = sqrt(l.alpha.x * l.alpha.y);  // the tables' isotropic alpha: geometric mean
      vec3 reflected = mxc_lobe_albedo_scaled(l, o, vec3(1.0));
      vec3 addedR = max(mxc_lobe_albedo_scaled(l, o, ms) - reflected, vec3(0.0));
      vec3 transmitted = vec3(0.0);
      vec3 addedT = vec3(0.0);
#ifndef MXC_ACCURACY_FAST  // (fast has no shaped lobe: mxc_lobe_ms_shaped)
      if (l.kind == MXC_LOBE_DIELECTRIC && mxc_lobe_transmits(l)) {
        float rss = mxc_dielectric_albedo(o.z, alpha, l.eta);
        transmitted = max(mxc_dielectric_albedo_rt(o.z, alpha, l.eta) - rss, 0.0) * l.c1;
        addedT = max(c.msT[k] - 1.0, 0.0) * transmitted;  // msT >= 1: (1 - R_ms) / T_ss
      }
#endif
      // Over wi, the broader lobe's f cos integrates to its albedo: divided by it, each part
      // returns exactly the energy added (floors: a lobe that reflects or refracts nothing).
      MxcLobe mr = mxc_ms_lobe(l, false);
      vec3 broadR = mxc_lobe_albedo_scaled(mr, o, vec3(1.0));
      float broadT = 1.0;
#ifndef MXC_ACCURACY_FAST
      if (l.kind == MXC_LOBE_DIELECTRIC && mxc_lobe_transmits(l)) {
        MxcLobe mt = mxc_ms_lobe(l, true);
        float at = sqrt(mt.alpha.x * mt.alpha.y);
        broadT = mxc_dielectric_albedo_rt(o.z, at, l.eta) - mxc_dielectric_albedo(o.z, at, l.eta);
      }
#endif
      c.msLobe[k] = addedR / max(broadR, vec3(1e-4));
      c.msLobeT[k] = addedT / max(broadT, 1e-4);
      // In proportion to the energy; below 1 so that the lobe's own sampler keeps a share (the
      // mixture's pdf is then > 0 wherever the single scattering is).
      float total = max(mxc_luminance(reflected + addedR + transmitted + addedT), 1e-6);
      float added = mxc_luminance(addedR + addedT);
      c.msPick[k] = 0.999 * min(added / total, 1.0);
      c.msSplit[k] = added > 0.0 ? mxc_luminance(addedR) / added : 1.0;
      c.msT[k] = 1.0;
    } else {
      c.ms[k] = ms;
    }
  }
}

// f cos and, when `wantPdf`, the pdf of sampling wi (mxc_closure_sample_direction; else 0)
// together: one loop over the lobes, so that a stage evaluating directions for either needs one
// inlined copy of the lobes. Callers pass a `wantPdf` that is the same for every invocation.
vec3 mxc_closure_eval_pdf(MxcClosure c, vec3 wo, vec3 wi, bool wantPdf, out float pdf) {
  vec3 f = vec3(0.0);
  float p = 0.0;
  for (int k = 0; k < c.count; ++k) {
    MxcLobe l = c.lobes[k];
    if (l.weight == vec3(0.0)) continue;  // off (an input of the general shader): its f is 0
    mat3 frame = mxc_frame(l.N, l.T);
    vec3 o = mxc_to_local(frame, wo);
    vec3 i = mxc_to_local(frame, wi);
    vec3 fk = vec3(0.0);
    float pk = 0.0;
    // Pass 0: the lobe; pass 1 (a lobe whose multiple scattering is shaped, seen from above:
    // mxc_lobe_ms_shaped): its multiple scattering, the broader lobe on wi's side, sampled with
    // probability msPick, its reflecting part msSplit of that. A loop with a bound known only
    // at run time keeps one inlined copy of the lobe code (lavapipe compiles each copy).
    int passes = c.msPick[k] > 0.0 ? 2 : 1;
    for (int pass = 0; pass < passes; ++pass) {
      bool shaped = pass == 1;
      MxcLobe m = shaped ? mxc_ms_lobe(l, i.z < 0.0) : l;
      vec3 scale = shaped ? (i.z > 0.0 ? c.msLobe[k] : c.msLobeT[k])
                          : (o.z * i.z < 0.0 ? vec3(c.msT[k]) : c.ms[k]);  // refraction or reflection
      fk += scale * mxc_lobe_eval(m, o, i);
      if (wantPdf) {
        float share = shaped ? c.msPick[k] * (i.z > 0.0 ? c.msSplit[k] : 1.0 - c.msSplit[k]) : 1.0 - c.msPick[k];
        pk += share * mxc_lobe_pdf(m, o, i);
      }
    }
    f += l.weight * mxc_lobe_absorption(l, abs(i.z)) * fk;
    if (wantPdf) p += c.choice[k] * pk;
  }
  pdf = c.choiceTotal > 0.0 ? p / c.choiceTotal : 0.0;
  return f;
}

// One-sample multiple importance sampling over the lobes (Veach 1997, s. 9.2.4): a lobe is
// chosen, sampled, and the sample weighted by the whole mixture's f and pdf; a delta lobe's
// sample is weighted by that lobe alone (no other lobe reaches its direction). Only the delta
// lobe's weight is set here: the others' is the mixture's, left to mxc_closure_eval_pdf
// (`evaluate`; mxc_closure_sample does both).
MxcSample mxc_closure_sample_direction(MxcClosure c, vec3 wo, vec3 u) {
  MxcSample s;
  s.valid = false;
  s.delta = false;
  s.evaluate = false;
  s.pdf = 0.0;
  s.weight = vec3(0.0);
  s.wi = wo;
  float total = c.choiceTotal;  // >= 1e-4 per lobe of weight other than 0
  if (c.count == 0 || total <= 0.0) return s;
  // Pick lobe k with probability choice_k / total, reusing u.z for the lobe's own choice. A
  // lobe of choice 0 is never picked: x < before + 0 cannot hold once x >= before, and the last
  // lobe that can be chosen takes what rounding leaves over.
  float x = u.z * total;
  int chosen = -1;
  float before = 0.0;
  float p = 0.0;
  float lastBefore = 0.0;
  int last = -1;
  for (int k = 0; k < c.count; ++k) {
    float pk = c.choice[k];
    if (pk <= 0.0) continue;
    if (x < before + pk) {
      chosen = k;
      p = pk;
      break;
    }
    last = k;
    lastBefore = before;
    before += pk;
  }
  if (chosen < 0) {  // x >= the sum by rounding: the last lobe with a choice (total > 0: there is one)
    chosen = max(last, 0);
    p = c.choice[chosen];
    before = lastBefore;
  }
  if (p <= 0.0) return s;
  float uz = clamp((x - before) / p, 0.0, 0.99999994);  // p > 0
  MxcLobe l = c.lobes[chosen];
  mat3 frame = mxc_frame(l.N, l.T);
  vec3 o = mxc_to_local(frame, wo);
  // The lobe's shaped multiple scattering with probability q: a sample of the broader lobe,
  // reflecting with probability msSplit; the mixture's pdf has it (mxc_closure_eval_pdf). One
  // call of the sampler for either (one inlined copy).
  float q = c.msPick[chosen];
  bool shaped = uz < q;
  bool reflected = true;
  if (shaped) {
    float v = uz / q;  // q > 0
    float split = c.msSplit[chosen];
    reflected = v < split;
    uz = reflected ? v / max(split, 1e-6) : (v - split) / max(1.0 - split, 1e-6);
  } else {
    uz = (uz - q) / (1.0 - q);  // q <= 0.999
  }
  MxcLobe m = shaped ? mxc_ms_lobe(l, !reflected) : l;
  MxcLobeSample ls = mxc_lobe_sample(m, o, vec3(u.xy, min(uz, 0.99999994)));
  if (!ls.valid) return s;
  s.wi = mxc_to_world(frame, ls.wi);
  if (ls.delta) {
    s.delta = true;
    s.pdf = ls.pdf * p / total;
    s.weight = l.weight * c.ms[chosen] * mxc_lobe_absorption(l, abs(ls.wi.z)) * ls.value / s.pdf;
    s.valid = s.pdf > 0.0;
    return s;
  }
  // The whole mixture's f and pdf at wi: mxc_closure_eval_pdf, by the caller.
  s.evaluate = true;
  s.valid = true;
  return s;
}
