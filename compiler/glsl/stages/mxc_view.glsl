// The camera, lights and environment of the raster renderer (binding 1, filled by
// runtime/Renderer.cpp), shared by its vertex and fragment stages.

const int MXC_MAX_LIGHTS = 8;

layout(set = 0, binding = 1, std140) uniform MxcView {
  mat4 objectToWorld;
  mat4 normalToWorld;  // inverse transpose of objectToWorld
  mat4 worldToClip;
  vec4 eye;            // xyz: camera position (world)
  vec4 jitter;         // xy: this frame's sub-pixel offset, in normalised device units
  vec4 lightVector[MXC_MAX_LIGHTS];    // w = 0: xyz points towards a directional light; w = 1: a point light's position
  vec4 lightRadiance[MXC_MAX_LIGHTS];  // rgb: irradiance at normal incidence (directional) or intensity in W/sr (point)
  ivec4 counts;        // x: lights, y: environment (0 none, 1 white furnace, 2 sky), z: frame index, w: samples per frame
  vec4 environment;    // x: environment intensity, y: emission scale (radiance per unit of emission_luminance)
} mxc_view;
