#pragma once
/// \file
/// Triangle meshes for the renderer: a UV sphere, a plane, and Wavefront OBJ files, each with
/// normals, tangents (along increasing u) and texture coordinates.

#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace mxc::rt {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec4 tangent;  ///< xyz: unit tangent, w: +1 or -1, the handedness of the bitangent
  glm::vec2 uv;
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  ///< triangles, counter-clockwise seen from the front
};

/// A unit sphere at the origin, y up, u around the y axis and v from the south pole (0) to the
/// north pole (1), as MaterialX's test spheres.
Mesh makeSphere(uint32_t segments = 128, uint32_t rings = 64);
/// A square of side 2 in the xz plane facing +y, uv [0, 1]^2.
Mesh makePlane();
/// Reads an OBJ file (v, vt, vn, f with polygons as fans; other statements ignored). Missing
/// normals are computed from the faces; tangents from the texture coordinates (or any
/// perpendicular when there are none). Returns an error "path:line: message" instead.
std::variant<Mesh, std::string> loadObj(const std::filesystem::path& path);

}  // namespace mxc::rt
