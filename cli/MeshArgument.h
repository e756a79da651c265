#pragma once
/// \file
/// What `--mesh` names: a mesh made here (sphere, plane), a mesh of MaterialX's resources found
/// on the search path by name (shaderball, teapot, cube, ...: resources/Geometry/NAME.glb or
/// .obj, as MaterialX's viewer resolves them), or a mesh file (.glb, .gltf, .obj).

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "runtime/Mesh.h"

namespace mxc::cli {

struct MeshChoice {
  rt::Mesh mesh;
  std::filesystem::path file;  ///< the file read; empty for a mesh made here
  /// Where the default camera looks from (from the mesh towards the eye): the front (+z), or
  /// from above at 45 degrees for the plane.
  glm::vec3 viewDirection{0.0f, 0.0f, 1.0f};
};

/// The mesh `argument` names, or why there is none (a name found nowhere lists where it looked).
std::variant<MeshChoice, std::string> chooseMesh(const std::string& argument,
                                                 const std::vector<std::filesystem::path>& searchPaths);

}  // namespace mxc::cli
