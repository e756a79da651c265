// Fragment stage of the sphere renderer: the material's closure at the shading point, lit by
// the analytic lights (evaluated exactly) and by the environment (integrated by Monte Carlo:
// `counts.w` samples per pixel and frame; frames accumulate by additive blending and the
// harness divides by their number). An environment image is sampled two ways, by the closure
// and by the image's own distribution (stages/mxc_environment.glsl), combined by multiple
// importance sampling with the power heuristic (Veach 1997, s. 9.2); the smooth environments
// (white, sky) by the closure alone.

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
  // Continuous at the horizon (both halves start from `horizon`), so glossy surfaces show no
  // line where the sky meets the ground.
  if (y >= 0.0) return mix(horizon, zenith, sqrt(y));  // sqrt of y >= 0
  return mix(horizon, ground, sqrt(-y));               // -y > 0
}

// Radiance arriving from world direction d.
vec3 mxc_environment(vec3 d) {
  if (mxc_view.counts.y == MXC_ENV_WHITE) return vec3(mxc_view.environment.x);
  if (mxc_view.counts.y == MXC_ENV_SKY) return mxc_view.environment.x * mxc_sky(d);
  if (mxc_view.counts.y == MXC_ENV_MAP) {
    return mxc_view.environment.x * mxc_env_lookup(mxc_env_to_map(d, mxc_view.environment.z));
  }
  return vec3(0.0);
}

// The radical inverse of i in base b (van der Corput for b = 2; Halton 1964), in [0, 1).
float mxc_radical_inverse(uint i, uint base) {
  if (base == 2u) return float(bitfieldReverse(i) >> 8) * (1.0 / 16777216.0);  // 24 bits
  float inv = 1.0 / float(base);  // base >= 2
  float f = inv, r = 0.0;
  for (; i > 0u; i /= base) {
    r += f * float(i % base);
    f *= inv;
  }
  return min(r, 0.99999994);  // rounding must not reach 1
}

// The power heuristic's weight (beta = 2) of a strategy with density a against one with b.
float mxc_power_heuristic(float a, float b) {
  float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.0 ? a2 / (a2 + b2) : 0.0;  // > 0: not both zero
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
      if (light.w == 2.0) {
        // A spot light: full inside the inner cone, none outside the outer one, a smooth fade
        // between (cosInner > cosOuter, checked where the light is made).
        vec4 spot = mxc_view.lightSpot[k];
        irradiance *= smoothstep(spot.w, mxc_view.lightRadiance[k].w, dot(-wi, spot.xyz));
      }
    }
    radiance += mxc_closure_eval(c, wo, wi) * irradiance;
  }

  if (mxc_view.counts.y != MXC_ENV_NONE) {
    int n = max(mxc_view.counts.w, 1);
    uint seed = mxc_pcg(uint(gl_FragCoord.x) + mxc_pcg(uint(gl_FragCoord.y) + mxc_pcg(uint(mxc_view.counts.z))));
    // The closure sample's three numbers (lobe choice, then direction) and the image sample's
    // cell follow a 4D Halton sequence (bases 2, 3, 5, 7; Halton 1964) over the pixel's samples,
    // frame by frame, shifted by a random offset per pixel (Cranley & Patterson 1976): each
    // number stays uniform, so nothing is biased, but over N samples a lobe taken with
    // probability p is taken about pN times rather than a binomial count, and directions cover
    // the lobe evenly. With independent numbers a smooth coat or glass, whose reflection is
    // taken a few percent of the time, shows a bright light's reflection as speckle.
    uint pixel = mxc_pcg(uint(gl_FragCoord.x) ^ mxc_pcg(uint(gl_FragCoord.y) + 0x9e3779b9u));
    vec4 shift = vec4(mxc_uniform(pixel), mxc_uniform(pixel), mxc_uniform(pixel), mxc_uniform(pixel));
    bool image = mxc_view.counts.y == MXC_ENV_MAP;
    vec3 sum = vec3(0.0);
    for (int s = 0; s < n; ++s) {
      uint index = uint(mxc_view.counts.z) * uint(n) + uint(s);
      vec4 choice = fract(vec4(mxc_radical_inverse(index, 2u), mxc_radical_inverse(index, 3u),
                               mxc_radical_inverse(index, 5u), mxc_radical_inverse(index, 7u)) + shift);
      // The closure's sample. Above the surface an image's samples reach the same directions:
      // the two are weighted against each other. Below it (transmission) and for delta lobes
      // only the closure reaches the direction, with weight 1.
      vec3 u = vec3(choice.z, choice.w, choice.x);
      MxcSample smp = mxc_closure_sample(c, wo, u);
      if (smp.valid) {
        bool above = dot(smp.wi, N) > 0.0;
        vec3 seen = above ? smp.wi : mxc_exit_direction(-wo, smp.wi);
        float w = 1.0;
        if (image && above && !smp.delta) {
          w = mxc_power_heuristic(smp.pdf, mxc_env_pdf(mxc_env_to_map(smp.wi, mxc_view.environment.z)));
        }
        sum += w * smp.weight * mxc_environment(seen);
      }
      if (!image) continue;
      // The image's sample, where the image is bright; only above the surface (see above).
      vec4 v = vec4(choice.y, mxc_uniform(seed), mxc_uniform(seed), mxc_uniform(seed));
      // The estimate divides by the density the direction was drawn with; the weight reads the
      // density as the closure's samples read it (mxc_env_pdf), so that the two weights sum to 1
      // at every direction, even one on a cell's edge that rounding puts in either cell.
      float lightPdf;
      vec3 m = mxc_env_sample(v, lightPdf);
      vec3 wi = mxc_env_to_world(m, mxc_view.environment.z);
      if (lightPdf > 0.0 && dot(wi, N) > 0.0) {
        float w = mxc_power_heuristic(mxc_env_pdf(m), mxc_closure_pdf(c, wo, wi));
        sum += w * mxc_closure_eval(c, wo, wi) * mxc_environment(wi) / lightPdf;  // lightPdf > 0
      }
    }
    radiance += sum / float(n);  // n >= 1
  }
  // What passes straight through (opacity < 1) shows the background, which the harness
  // composites under the accumulated image with (1 - alpha).
  float coverage = 1.0 - clamp(mxc_luminance(c.transparency), 0.0, 1.0);
  outColor = vec4(radiance, coverage);
}
