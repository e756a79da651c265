// Draws directions from the environment's distribution, for the test of its sampling against
// the density it reports (tests/runtime/EnvironmentMapTest.cpp): invocation i writes
// mxc_env_out[i] = (direction in map space, pdf as drawn), and mxc_env_out[count + i] =
// (mxc_env_pdf of that direction, 0, 0, 0), the density the renderer's MIS weights use.

layout(local_size_x = 64) in;
layout(push_constant) uniform MxcEnvSamplePush {
  uint count;
  uint seed;
} mxc_env_push;
layout(set = 0, binding = MXC_ENV_SAMPLE_OUTPUT, std430) writeonly buffer MxcEnvOutput { vec4 mxc_env_out[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= mxc_env_push.count) return;
  uint seed = mxc_pcg(i * 4u + mxc_pcg(mxc_env_push.seed));
  vec4 u = vec4(mxc_uniform(seed), mxc_uniform(seed), mxc_uniform(seed), mxc_uniform(seed));
  float pdf;
  vec3 d = mxc_env_sample(u, pdf);
  mxc_env_out[i] = vec4(d, pdf);
  mxc_env_out[mxc_env_push.count + i] = vec4(mxc_env_pdf(d), 0.0, 0.0, 0.0);
}
