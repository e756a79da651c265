// mxc shader library: constants, guarded math, shading frames, random numbers.
// Every division, square root, normalisation and pow states why it is safe.

#include "generated/mxc_codes.glsl"

const float MXC_PI = 3.14159265358979;
const float MXC_INV_PI = 0.318309886183791;
const float MXC_EPS = 1e-7;

float mxc_sqr(float x) { return x * x; }
vec3 mxc_sqr(vec3 x) { return x * x; }
float mxc_mean(vec3 c) { return (c.x + c.y + c.z) * (1.0 / 3.0); }
float mxc_luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }  // Rec.709 weights

// sqrt of a value that rounding can push slightly below 0.
float mxc_safe_sqrt(float x) { return sqrt(max(x, 0.0)); }
vec3 mxc_safe_sqrt(vec3 x) { return sqrt(max(x, vec3(0.0))); }

// v / |v|, or `fallback` when |v| is too small to have a direction.
vec3 mxc_safe_normalize(vec3 v, vec3 fallback) {
  float l2 = dot(v, v);
  return l2 > 1e-20 ? v * inversesqrt(l2) : fallback;
}

// An orthonormal frame (tangent, bitangent, normal) around N, with the tangent T projected
// into the tangent plane. A degenerate tangent (zero, NaN, or parallel to N) is replaced by
// a tangent built from N alone (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
mat3 mxc_frame(vec3 N, vec3 T) {
  vec3 t = T - N * dot(N, T);
  float l2 = dot(t, t);
  if (!(l2 > 1e-12)) {  // also false for NaN
    float s = N.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + N.z);  // |s + N.z| >= 1 since s has N.z's sign
    float b = N.x * N.y * a;
    t = vec3(1.0 + s * N.x * N.x * a, s * b, -s * N.x);
  } else {
    t *= inversesqrt(l2);
  }
  return mat3(t, cross(N, t), N);
}

vec3 mxc_to_local(mat3 frame, vec3 v) { return vec3(dot(v, frame[0]), dot(v, frame[1]), dot(v, frame[2])); }
vec3 mxc_to_world(mat3 frame, vec3 v) { return frame[0] * v.x + frame[1] * v.y + frame[2] * v.z; }

// PCG hash (O'Neill 2014, as used by Jarzynski & Olano 2020) for per-sample random numbers.
uint mxc_pcg(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
float mxc_uniform(inout uint seed) {
  seed = mxc_pcg(seed);
  return float(seed >> 8) * (1.0 / 16777216.0);  // 24 bits: in [0, 1)
}

// Cosine-weighted hemisphere direction (z up) and its pdf cos/pi.
vec3 mxc_sample_cosine(vec2 u) {
  float r = sqrt(u.x);
  float phi = 2.0 * MXC_PI * u.y;
  return vec3(r * cos(phi), r * sin(phi), mxc_safe_sqrt(1.0 - u.x));
}

// The angular falloff of a conical emitter (MaterialX conical_edf): 1 inside the half-angle
// `innerDeg`, fading smoothly to 0 at `outerDeg`; an outer angle not beyond the inner one
// means no fading (a hard edge), and smoothstep is never given equal or reversed edges.
float mxc_cone_falloff(float cosTheta, float innerDeg, float outerDeg) {
  float cosInner = cos(radians(innerDeg));
  float cosOuter = cos(radians(max(outerDeg, innerDeg)));
  if (cosOuter >= cosInner - 1e-6) return cosTheta >= cosInner ? 1.0 : 0.0;
  return smoothstep(cosOuter, cosInner, cosTheta);
}
