// Vertex stage of the sphere renderer: object-space mesh attributes to world space. The depth
// pre-pass and the shading pass run this same module on the same data, and the clip position
// is `precise`, so that both passes get the same depth (runtime/Renderer.cpp shades with an
// EQUAL depth test).

#include "generated/mxc_vertex_inputs.glsl"

layout(location = 0) out vec3 vPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec4 vTangent;
layout(location = 3) out vec2 vUv;
layout(location = 4) out vec3 vObjectPosition;
layout(location = 5) out vec3 vObjectNormal;
layout(location = 6) out vec3 vObjectTangent;

void main() {
  vec4 world = mxc_view.objectToWorld * vec4(inPosition, 1.0);
  vPosition = world.xyz;
  vNormal = mat3(mxc_view.normalToWorld) * inNormal;
  vTangent = vec4(mat3(mxc_view.objectToWorld) * inTangent.xyz, inTangent.w);
  vUv = inUv;
  vObjectPosition = inPosition;
  vObjectNormal = inNormal;
  vObjectTangent = inTangent.xyz;
  precise vec4 clip = mxc_view.worldToClip * world;
  clip.xy += mxc_view.jitter.xy * clip.w;  // sub-pixel jitter: antialiasing over frames
  gl_Position = clip;
}
