#include "cli/MeshArgument.h"

#include <fmt/format.h>

#include "runtime/MeshFile.h"

namespace mxc::cli {

std::variant<MeshChoice, std::string> chooseMesh(const std::string& argument,
                                                 const std::vector<std::filesystem::path>& searchPaths) {
  MeshChoice choice;
  if (argument == "sphere") {
    choice.mesh = rt::makeSphere();
    return choice;
  }
  if (argument == "plane") {
    choice.mesh = rt::makePlane();
    choice.viewDirection = glm::vec3(0.0f, 1.0f, 1.0f);
    return choice;
  }
  const std::filesystem::path asPath(argument);
  if (asPath.has_extension() || argument.find('/') != std::string::npos) {
    choice.file = asPath;
  } else {
    // A name: resources/Geometry/<name>.glb, then .obj, in each search path.
    std::vector<std::string> looked;
    for (const std::filesystem::path& folder : searchPaths) {
      for (const char* extension : {".glb", ".obj"}) {
        const std::filesystem::path candidate = folder / "resources" / "Geometry" / (argument + extension);
        std::error_code error;
        if (std::filesystem::is_regular_file(candidate, error)) {
          choice.file = candidate;
          break;
        }
        looked.push_back(candidate.string());
      }
      if (!choice.file.empty()) break;
    }
    if (choice.file.empty()) {
      if (looked.empty()) {
        return fmt::format("no mesh file named '{}': give a file (.glb, .gltf, .obj), sphere or plane, or a "
                           "--search-path (or MATERIALX_SEARCH_PATH) holding resources/Geometry/{}.glb",
                           argument, argument);
      }
      return fmt::format("no mesh named '{}' on the search path (looked for {})", argument, fmt::join(looked, ", "));
    }
  }
  auto loaded = rt::loadMesh(choice.file);
  if (auto* why = std::get_if<std::string>(&loaded)) return *why;
  choice.mesh = std::move(std::get<rt::Mesh>(loaded));
  return choice;
}

}  // namespace mxc::cli
