// Evaluation of the material for rows of direction pairs: mxc_in[2i] = wo, mxc_in[2i + 1] = wi
// (unit vectors in the frame of mxc_flat_geometry); mxc_out[i] = (f(wo, wi) |wi.z|, pdf of
// sampling wi from wo).

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= mxc_batch.counts.x) return;
  MxcGeometry g = mxc_flat_geometry();
  vec3 wo = mxc_in[2u * i].xyz;
  vec3 wi = mxc_in[2u * i + 1u].xyz;
  mxc_closure_seed(mxc_pcg(i + mxc_pcg(mxc_batch.counts.z)));
  MxcClosure c;
  mxc_material_closure(g, wo, c);
  float pdf;
  vec3 f = mxc_closure_eval_pdf(c, wo, wi, true, pdf);
  mxc_out[i] = vec4(f, pdf);
}
