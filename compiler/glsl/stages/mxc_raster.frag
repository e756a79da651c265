// Fragment stage of the sphere renderer: the material's closure at the shading point, lit by
// the analytic lights (evaluated exactly) and by the environment (integrated by Monte Carlo:
// `counts.w` closure samples per pixel and frame, with the closure's one-sample MIS; frames
// accumulate by additive blending and the harness divides by their number).

layout(location = 0) in vec3 vPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec4 vTangent;
layout(location = 3) in vec2 vUv;
layout(location = 4) in vec3 vObjectPosition;
layout(location = 5) in vec3 vObjectNormal;
layout(location = 6) in vec3 vObjectTangent;

layout(location = 0) out vec4 outColor;

// A smooth analytic sky, y up: a gradient from a warm bright horizon to a blue zenith over a
// darker ground. Smooth radiance lets closure sampling alone converge quickly; the sun, when
// wanted, is a directional light.
vec3 mxc_sky(vec3 d) {
  float y = clamp(d.y, -1.0, 1.0);
  vec3 horizon = vec3(1.0, 0.96, 0.9);
  vec3 zenith = vec3(0.3, 0.5, 0.95);
  vec3 ground = vec3(0.16, 0.145, 0.13);
  if (y >= 0.0) return mix(horizon, zenith, sqrt(y));  // sqrt of y >= 0
  return mix(0.6 * horizon, ground, sqrt(-y));         // -y > 0
}

vec3 mxc_environment(vec3 d) {
  if (mxc_view.counts.y == MXC_ENV_WHITE) return vec3(mxc_view.environment.x);
  if (mxc_view.counts.y == MXC_ENV_SKY) return mxc_view.environment.x * mxc_sky(d);
  return vec3(0.0);
}

// Light refracted into a solid object leaves it on the far side. For a sphere the exit
// refraction deviates the ray by the same angle, in the same sense, as the entry did (the chord
// is symmetric about the sphere's centre), so the environment is seen along the entry's
// direction change applied twice: t rotated once more by the rotation that took d to t
// (Rodrigues' formula). A thin sheet transmits along d itself, which this leaves unchanged.
vec3 mxc_exit_direction(vec3 d, vec3 t) {
  vec3 axis = cross(d, t);
  float s = length(axis);
  if (s < 1e-6) return t;  // no deviation
  axis /= s;               // s > 0
  float c = dot(d, t);
  return t * c + cross(axis, t) * s + axis * dot(axis, t) * (1.0 - c);
}

void main() {
  MxcGeometry g;
  g.P = vPosition;
  g.Pobj = vObjectPosition;
  vec3 N = mxc_safe_normalize(vNormal, vec3(0.0, 0.0, 1.0));
  if (!gl_FrontFacing) N = -N;  // a two-sided surface is shaded on the side the camera sees
  float handedness = vTangent.w < 0.0 ? -1.0 : 1.0;
  mat3 frame = mxc_frame(N, vTangent.xyz);
  g.N = N;
  g.T = frame[0];
  g.B = frame[1] * handedness;
  g.Nobj = mxc_safe_normalize(vObjectNormal, vec3(0.0, 0.0, 1.0));
  mat3 objectFrame = mxc_frame(g.Nobj, vObjectTangent);
  g.Tobj = objectFrame[0];
  g.Bobj = objectFrame[1] * handedness;
  g.uv = vUv;
  g.color = vec4(1.0);
  g.objectToWorld = mxc_view.objectToWorld;
  g.frame = mxc_params.frame;
  g.time = mxc_params.time;
  vec3 wo = mxc_safe_normalize(mxc_view.eye.xyz - vPosition, N);

  mxc_closure_seed(mxc_pcg(uint(gl_FragCoord.x) ^ mxc_pcg(uint(gl_FragCoord.y) + mxc_pcg(uint(mxc_view.counts.z) + 7u))));
  MxcClosure c;
  mxc_material_closure(g, wo, c);
  vec3 radiance = c.emission * mxc_view.environment.y;

  for (int k = 0; k < min(mxc_view.counts.x, MXC_MAX_LIGHTS); ++k) {
    vec4 light = mxc_view.lightVector[k];
    vec3 irradiance = mxc_view.lightRadiance[k].rgb;
    vec3 wi;
    if (light.w == 0.0) {
      wi = mxc_safe_normalize(light.xyz, N);
    } else {
      vec3 d = light.xyz - vPosition;
      float d2 = max(dot(d, d), 1e-8);  // a light inside the surface point: bounded
      wi = d * inversesqrt(d2);
      irradiance /= d2;  // inverse-square falloff of a point light's intensity
    }
    radiance += mxc_closure_eval(c, wo, wi) * irradiance;
  }

  if (mxc_view.counts.y != MXC_ENV_NONE) {
    int n = max(mxc_view.counts.w, 1);
    uint seed = mxc_pcg(uint(gl_FragCoord.x) + mxc_pcg(uint(gl_FragCoord.y) + mxc_pcg(uint(mxc_view.counts.z))));
    vec3 sum = vec3(0.0);
    for (int s = 0; s < n; ++s) {
      vec3 u = vec3(mxc_uniform(seed), mxc_uniform(seed), mxc_uniform(seed));
      MxcSample smp = mxc_closure_sample(c, wo, u);
      if (!smp.valid) continue;
      vec3 seen = dot(smp.wi, N) < 0.0 ? mxc_exit_direction(-wo, smp.wi) : smp.wi;
      sum += smp.weight * mxc_environment(seen);
    }
    radiance += sum / float(n);  // n >= 1
  }
  // What passes straight through (opacity < 1) shows the background, which the harness
  // composites under the accumulated image with (1 - alpha).
  float coverage = 1.0 - clamp(mxc_luminance(c.transparency), 0.0, 1.0);
  outColor = vec4(radiance, coverage);
}
