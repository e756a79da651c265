// A sample of either closure (mxc_closure.glsl, mxc_walk.glsl) with its weight: the
// direction, then, unless the closure weighted it itself (a delta lobe, a walk), the mixture's
// f cos / pdf at it. For stages that evaluate no other direction; the renderer's fragment
// stage calls the two halves itself, with one evaluation for every direction it lights from.
MxcSample mxc_closure_sample(MxcClosure c, vec3 wo, vec3 u) {
  MxcSample s = mxc_closure_sample_direction(c, wo, u);
#ifdef MXC_SAMPLES_WEIGHTED
  // No evaluation compiled: lavapipe would run it, masked, for every sample.
  return s;
#else
  if (!s.valid || !s.evaluate) return s;
  vec3 f = mxc_closure_eval_pdf(c, wo, s.wi, true, s.pdf);
  s.evaluate = false;
  s.valid = s.pdf > 0.0;
  s.weight = s.valid ? f / s.pdf : vec3(0.0);  // pdf > 0 where valid
  return s;
#endif
}
