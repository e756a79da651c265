#pragma once
/// \file
/// Reading meshes from files: glTF 2.0 (`.glb`, `.gltf`, through tinygltf) and Wavefront OBJ
/// (`.obj`, through tinyobjloader), flattened into one triangle mesh in the conventions of
/// runtime/Mesh.h (texture v up, as MaterialX's: glTF's v is flipped).
///
/// - glTF: every primitive of the default scene's node hierarchy (or of every root node when
///   there is no scene), with its node's world transform applied (glTF 2.0 spec, 3.5.2); a
///   transform with a negative determinant reverses the winding (3.7.1) and the bitangent's
///   handedness. Triangle lists, strips and fans; points and lines are skipped. Normals, the
///   first texture coordinate set and tangents come from the file; missing normals are flat
///   (3.7.2.1), missing tangents MikkTSpace-compatible (runtime/Tangents.h). Each node with a
///   mesh is a part (Mesh::parts) named by the node, else its mesh. Images are not read: a
///   material's textures come from its document.
/// - OBJ: v, vt, vn and polygonal faces (triangulated as fans); missing normals are smooth
///   (area-weighted over the faces sharing a position), tangents MikkTSpace-compatible. Each
///   object or group (tinyobjloader's shapes) is a part.
///
/// Files are read through readInputFile (bounded size, no FIFOs or devices), buffers a .gltf
/// names included. Every index and accessor range is checked; a mesh with no triangle, or with
/// NaN or Inf anywhere, is refused.

#include <filesystem>
#include <string>
#include <variant>

#include "runtime/Mesh.h"

namespace mxc::rt {

/// Reads `path` by its extension (.glb, .gltf, .obj, any case), or returns why it cannot,
/// naming the file ("path: message").
std::variant<Mesh, std::string> loadMesh(const std::filesystem::path& path);
/// The same for the file's bytes, read from `path` (whose extension gives the format and whose
/// folder a glTF's relative buffers are found in): the fuzz target's entry point.
std::variant<Mesh, std::string> loadMeshBytes(const std::filesystem::path& path, const std::string& bytes);

}  // namespace mxc::rt
