// Procedural and texture functions of the MaterialX standard library, written for mxc from the
// MaterialX 1.39 specification's node descriptions: gradient noise, fractal noise, cell and
// Worley noise, HSV conversion, rotations, normal mapping, image addressing.

// Integer hash of a lattice point (PCG, as mxc_pcg), to [0, 1).
float mxc_hash(ivec3 p) {
  uint h = mxc_pcg(uint(p.x) + mxc_pcg(uint(p.y) + mxc_pcg(uint(p.z))));
  return float(h >> 8) * (1.0 / 16777216.0);
}
vec3 mxc_hash3(ivec3 p) {
  return vec3(mxc_hash(p), mxc_hash(p + ivec3(1549, 0, 0)), mxc_hash(p + ivec3(0, 3571, 0)));
}

// Gradient (Perlin) noise in [-1, 1] approximately (Perlin 2002, "Improving Noise"): a
// pseudo-random unit gradient at each lattice point, blended with the quintic fade.
float mxc_gradient_noise(vec3 p, int channel) {
  ivec3 i = ivec3(floor(p));
  vec3 f = p - floor(p);
  vec3 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  float n[8];
  for (int k = 0; k < 8; ++k) {
    ivec3 o = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    vec3 g = mxc_hash3(i + o + ivec3(channel * 7919)) * 2.0 - 1.0;
    n[k] = dot(mxc_safe_normalize(g, vec3(1.0, 0.0, 0.0)), f - vec3(o));
  }
  float x0 = mix(mix(n[0], n[1], u.x), mix(n[2], n[3], u.x), u.y);
  float x1 = mix(mix(n[4], n[5], u.x), mix(n[6], n[7], u.x), u.y);
  return mix(x0, x1, u.z) * 1.7;  // scaled so the range is about [-1, 1]
}
float mxc_noise_float(vec3 p) { return mxc_gradient_noise(p, 0); }
vec3 mxc_noise_vec3(vec3 p) { return vec3(mxc_gradient_noise(p, 0), mxc_gradient_noise(p, 1), mxc_gradient_noise(p, 2)); }

// Fractal sum of octaves: amplitude times diminish, frequency times lacunarity per octave.
float mxc_fractal_float(vec3 p, int octaves, float lacunarity, float diminish) {
  float sum = 0.0;
  float amplitude = 1.0;
  for (int k = 0; k < clamp(octaves, 0, 16); ++k) {
    sum += amplitude * mxc_noise_float(p);
    amplitude *= diminish;
    p *= lacunarity;
  }
  return sum;
}
vec3 mxc_fractal_vec3(vec3 p, int octaves, float lacunarity, float diminish) {
  vec3 sum = vec3(0.0);
  float amplitude = 1.0;
  for (int k = 0; k < clamp(octaves, 0, 16); ++k) {
    sum += amplitude * mxc_noise_vec3(p);
    amplitude *= diminish;
    p *= lacunarity;
  }
  return sum;
}

// Cell noise: one random value in [0, 1) per unit cell.
float mxc_cellnoise(vec3 p) { return mxc_hash(ivec3(floor(p))); }

// Worley noise: distance to the nearest jittered feature point in the 27 neighbouring cells.
float mxc_worley(vec3 p, float jitter) {
  ivec3 cell = ivec3(floor(p));
  float best = 1e10;
  for (int k = 0; k < 27; ++k) {
    ivec3 o = ivec3(k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1);
    vec3 feature = vec3(cell + o) + 0.5 + (mxc_hash3(cell + o) - 0.5) * clamp(jitter, 0.0, 1.0);
    best = min(best, length(p - feature));
  }
  return best;
}

