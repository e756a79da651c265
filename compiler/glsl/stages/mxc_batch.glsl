// What the compute stages share: the batch uniforms, the buffers, and the shading point they
// evaluate at (a flat surface: normal +z, tangent +x, at the origin).

#include "generated/mxc_batch_block.glsl"

MxcGeometry mxc_flat_geometry() {
  MxcGeometry g;
  g.P = vec3(0.0);
  g.Pobj = vec3(0.0);
  g.N = vec3(0.0, 0.0, 1.0);
  g.Nobj = g.N;
  g.T = vec3(1.0, 0.0, 0.0);
  g.Tobj = g.T;
  g.B = vec3(0.0, 1.0, 0.0);
  g.Bobj = g.B;
  g.uv = mxc_batch.uv.xy;
  g.color = vec4(1.0);
  g.objectToWorld = mat4(1.0);
  g.frame = MXC_PARAMETER(mxc_params.frame);  // as every parameter (ExprEmitter, Op::Parameter)
  g.time = MXC_PARAMETER(mxc_params.time);
  return g;
}
