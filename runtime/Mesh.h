#pragma once
/// \file
/// Triangle meshes for the renderer, each with normals, tangents (along increasing u) and
/// texture coordinates: a UV sphere and a plane made here; files are read by runtime/MeshFile.h.

#include <cstdint>
#include <string>
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

/// A named piece of a mesh: a range of its triangles (a glTF node, an OBJ object or group), what
/// a MaterialX look's `geom` names (`Preview_Mesh` of the shader ball).
struct MeshPart {
  std::string name;
  uint32_t firstIndex = 0;  ///< into Mesh::indices, a multiple of 3
  uint32_t indexCount = 0;
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  ///< triangles, counter-clockwise seen from the front
  /// The pieces in file order, covering `indices` without overlap (unnamed ones get "node<N>"
  /// or "shape<N>"); empty for the sphere and the plane.
  std::vector<MeshPart> parts;
};

/// A unit sphere at the origin, y up, u around the y axis and v from the south pole (0) to the
/// north pole (1), as MaterialX's test spheres.
Mesh makeSphere(uint32_t segments = 128, uint32_t rings = 64);
/// A square of side 2 in the xz plane facing +y, uv [0, 1]^2.
Mesh makePlane();
/// The sphere about a mesh that framing fits: centred on its bounding box, through its
/// farthest vertex (tighter than the box's half diagonal: exactly the unit sphere for
/// makeSphere()).
struct MeshBounds {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
};
MeshBounds meshBounds(const Mesh& mesh);

}  // namespace mxc::rt
