#include "runtime/Mesh.h"

#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "compiler/common/InputFile.h"

namespace mxc::rt {

namespace {

constexpr float kPi = 3.14159265358979f;

/// A unit vector perpendicular to n (n is a unit vector).
glm::vec3 perpendicular(glm::vec3 n) {
  glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(a, n));  // a is not parallel to n: the cross product is not zero
}

/// Per-vertex tangents from texture coordinates (Lengyel 2001, "Computing Tangent Space Basis
/// Vectors for an Arbitrary Mesh"), orthogonalised against the normal.
void computeTangents(Mesh& mesh) {
  std::vector<glm::vec3> tan(mesh.vertices.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> bitan(mesh.vertices.size(), glm::vec3(0.0f));
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t ia = mesh.indices[i], ib = mesh.indices[i + 1], ic = mesh.indices[i + 2];
    const Vertex &a = mesh.vertices[ia], &b = mesh.vertices[ib], &c = mesh.vertices[ic];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-12f) continue;  // degenerate texture mapping: no tangent from this face
    const float r = 1.0f / det;
    const glm::vec3 t = (e1 * d2.y - e2 * d1.y) * r;
    const glm::vec3 bt = (e2 * d1.x - e1 * d2.x) * r;
    for (uint32_t v : {ia, ib, ic}) {
      tan[v] += t;
      bitan[v] += bt;
    }
  }
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    Vertex& vx = mesh.vertices[v];
    glm::vec3 t = tan[v] - vx.normal * glm::dot(vx.normal, tan[v]);
    const float len = glm::length(t);
    t = len > 1e-8f ? t / len : perpendicular(vx.normal);  // len checked
    const float w = glm::dot(glm::cross(vx.normal, t), bitan[v]) < 0.0f ? -1.0f : 1.0f;
    vx.tangent = glm::vec4(t, w);
  }
}

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

std::variant<Mesh, std::string> loadObj(const std::filesystem::path& path) {
  // A regular file of bounded size: `--mesh /dev/zero` would read forever and a FIFO block.
  constexpr size_t kMaxMeshBytes = size_t{2} << 30;
  auto bytes = readInputFile(path, kMaxMeshBytes);
  if (auto* why = std::get_if<1>(&bytes)) return fmt::format("cannot read the mesh '{}': {}", path.string(), *why);
  std::istringstream in(std::move(std::get<0>(bytes)));
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::vec2> uvs;
  Mesh mesh;
  bool computeNormals = false;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    std::istringstream s(line);
    std::string tag;
    if (!(s >> tag) || tag[0] == '#') continue;
    auto bad = [&](const std::string& what) { return fmt::format("{}:{}: {}", path.string(), lineNo, what); };
    if (tag == "v" || tag == "vn") {
      glm::vec3 p;
      if (!(s >> p.x >> p.y >> p.z) || !std::isfinite(p.x + p.y + p.z)) return bad("expected three numbers");
      (tag == "v" ? positions : normals).push_back(p);
    } else if (tag == "vt") {
      glm::vec2 t;
      if (!(s >> t.x >> t.y) || !std::isfinite(t.x + t.y)) return bad("expected two numbers");
      uvs.push_back(t);
    } else if (tag == "f") {
      std::vector<uint32_t> face;
      std::string corner;
      while (s >> corner) {
        int idx[3] = {0, 0, 0};
        size_t part = 0, start = 0;
        for (; part < 3 && start <= corner.size(); ++part) {
          const size_t slash = std::min(corner.find('/', start), corner.size());
          const std::string field = corner.substr(start, slash - start);
          if (!field.empty()) {
            try {
              idx[part] = std::stoi(field);
            } catch (const std::exception&) {
              return bad(fmt::format("bad face index '{}'", corner));
            }
          }
          start = slash + 1;
        }
        auto resolve = [](int i, size_t n) -> long { return i > 0 ? i - 1 : i < 0 ? long(n) + i : -1; };
        const long p = resolve(idx[0], positions.size());
        const long t = resolve(idx[1], uvs.size());
        const long nn = resolve(idx[2], normals.size());
        if (p < 0 || p >= long(positions.size()) || t >= long(uvs.size()) || nn >= long(normals.size()) ||
            (idx[1] != 0 && t < 0) || (idx[2] != 0 && nn < 0)) {
          return bad(fmt::format("face index out of range in '{}'", corner));
        }
        Vertex v{positions[p], nn >= 0 ? normals[nn] : glm::vec3(0.0f), glm::vec4(0.0f), t >= 0 ? uvs[t] : glm::vec2(0.0f)};
        if (nn < 0) computeNormals = true;
        face.push_back(static_cast<uint32_t>(mesh.vertices.size()));
        mesh.vertices.push_back(v);
      }
      if (face.size() < 3) return bad("a face needs at least three corners");
      for (size_t k = 1; k + 1 < face.size(); ++k) mesh.indices.insert(mesh.indices.end(), {face[0], face[k], face[k + 1]});
    }
  }
  if (mesh.indices.empty()) return fmt::format("{}: the mesh has no faces (f lines)", path.string());
  if (computeNormals) {
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      Vertex* v[3] = {&mesh.vertices[mesh.indices[i]], &mesh.vertices[mesh.indices[i + 1]], &mesh.vertices[mesh.indices[i + 2]]};
      const glm::vec3 n = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
      for (Vertex* x : v) {
        if (x->normal == glm::vec3(0.0f)) x->normal = n;
      }
    }
  }
  for (Vertex& v : mesh.vertices) {
    const float len = glm::length(v.normal);
    v.normal = len > 1e-12f ? v.normal / len : glm::vec3(0, 1, 0);  // a degenerate face: any normal
  }
  computeTangents(mesh);
  return mesh;
}

}  // namespace mxc::rt
