// What the compute stages share: the batch uniforms, the buffers, and the shading point they
// evaluate at (a flat surface: normal +z, tangent +x, at the origin).

layout(local_size_x = 64) in;

layout(set = 0, binding = 1, std140) uniform MxcBatch {
  uvec4 counts;  // x: rows (eval) or angles (furnace), y: samples per invocation, z: random seed
  vec4 uv;       // xy: texture coordinates of the shading point
} mxc_batch;

layout(set = 0, binding = 3, std430) readonly buffer MxcInput { vec4 mxc_in[]; };
layout(set = 0, binding = 4, std430) writeonly buffer MxcOutput { vec4 mxc_out[]; };

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
  g.frame = mxc_params.frame;
  g.time = mxc_params.time;
  return g;
}
