#include "runtime/Tangents.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace mxc::rt {

namespace {

/// A unit vector perpendicular to the unit vector n.
glm::vec3 perpendicular(glm::vec3 n) {
  const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(a, n));  // |n.x| < 0.9 or |n.y| >= 0.44: a is not parallel to n
}

/// v without its component along the unit vector n, normalised; false when nothing is left.
bool projectToPlane(glm::vec3 v, glm::vec3 n, glm::vec3& out) {
  const glm::vec3 p = v - n * glm::dot(n, v);
  const float length = glm::length(p);
  if (!(length > 1e-20f)) return false;  // also false for NaN
  out = p / length;                      // length > 0
  return true;
}

/// The key MikkTSpace welds vertices by: position, normal and texture coordinate, bit for bit
/// (with -0 read as +0).
struct WeldKey {
  float values[8];
  bool operator==(const WeldKey& o) const { return std::memcmp(values, o.values, sizeof values) == 0; }
};

struct WeldHash {
  size_t operator()(const WeldKey& k) const {
    size_t h = 1469598103934665603ull;
    uint32_t bits[8];
    std::memcpy(bits, k.values, sizeof bits);
    for (uint32_t b : bits) h = (h ^ b) * 1099511628211ull;
    return h;
  }
};

WeldKey weldKey(const Vertex& v) {
  WeldKey k{{v.position.x, v.position.y, v.position.z, v.normal.x, v.normal.y, v.normal.z, v.uv.x, v.uv.y}};
  for (float& x : k.values) x += 0.0f;  // -0 + 0 = +0
  return k;
}

/// One triangle's mapping: the direction of increasing u and whether the mapping preserves
/// orientation (Mikkelsen 2008, 4.2: the sign of the texture-space area).
struct TriangleFrame {
  glm::vec3 tangent{0.0f};
  bool preservesOrientation = true;
  bool usable = false;  ///< a non-zero texture area and a non-zero tangent
};

TriangleFrame triangleFrame(const Vertex& a, const Vertex& b, const Vertex& c) {
  // With d1 = b - a, d2 = c - a in space and s1, s2 in texture space, the tangent dP/du solves
  // [d1 d2] = [T B] [s1 s2]: T = (s2.y d1 - s1.y d2) / area2 (Lengyel 2001).
  const glm::vec3 d1 = b.position - a.position, d2 = c.position - a.position;
  const glm::vec2 s1 = b.uv - a.uv, s2 = c.uv - a.uv;
  const float area2 = s1.x * s2.y - s1.y * s2.x;
  TriangleFrame frame;
  frame.preservesOrientation = area2 > 0.0f;
  const glm::vec3 t = (s2.y * d1 - s1.y * d2) * (area2 < 0.0f ? -1.0f : 1.0f);  // the sign of 1/area2
  const float length = glm::length(t);
  if (area2 != 0.0f && length > 1e-20f && std::isfinite(length)) {
    frame.tangent = t / length;  // length > 0
    frame.usable = true;
  }
  return frame;
}

/// The angle at corner `at` of a triangle, between the edges to `p1` and `p2` projected into the
/// plane of the unit normal n (MikkTSpace weights by it); 0 for a degenerate corner.
float cornerAngle(glm::vec3 at, glm::vec3 p1, glm::vec3 p2, glm::vec3 n) {
  glm::vec3 e1, e2;
  if (!projectToPlane(p1 - at, n, e1) || !projectToPlane(p2 - at, n, e2)) return 0.0f;
  return std::acos(std::clamp(glm::dot(e1, e2), -1.0f, 1.0f));  // clamped: rounding can leave [-1, 1]
}

}  // namespace

