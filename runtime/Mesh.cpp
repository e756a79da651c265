#include "runtime/Mesh.h"

#include <cmath>
#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace mxc::rt {

namespace {

constexpr float kPi = 3.14159265358979f;

}  // namespace

Mesh makeSphere(uint32_t segments, uint32_t rings) {
  Mesh mesh;
  for (uint32_t r = 0; r <= rings; ++r) {
    const float v = float(r) / float(rings);
    const float theta = kPi * (1.0f - v);  // from the north pole (v = 1) down
    for (uint32_t s = 0; s <= segments; ++s) {
      const float u = float(s) / float(segments);
      const float phi = 2.0f * kPi * u;
      const glm::vec3 p(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      // The tangent follows increasing u (d/dphi), defined at the poles by the same formula.
      const glm::vec3 t(std::cos(phi), 0.0f, -std::sin(phi));
      mesh.vertices.push_back({p, p, glm::vec4(t, 1.0f), glm::vec2(u, v)});
    }
  }
  const uint32_t stride = segments + 1;
  for (uint32_t r = 0; r < rings; ++r) {
    for (uint32_t s = 0; s < segments; ++s) {
      const uint32_t a = r * stride + s, b = a + 1, c = a + stride, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  }
  return mesh;
}

Mesh makePlane() {
  Mesh mesh;
  const glm::vec3 n(0, 1, 0);
  const glm::vec4 t(1, 0, 0, 1);
  mesh.vertices = {{{-1, 0, 1}, n, t, {0, 0}}, {{1, 0, 1}, n, t, {1, 0}}, {{1, 0, -1}, n, t, {1, 1}}, {{-1, 0, -1}, n, t, {0, 1}}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

MeshBounds meshBounds(const Mesh& mesh) {
  MeshBounds bounds;
  if (mesh.vertices.empty()) return bounds;
  glm::vec3 lo = mesh.vertices[0].position, hi = lo;
  for (const Vertex& v : mesh.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  bounds.center = 0.5f * (lo + hi);
  for (const Vertex& v : mesh.vertices) bounds.radius = std::max(bounds.radius, glm::length(v.position - bounds.center));
  return bounds;
}

}  // namespace mxc::rt