// Glitter flakes (MaterialX "flake2d", "flake3d") as a Boolean model of random sets (Chiu,
// Stoyan, Kendall and Mecke, "Stochastic Geometry and Its Applications", 3rd ed., ch. 3): each
// unit cell holds a flake with probability `probability`, a cube of side sqrt(3) centred in the
// cell and turned by a uniformly random rotation (Shoemake 1992, "Uniform Random Rotations",
// Graphics Gems III). The cube's inscribed ball (radius sqrt(3)/2) reaches every corner of its
// cell, so when every cell holds a flake every point is covered; its circumscribed ball (radius
// 3/2) stays within the 27 cells around a point, so those hold every flake that can cover it.
// Where flakes overlap, the one of highest priority (a random number per flake: the one lying
// on top) is seen. Returns (priority, rand, xi0, xi1) of that flake, priority in (0, 1], all
// zero where no flake is; xi0 and xi1 are in [0, 1) and sample its normal.
vec4 mxc_flake(vec3 p, float probability) {
  ivec3 cell = ivec3(floor(p));
  vec4 seen = vec4(0.0);
  for (int k = 0; k < 27; ++k) {
    ivec3 c = cell + ivec3(k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1);
    vec3 d = p - (vec3(c) + 0.5);
    if (dot(d, d) > 2.25) continue;  // beyond the circumscribed ball: this cell's flake cannot cover p
    if (mxc_hash(c + ivec3(0, 0, 7703)) >= probability) continue;  // the cell holds no flake
    float priority = 1.0 - mxc_hash(c + ivec3(0, 6271, 0));  // in (0, 1]: 0 is kept for "no flake"
    if (priority <= seen.x) continue;
    // The unit quaternion of Shoemake's method; u.x in [0, 1) keeps both square roots real.
    vec3 u = mxc_hash3(c + ivec3(4421, 0, 0));
    float a = sqrt(1.0 - u.x);
    float b = sqrt(u.x);
    vec4 q = vec4(a * sin(6.28318531 * u.y), a * cos(6.28318531 * u.y), b * sin(6.28318531 * u.z),
                  b * cos(6.28318531 * u.z));
    vec3 t = 2.0 * cross(q.xyz, d);
    vec3 r = d + q.w * t + cross(q.xyz, t);  // d turned by q
    if (max(abs(r.x), max(abs(r.y), abs(r.z))) > 0.8660254) continue;  // outside the cube
    seen = vec4(priority, mxc_hash3(c + ivec3(0, 0, 9157)));
  }
  return seen;
}