void generateTangents(Mesh& mesh) {
  const size_t vertexCount = mesh.vertices.size();
  // 1. Welded vertex ids.
  std::vector<uint32_t> weld(vertexCount);
  {
    std::unordered_map<WeldKey, uint32_t, WeldHash> ids;
    ids.reserve(vertexCount);
    for (size_t v = 0; v < vertexCount; ++v) {
      weld[v] = ids.emplace(weldKey(mesh.vertices[v]), static_cast<uint32_t>(ids.size())).first->second;
    }
  }
  // 2. Angle-weighted sums per group: (welded vertex, orientation).
  const size_t cornerCount = mesh.indices.size() / 3 * 3;
  std::vector<glm::vec3> sums(size_t{2} * vertexCount, glm::vec3(0.0f));  // index: 2 * weld + orientation
  std::vector<uint8_t> reached(size_t{2} * vertexCount, 0);
  std::vector<TriangleFrame> frames(cornerCount / 3);
  for (size_t t = 0; t < frames.size(); ++t) {
    const uint32_t* corner = &mesh.indices[3 * t];
    const Vertex* v[3] = {&mesh.vertices[corner[0]], &mesh.vertices[corner[1]], &mesh.vertices[corner[2]]};
    frames[t] = triangleFrame(*v[0], *v[1], *v[2]);
    if (!frames[t].usable) continue;
    for (int k = 0; k < 3; ++k) {
      glm::vec3 projected;
      if (!projectToPlane(frames[t].tangent, v[k]->normal, projected)) continue;
      const float angle = cornerAngle(v[k]->position, v[(k + 1) % 3]->position, v[(k + 2) % 3]->position, v[k]->normal);
      const size_t group = size_t{2} * weld[corner[k]] + (frames[t].preservesOrientation ? 1 : 0);
      sums[group] += angle * projected;
      reached[group] = 1;
    }
  }
  // 3. Each corner's tangent: its group's normalised sum, or another group of the vertex.
  auto groupTangent = [&](size_t group, glm::vec3 n, glm::vec3& out) {
    return reached[group] && projectToPlane(sums[group], n, out);
  };
  std::vector<glm::vec4> cornerTangents(cornerCount);
  for (size_t t = 0; t < frames.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t index = mesh.indices[3 * t + k];
      const glm::vec3 n = mesh.vertices[index].normal;
      const size_t own = size_t{2} * weld[index] + (frames[t].preservesOrientation ? 1 : 0);
      glm::vec3 tangent;
      float w = frames[t].preservesOrientation ? 1.0f : -1.0f;
      if (!(frames[t].usable && groupTangent(own, n, tangent))) {
        // No mapping of its own here: the orientation-preserving group first, as MikkTSpace
        // joins such triangles to a neighbouring group.
        const size_t preserving = size_t{2} * weld[index] + 1;
        if (groupTangent(preserving, n, tangent)) {
          w = 1.0f;
        } else if (groupTangent(preserving ^ 1, n, tangent)) {
          w = -1.0f;
        } else {
          tangent = perpendicular(n);
          w = 1.0f;
        }
      }
      cornerTangents[3 * t + k] = glm::vec4(tangent, w);
    }
  }
  // 4. One vertex per (vertex, tangent): the first tangent a vertex meets keeps its slot.
  std::vector<std::vector<std::pair<glm::vec4, uint32_t>>> variants(vertexCount);
  for (size_t c = 0; c < cornerCount; ++c) {
    const uint32_t index = mesh.indices[c];
    auto& list = variants[index];
    auto found = std::find_if(list.begin(), list.end(), [&](const auto& e) { return e.first == cornerTangents[c]; });
    if (found != list.end()) {
      mesh.indices[c] = found->second;
      continue;
    }
    uint32_t slot = index;
    if (!list.empty()) {
      slot = static_cast<uint32_t>(mesh.vertices.size());
      const Vertex copy = mesh.vertices[index];  // push_back may reallocate
      mesh.vertices.push_back(copy);
    }
    mesh.vertices[slot].tangent = cornerTangents[c];
    list.emplace_back(cornerTangents[c], slot);
    mesh.indices[c] = slot;
  }
  for (size_t v = 0; v < vertexCount; ++v) {
    if (variants[v].empty()) mesh.vertices[v].tangent = glm::vec4(perpendicular(mesh.vertices[v].normal), 1.0f);
  }
}

}  // namespace mxc::rt
