// The white furnace: the directional albedo of the material for the view directions
// mxc_in[a], by Monte Carlo with the closure's own sampling. Work group a, invocation t writes
// the sums of its `counts.y` samples: mxc_out[4 (MXC_WORK_GROUP_SIZE a + t) + k] = reflected sum, transmitted
// sum, and their squares (k = 0..3), from which the host gets the mean and its standard error.
// Light passing straight through (opacity < 1) counts as transmitted.

void main() {
  uint a = gl_WorkGroupID.x;
  uint t = gl_LocalInvocationID.x;
  if (a >= mxc_batch.counts.x) return;
  MxcGeometry g = mxc_flat_geometry();
  vec3 wo = mxc_in[a].xyz;
  uint seed = mxc_pcg(MXC_WORK_GROUP_SIZE * a + t + mxc_pcg(mxc_batch.counts.z));
  mxc_closure_seed(seed ^ 0x5bd1e995u);
  MxcClosure c;
  mxc_material_closure(g, wo, c);
  vec3 r = vec3(0.0), tr = vec3(0.0), r2 = vec3(0.0), tr2 = vec3(0.0);
  uint drawn = 0u;
  for (uint s = 0u; s < mxc_batch.counts.y; ++s) {
    ++drawn;
    vec3 u = vec3(mxc_uniform(seed), mxc_uniform(seed), mxc_uniform(seed));
    MxcSample smp = mxc_closure_sample(c, wo, u);
    vec3 w = smp.valid ? smp.weight : vec3(0.0);
    vec3 reflected = smp.wi.z > 0.0 ? w : vec3(0.0);
    vec3 transmitted = (smp.wi.z > 0.0 ? vec3(0.0) : w) + c.transparency;
    r += reflected;
    tr += transmitted;
    r2 += reflected * reflected;
    tr2 += transmitted * transmitted;
  }
  uint base = 4u * (MXC_WORK_GROUP_SIZE * a + t);
  // w: the samples this invocation drew, which the host checks (a device may cut long loops).
  mxc_out[base] = vec4(r, float(drawn));
  mxc_out[base + 1u] = vec4(tr, 0.0);
  mxc_out[base + 2u] = vec4(r2, 0.0);
  mxc_out[base + 3u] = vec4(tr2, 0.0);
}
