// The renderer's environment image: an equirectangular (latitude-longitude) radiance map, its
// lookup, and its importance sampling. The density is piecewise constant over a grid of cells
// equal in longitude and latitude, each cell's density proportional to its mean luminance; a
// cell is drawn from an alias table (Walker 1977, built by Vose's 1991 method in
// runtime/EnvironmentDistribution.cpp) and a direction uniformly in solid angle inside it
// (uniform in longitude and in cos(theta)), so the density per steradian is the cell's own
// value with no 1 / sin(theta) factor to blow up at the poles.
//
// Directions are in the map's space, y up; the renderer rotates world directions into it.
// Mapping (the same in runtime/EnvironmentDistribution.cpp, whose test checks both agree):
//   u = 0.5 + atan(x, -z) / (2 pi), v = acos(y) / pi,
// so the image's centre lies along -z (behind the object, seen from the default camera),
// u grows towards +x, and the top row looks straight up.

#include "generated/mxc_environment_block.glsl"

vec2 mxc_env_uv(vec3 d) {
  // atan(0, 0) is undefined in GLSL: at the poles every longitude is the same point.
  float u = abs(d.x) + abs(d.z) > 1e-12 ? 0.5 + atan(d.x, -d.z) * (0.5 * MXC_INV_PI) : 0.5;
  // theta = atan(|d.xz|, d.y) rather than acos(d.y): lavapipe's acos is off by about 5e-5 rad,
  // which put 0.3% of the sampler's directions in the neighbouring row of cells.
  float v = atan(length(d.xz), d.y) * MXC_INV_PI;  // atan(0, 0) cannot occur: |d| = 1
  return vec2(u, v);
}

// Radiance arriving from map-space direction d (unit). The sampler repeats across (the seam at
// u = 0 and 1 is continuous) and clamps down.
vec3 mxc_env_lookup(vec3 d) {
  return textureLod(MXC_SAMPLER2D(mxc_env_radiance), mxc_env_uv(d), 0.0).rgb;
}

// The index of the cell holding map-space direction d.
uint mxc_env_cell(vec3 d) {
  vec2 uv = mxc_env_uv(d);
  uvec2 size = max(mxc_env_size.xy, uvec2(1u));
  uint i = min(uint(max(uv.x, 0.0) * float(size.x)), size.x - 1u);
  uint j = min(uint(max(uv.y, 0.0) * float(size.y)), size.y - 1u);
  return j * size.x + i;
}

// The density per steradian with which mxc_env_sample draws d (0 for a black image).
float mxc_env_pdf(vec3 d) {
  return mxc_env_cells[mxc_env_cell(d)].z;
}

// A map-space direction drawn with density `pdf` per steradian (0: nothing to sample, the
// image is black); u uniform in [0, 1)^4.
vec3 mxc_env_sample(vec4 u, out float pdf) {
  uvec2 size = max(mxc_env_size.xy, uvec2(1u));
  uint n = size.x * size.y;
  // The alias method: a cell uniformly, kept with its probability, else its alias.
  uint k = min(uint(u.x * float(n)), n - 1u);
  vec4 cell = mxc_env_cells[k];
  if (u.y >= cell.x) k = min(floatBitsToUint(cell.y), n - 1u);  // min: a bad alias stays in the buffer
  pdf = mxc_env_cells[k].z;
  uint i = k % size.x;  // size.x >= 1
  uint j = k / size.x;
  // Uniform in solid angle inside the cell: longitude uniform, cos(theta) uniform between
  // the cell's rows.
  float phi = 2.0 * MXC_PI * ((float(i) + u.z) / float(size.x) - 0.5);  // atan(x, -z), from u
  float y0 = cos(MXC_PI * float(j) / float(size.y));
  float y1 = cos(MXC_PI * float(j + 1u) / float(size.y));
  float y = mix(y0, y1, u.w);
  float r = mxc_safe_sqrt(1.0 - y * y);
  return vec3(r * sin(phi), y, -r * cos(phi));
}

// World to map space and back: the image turned by `angle` radians about +y (counter-clockwise
// seen from above) shows map direction m at world direction R(angle) m.
vec3 mxc_env_to_map(vec3 w, float angle) {
  float c = cos(angle), s = sin(angle);
  return vec3(c * w.x - s * w.z, w.y, s * w.x + c * w.z);
}
vec3 mxc_env_to_world(vec3 m, float angle) {
  float c = cos(angle), s = sin(angle);
  return vec3(c * m.x + s * m.z, m.y, -s * m.x + c * m.z);
}
