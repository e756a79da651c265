#pragma once
/// \file
/// Scene files: JSON, version 1 (`"mxc_scene": 1`), described by docs/scene.schema.json and
/// docs/scenes.md. A scene names its documents, objects (a mesh under a transform, with a
/// material by name or through a document's look), lights, environment, camera and render
/// settings. Reading checks every field and refuses the file at the first problem, naming the
/// file and the field (`scene.json: objects[1].scale: expected a number > 0 or three of them`);
/// unknown fields are refused too, so that a misspelt one is not silently ignored.

#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "compiler/common/Accuracy.h"
#include "runtime/Camera.h"
#include "runtime/Renderer.h"

namespace mxc::cli {

inline constexpr int kSceneVersion = 1;

struct SceneObjectSpec {
  std::string name;
  std::string mesh = "sphere";  ///< as `--mesh` (cli/MeshArgument.h), files relative to the scene
  std::string material;         ///< empty: from the scene's look
  glm::mat4 objectToWorld{1.0f};  ///< translate * rotate (x, then y, then z) * scale
};

struct SceneEnvironment {
  rt::Environment kind = rt::Environment::Sky;
  std::filesystem::path image;  ///< for Environment::Map, relative paths resolved against the scene
  float intensity = 1.0f;
  float rotationDegrees = 0.0f;
};

struct Scene {
  std::filesystem::path file;  ///< empty for a scene made from the command line (`--look`)
  std::vector<std::filesystem::path> documents;   ///< resolved against the scene's folder
  std::vector<std::filesystem::path> searchPaths;  ///< idem
  std::string look;                                ///< a look of the documents, or empty
  std::vector<SceneObjectSpec> objects;
  std::vector<rt::Light> lights;
  SceneEnvironment environment;
  std::optional<rt::Camera> camera;  ///< none: framed to fit every object
  /// Where the framing camera looks from (from the objects towards the eye): the front and a
  /// little above, so that a floor is seen rather than its edge.
  glm::vec3 viewDirection{0.0f, 0.35f, 1.0f};
  uint32_t width = 512, height = 512;
  uint32_t spp = 64;
  float exposure = 0.0f;
  std::string toneMapping = "aces";
  /// The accuracy tier of every material's shader, when the scene states one (else the
  /// command's --accuracy).
  std::optional<Accuracy> accuracy;
  std::optional<glm::vec3> background;
};

/// Whether `path` names a scene file rather than a document (its extension is .json).
bool isSceneFile(const std::filesystem::path& path);

/// Reads and checks a scene file, or returns why it cannot be used ("file: field: problem";
/// JSON syntax errors as "file:line:column: ...").
std::variant<Scene, std::string> readScene(const std::filesystem::path& path);
/// The same for the scene's text, read from `path` (which names it in messages and is the
/// folder its relative files are found in): the fuzz target's entry point.
std::variant<Scene, std::string> readSceneText(const std::filesystem::path& path, const std::string& text);

}  // namespace mxc::cli
