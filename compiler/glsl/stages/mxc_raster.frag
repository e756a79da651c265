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

// What the scene has, from the specialization constants where the pipeline has them (then the
// code of what the scene does not have folds away), else from the view block.
int mxc_environment_code() { return MXC_ENVIRONMENT != MXC_FROM_VIEW ? MXC_ENVIRONMENT : mxc_view.counts.y; }
int mxc_light_count() {
  return min(MXC_LIGHT_COUNT != MXC_FROM_VIEW ? MXC_LIGHT_COUNT : mxc_view.counts.x, MXC_MAX_LIGHTS);
}
int mxc_light_kinds() {
  const int all = (1 << MXC_LIGHT_DIRECTIONAL) | (1 << MXC_LIGHT_POINT) | (1 << MXC_LIGHT_SPOT);
  return MXC_LIGHT_KINDS != MXC_FROM_VIEW ? MXC_LIGHT_KINDS : all;
}

// Radiance arriving from world direction d.
vec3 mxc_environment(vec3 d) {
  int code = mxc_environment_code();
  if (code == MXC_ENV_WHITE) return vec3(mxc_view.environment.x);
  if (code == MXC_ENV_SKY) return mxc_view.environment.x * mxc_sky(d);
  if (code == MXC_ENV_MAP) {
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
  vec3 wo = mxc_safe_normalize(mxc_view.eye.xyz - vPosition, N);
  // The interpolated normal of a facet the camera sees can still face away from the camera
  // near a silhouette (the vertex normals lean past the view there). A closure seen from below
  // its horizon samples by densities that vanish there (the visible normals of a view below the
  // horizon): a direction drawn with a pdf of 1e-6 weighs f / pdf = 1e12, the fireflies of car
  // paint's silhouette (issue 39). The shading normal is bent towards the eye just enough that
  // the eye is above its horizon by MXC_VIEW_HORIZON: N + t wo with dot(wo, N + t wo) = 0.01.
  const float MXC_VIEW_HORIZON = 0.01;
  float facing = dot(wo, N);
  if (facing < MXC_VIEW_HORIZON) N = normalize(N + (MXC_VIEW_HORIZON - facing) * wo);  // |N| >= ~0.01: not zero
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
  g.frame = MXC_PARAMETER(mxc_params.frame);  // as every parameter (ExprEmitter, Op::Parameter)
  g.time = MXC_PARAMETER(mxc_params.time);
#ifdef MXC_HAS_TEXTURE_FOOTPRINT
  mxc_texture_footprint = mxc_view.jitter.z;  // set by the renderer; 0 from a host that leaves it: guarded below
  if (!(mxc_texture_footprint > 0.0)) mxc_texture_footprint = 1.0;
#endif

  mxc_closure_seed(mxc_pcg(uint(gl_FragCoord.x) ^ mxc_pcg(uint(gl_FragCoord.y) + mxc_pcg(uint(mxc_view.counts.z) + 7u))));
  MxcClosure c;
  mxc_material_closure(g, wo, c);
  vec3 radiance = c.emission * mxc_view.environment.y;

  // Every direction the point is lit from goes through one call of mxc_closure_eval_pdf: the
  // device compiler inlines every call, and the closure's evaluation is most of the shader
  // (with one call site instead of three, lavapipe builds the pipeline about 1.5x as fast).
  // Lavapipe runs pixels in SIMD lanes and executes both sides of every branch, masked; so the
  // work is batched: batch b draws environment sample b (the closure's direction and, for an
  // image, the image's), batch 0 also takes the lights, and one inner loop evaluates the
  // batch's directions. Each strategy's code then runs once per batch, as it would unbatched.
  int lights = mxc_light_count();
  int kinds = mxc_light_kinds();
  bool image = mxc_environment_code() == MXC_ENV_MAP;
  int n = mxc_environment_code() != MXC_ENV_NONE ? max(mxc_view.counts.w, 1) : 0;
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
  vec3 sum = vec3(0.0);  // the environment samples' estimates
#ifdef MXC_SAMPLES_WEIGHTED
  const int evaluatedClosureSamples = 0;  // the closure weighs its samples (a walk)
#else
  const int evaluatedClosureSamples = 1;
#endif
  for (int b = 0; b < max(n, lights > 0 ? 1 : 0); ++b) {
    int batchLights = b == 0 ? lights : 0;
    // The directions of environment sample b that the inner loop evaluates.
    int batchSamples = b < n ? evaluatedClosureSamples + (image ? 1 : 0) : 0;
    uint index = uint(mxc_view.counts.z) * uint(max(n, 1)) + uint(b);
    vec4 choice = fract(vec4(mxc_radical_inverse(index, 2u), mxc_radical_inverse(index, 3u),
                             mxc_radical_inverse(index, 5u), mxc_radical_inverse(index, 7u)) + shift);
    // The closure's sample. Above the surface an image's samples reach the same directions: the
    // two are weighted against each other. Below it (transmission) and for delta lobes only the
    // closure reaches the direction, with weight 1.
    // Not drawn at all without an environment (n = 0: a constant where the pipeline is
    // specialized, and the sampling code is then not compiled).
    MxcSample smp;
    smp.valid = false;
    smp.evaluate = false;
    smp.delta = false;
    smp.pdf = 0.0;
    smp.weight = vec3(0.0);
    smp.wi = N;
    if (n > 0) smp = mxc_closure_sample_direction(c, wo, vec3(choice.z, choice.w, choice.x));
    bool above = dot(smp.wi, N) > 0.0;
    vec3 seen = smp.valid ? mxc_environment(above ? smp.wi : mxc_exit_direction(-wo, smp.wi)) : vec3(0.0);
    if (b < n && smp.valid && !smp.evaluate) {  // weighted by the closure (a delta lobe, a walk)
      float w = image && above && !smp.delta
                    ? mxc_power_heuristic(smp.pdf, mxc_env_pdf(mxc_env_to_map(smp.wi, mxc_view.environment.z)))
                    : 1.0;
      sum += w * smp.weight * seen;
    }
    // The image's sample, where the image is bright; only above the surface (see above).
    vec3 m = vec3(0.0);    // its direction in the map
    float lightPdf = 0.0;  // the density it was drawn with
    vec3 imageWi = N;
    vec3 imageSeen = vec3(0.0);
    if (image && b < n) {
      vec4 v = vec4(choice.y, mxc_uniform(seed), mxc_uniform(seed), mxc_uniform(seed));
      m = mxc_env_sample(v, lightPdf);
      imageWi = mxc_env_to_world(m, mxc_view.environment.z);
      if (lightPdf > 0.0 && dot(imageWi, N) > 0.0) imageSeen = mxc_environment(imageWi);
    }
    for (int j = 0; j < batchLights + batchSamples; ++j) {
      vec3 wi = N;
      vec3 incoming = vec3(0.0);  // a light's irradiance, or the radiance arriving along wi
      bool use = true;            // wi contributes
      // 0: light j, 1: the closure's sample, 2: the image's sample.
      int strategy = n == 0 || j < batchLights ? 0 : j == batchLights + evaluatedClosureSamples - 1 ? 1 : 2;
      if (strategy == 0) {
        vec4 light = mxc_view.lightVector[j];
        incoming = mxc_view.lightRadiance[j].rgb;
        // Only the kinds the scene has (constant where the pipeline is specialized).
        const int directionalOnly = 1 << MXC_LIGHT_DIRECTIONAL;
        bool directional = kinds == directionalOnly || ((kinds & directionalOnly) != 0 && light.w == float(MXC_LIGHT_DIRECTIONAL));
        if (directional) {
          wi = mxc_safe_normalize(light.xyz, N);
        } else {
          vec3 d = light.xyz - vPosition;
          float d2 = max(dot(d, d), 1e-8);  // a light inside the surface point: bounded
          wi = d * inversesqrt(d2);
          incoming /= d2;  // inverse-square falloff of a point light's intensity
          if ((kinds & (1 << MXC_LIGHT_SPOT)) != 0 && light.w == float(MXC_LIGHT_SPOT)) {
            // A spot light: full inside the inner cone, none outside the outer one, a smooth
            // fade between (cosInner > cosOuter, checked where the light is made).
            vec4 spot = mxc_view.lightSpot[j];
            incoming *= smoothstep(spot.w, mxc_view.lightRadiance[j].w, dot(-wi, spot.xyz));
          }
        }
      } else if (strategy == 1) {
        wi = smp.wi;
        incoming = seen;
        use = smp.valid && smp.evaluate;
      } else {
        wi = imageWi;
        incoming = imageSeen;
        use = lightPdf > 0.0 && dot(imageWi, N) > 0.0;
      }
      float pdf;
      vec3 f = mxc_closure_eval_pdf(c, wo, wi, strategy != 0, pdf);  // a light needs no pdf
      if (strategy == 0) {
        radiance += f * incoming;
      } else if (strategy == 1) {
        if (use && pdf > 0.0) {
          float w = image && above ? mxc_power_heuristic(pdf, mxc_env_pdf(mxc_env_to_map(wi, mxc_view.environment.z))) : 1.0;
          sum += w * f / pdf * incoming;  // pdf > 0
        }
      } else if (use) {
        // The estimate divides by the density the direction was drawn with; the weight reads
        // the density as the closure's samples read it (mxc_env_pdf), so that the two weights
        // sum to 1 at every direction, even one on a cell's edge that rounding puts in either.
        float w = mxc_power_heuristic(mxc_env_pdf(m), pdf);
        sum += w * f * incoming / lightPdf;  // lightPdf > 0 where used
      }
    }
  }
  radiance += sum / float(max(n, 1));  // n >= 1 wherever sum is not zero

  // What passes straight through (opacity < 1) shows the background, which the harness
  // composites under the accumulated image with (1 - alpha).
  float coverage = 1.0 - clamp(mxc_luminance(c.transparency), 0.0, 1.0);
  outColor = vec4(radiance, coverage);
}