// HSV with hue in [0, 1) (Smith 1978).
vec3 mxc_rgb_to_hsv(vec3 c) {
  float maxc = max(c.r, max(c.g, c.b));
  float minc = min(c.r, min(c.g, c.b));
  float delta = maxc - minc;
  float h = 0.0;
  if (delta > 0.0) {  // guards the three divisions by delta
    if (maxc == c.r) h = (c.g - c.b) / delta;
    else if (maxc == c.g) h = 2.0 + (c.b - c.r) / delta;
    else h = 4.0 + (c.r - c.g) / delta;
    h = fract(h / 6.0);
  }
  return vec3(h, maxc > 0.0 ? delta / maxc : 0.0, maxc);
}
vec3 mxc_hsv_to_rgb(vec3 hsv) {
  vec3 k = clamp(abs(fract(hsv.x + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  return hsv.z * mix(vec3(1.0), k, hsv.y);
}

// Counter-clockwise rotation by degrees.
vec2 mxc_rotate2d(vec2 v, float degrees) {
  float a = radians(degrees);
  float s = sin(a), c = cos(a);
  return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}
// Rotation about an axis (Rodrigues' formula); a zero axis leaves v unchanged.
vec3 mxc_rotate3d(vec3 v, float degrees, vec3 axis) {
  vec3 k = mxc_safe_normalize(axis, vec3(0.0));
  if (k == vec3(0.0)) return v;
  float a = radians(degrees);
  return v * cos(a) + cross(k, v) * sin(a) + k * dot(k, v) * (1.0 - cos(a));
}

// A tangent-space normal map sample in [0, 1]^3 to a world normal (MaterialX "normalmap"):
// xy scaled, in the frame (T, B, N); a degenerate result falls back to N.
vec3 mxc_normalmap(vec3 sampleValue, vec2 scale, vec3 N, vec3 T, vec3 B) {
  vec3 v = sampleValue * 2.0 - 1.0;
  v.xy *= scale;
  return mxc_safe_normalize(T * v.x + B * v.y + N * v.z, N);
}

// MaterialX "heighttonormal": the tangent-space normal of the height field h(texcoord), its
// deflection `scale` times the gradient of h with respect to the texture coordinate, encoded in
// [0, 1] as a normal map is. The gradient comes from the screen derivatives by the chain rule
// (the use of screen derivatives for bump mapping: Mikkelsen 2010, "Bump Mapping Unparametrized
// Surfaces on the GPU"): (dh/dx, dh/dy) = M (dh/du, dh/dv) with M = [du/dx dv/dx; du/dy dv/dy],
// so any graph computing h works, not only a texture. Compute stages have no derivatives, and a
// texture coordinate that does not change across the pixel (det M = 0) has no gradient: there
// the normal is flat.
vec3 mxc_heighttonormal(float h, float scale, vec2 uv) {
#ifdef MXC_STAGE_RASTER
  vec2 dhdxy = vec2(dFdx(h), dFdy(h));
  vec2 duvdx = dFdx(uv);
  vec2 duvdy = dFdy(uv);
  float det = duvdx.x * duvdy.y - duvdx.y * duvdy.x;
  if (abs(det) > 1e-20) {
    // M^-1 (dh/dx, dh/dy); the division is guarded above, and the gradient clamped so that the
    // vector below stays finite (a slope of 1e6 is horizontal to float precision already).
    vec2 gradient = vec2(duvdy.y * dhdxy.x - duvdx.y * dhdxy.y, duvdx.x * dhdxy.y - duvdy.x * dhdxy.x) / det;
    gradient = clamp(gradient, vec2(-1e6), vec2(1e6));
    // Its z is 1, so the length is at least 1: the normalize is safe.
    return normalize(vec3(-scale * gradient, 1.0)) * 0.5 + 0.5;
  }
#endif
  return vec3(0.5, 0.5, 1.0);
}

// MaterialX address modes along one axis (MXC_ADDRESS_*): constant (outside: use the default),
// clamp, periodic, mirror. Returns false when the coordinate is outside in constant mode.
bool mxc_address(inout float x, int mode) {
  if (mode == MXC_ADDRESS_CONSTANT) return x >= 0.0 && x <= 1.0;
  if (mode == MXC_ADDRESS_CLAMP) x = clamp(x, 0.0, 1.0);
  else if (mode == MXC_ADDRESS_PERIODIC) x = fract(x);
  else x = 1.0 - abs(mod(x, 2.0) - 1.0);
  return true;
}
// The width of a pixel this invocation's sample stands for: 1 for one sample per pixel; a
// renderer that averages N jittered frames sets 1 / sqrt(N) (mxc_raster.frag), so the texture is
// filtered over the sample's share of the pixel and the frames' jitter integrates the rest.
float mxc_texture_footprint = 1.0;
#define MXC_HAS_TEXTURE_FOOTPRINT

// filtertype: MXC_FILTER_LINEAR or MXC_FILTER_CLOSEST (MaterialX "filtertype").
vec4 mxc_sample_image(MXC_SAMPLER2D_PARAMETER(image), vec2 uv, vec4 fallback, int uaddress, int vaddress, int filtertype, bool missing) {
#ifdef MXC_STAGE_RASTER
  // The footprint first, before any branch: screen derivatives are undefined in control flow
  // that differs between the pixels of a quad (GLSL 4.50 section 8.14), and WGSL rejects them
  // there (its uniformity analysis). The footprint is the derivative of the coordinate before it
  // is wrapped: fract() and mirroring jump by a whole tile at a seam, which would read as a huge
  // footprint there. (v is flipped below, hence the sign.)
  vec2 dx = dFdx(uv) * vec2(mxc_texture_footprint, -mxc_texture_footprint);
  vec2 dy = dFdy(uv) * vec2(mxc_texture_footprint, -mxc_texture_footprint);
#endif
  vec2 st = uv;
  if (missing) return fallback;
  if (!mxc_address(st.x, uaddress) || !mxc_address(st.y, vaddress)) return fallback;
  // MaterialX texture coordinates have v up; images are stored top row first.
  st.y = 1.0 - st.y;
  if (filtertype == MXC_FILTER_CLOSEST) {
    // The centre of the texel st falls in, read at full resolution: the nearest texel.
    vec2 size = vec2(textureSize(MXC_SAMPLER2D(image), 0));
    return textureLod(MXC_SAMPLER2D(image), (min(floor(st * size), size - 1.0) + 0.5) / size, 0.0);
  }
#ifdef MXC_STAGE_RASTER
  // Trilinear through the mip chain, over the footprint above.
  return textureGrad(MXC_SAMPLER2D(image), st, dx, dy);
#else
  // Compute stages have no screen footprint: the full-resolution level.
  return textureLod(MXC_SAMPLER2D(image), st, 0.0);
#endif
}
