// Directions drawn by the closure's own sampling, for checking them against its pdf: for the
// view mxc_in[a] (work group a), invocation t draws counts.y samples and writes sample s at
// mxc_out[(MXC_WORK_GROUP_SIZE a + t) counts.y + s] = (wi, kind), kind 1 for a sample of the continuous part
// (density mxc_closure_pdf), 2 for a delta lobe's sample, 0 for none (the lobe's sample failed).

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
  uint base = (MXC_WORK_GROUP_SIZE * a + t) * mxc_batch.counts.y;
  for (uint s = 0u; s < mxc_batch.counts.y; ++s) {
    vec3 u = vec3(mxc_uniform(seed), mxc_uniform(seed), mxc_uniform(seed));
    MxcSample smp = mxc_closure_sample(c, wo, u);
    float kind = smp.valid ? (smp.delta ? 2.0 : 1.0) : 0.0;
    mxc_out[base + s] = vec4(smp.wi, kind);
  }
}
