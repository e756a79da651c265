#include "cli/Scene.h"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <set>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "compiler/common/InputFile.h"
#include "compiler/glsl/Contract.h"
#include "runtime/ToneMapping.h"

namespace mxc::cli {

namespace {

using nlohmann::json;

/// A scene file larger than this is not a scene.
constexpr size_t kMaxSceneBytes = size_t{64} << 20;

/// The first problem found, as "field: message"; every check returns false once there is one.
class Checker {
 public:
  std::optional<std::string> problem;

  bool fail(const std::string& where, const std::string& message) {
    if (!problem) problem = fmt::format("{}: {}", where, message);
    return false;
  }

  /// `value` is an object whose members are all in `allowed`.
  bool object(const json& value, const std::string& where, std::initializer_list<const char*> allowed) {
    if (!value.is_object()) return fail(where, "expected an object");
    for (const auto& [key, member] : value.items()) {
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; })) {
        std::vector<std::string> names(allowed.begin(), allowed.end());
        return fail(join(where, key), fmt::format("unknown field (expected {})", fmt::join(names, ", ")));
      }
    }
    return true;
  }

  bool number(const json& value, const std::string& where, float low, float high, float& out) {
    if (!value.is_number()) return fail(where, fmt::format("expected a number from {} to {}", low, high));
    // Compared as the float it becomes: 0.1 in the file is the bound 0.1f, not a double below it.
    const double v = value.get<double>();
    const float f = static_cast<float>(v);
    if (!std::isfinite(v) || !std::isfinite(f) || f < low || f > high) {
      return fail(where, fmt::format("expected a number from {} to {}", low, high));
    }
    out = f;
    return true;
  }

  bool integer(const json& value, const std::string& where, int64_t low, int64_t high, uint32_t& out) {
    if (!value.is_number_integer() || value.get<int64_t>() < low || value.get<int64_t>() > high) {
      return fail(where, fmt::format("expected a whole number from {} to {}", low, high));
    }
    out = static_cast<uint32_t>(value.get<int64_t>());
    return true;
  }

  bool string(const json& value, const std::string& where, std::string& out) {
    if (!value.is_string() || value.get<std::string>().empty()) return fail(where, "expected a non-empty string");
    out = value.get<std::string>();
    return true;
  }

  bool vector3(const json& value, const std::string& where, float low, float high, glm::vec3& out) {
    if (!value.is_array() || value.size() != 3) return fail(where, "expected an array of three numbers");
    for (int k = 0; k < 3; ++k) {
      if (!number(value[size_t(k)], fmt::format("{}[{}]", where, k), low, high, out[k])) return false;
    }
    return true;
  }

  bool choice(const json& value, const std::string& where, std::initializer_list<const char*> choices, std::string& out) {
    std::vector<std::string> names(choices.begin(), choices.end());
    if (!value.is_string() || std::find(names.begin(), names.end(), value.get<std::string>()) == names.end()) {
      return fail(where, fmt::format("expected one of {}", fmt::join(names, ", ")));
    }
    out = value.get<std::string>();
    return true;
  }

  static std::string join(const std::string& where, const std::string& key) { return where.empty() ? key : where + "." + key; }
};

constexpr float kHuge = 1e30f;

bool readLight(Checker& c, const json& value, const std::string& where, rt::Light& light) {
  if (!c.object(value, where, {"type", "direction", "position", "color", "intensity", "cone_angle", "cone_softness"})) return false;
  std::string type;
  if (!value.contains("type")) return c.fail(where, "a light needs a type (directional, point, spot)");
  if (!c.choice(value["type"], where + ".type", {"directional", "point", "spot"}, type)) return false;
  light.kind = type == "directional" ? rt::Light::Kind::Directional : type == "point" ? rt::Light::Kind::Point : rt::Light::Kind::Spot;
  auto required = [&](const char* field) {
    if (!value.contains(field)) return c.fail(where, fmt::format("a {} light needs '{}'", type, field));
    return true;
  };
  auto forbidden = [&](const char* field) {
    if (value.contains(field)) return c.fail(Checker::join(where, field), fmt::format("not a field of a {} light", type));
    return true;
  };
  if (light.kind == rt::Light::Kind::Directional) {
    if (!required("direction") || !forbidden("position") || !forbidden("cone_angle") || !forbidden("cone_softness")) return false;
    if (!c.vector3(value["direction"], where + ".direction", -kHuge, kHuge, light.vector)) return false;
    const float length = glm::length(light.vector);
    if (!(length > 1e-12f)) return c.fail(where + ".direction", "must not be zero");
    light.vector /= length;  // length > 0
  } else {
    if (!required("position")) return false;
    if (!c.vector3(value["position"], where + ".position", -kHuge, kHuge, light.vector)) return false;
    if (light.kind == rt::Light::Kind::Point) {
      if (!forbidden("direction") || !forbidden("cone_angle") || !forbidden("cone_softness")) return false;
    } else {
      if (!required("direction")) return false;
      if (!c.vector3(value["direction"], where + ".direction", -kHuge, kHuge, light.axis)) return false;
      const float length = glm::length(light.axis);
      if (!(length > 1e-12f)) return c.fail(where + ".direction", "must not be zero");
      light.axis /= length;  // length > 0
      float outer = 30.0f, softness = 5.0f;
      if (value.contains("cone_angle") && !c.number(value["cone_angle"], where + ".cone_angle", 0.1f, 90.0f, outer)) return false;
      if (value.contains("cone_softness") &&
          !c.number(value["cone_softness"], where + ".cone_softness", 0.0f, 90.0f, softness)) {
        return false;
      }
      // The cone's half-angle is `outer`; the light fades over the last `softness` degrees. The
      // inner cosine stays strictly above the outer one (a step would otherwise divide by 0).
      light.cosOuter = std::cos(glm::radians(outer));
      // The gap stays inside (cosOuter, 1] even for a cone of 0.1 degrees (1 - cosOuter =
      // 1.5e-6, some 25 float steps), so the light reaches full intensity on its axis.
      const float gap = std::min(1e-4f, 0.5f * (1.0f - light.cosOuter));
      light.cosInner = std::min(std::max(std::cos(glm::radians(std::max(outer - softness, 0.0f))), light.cosOuter + gap), 1.0f);
    }
  }
  if (value.contains("color") && !c.vector3(value["color"], where + ".color", 0.0f, kHuge, light.color)) return false;
  if (value.contains("intensity") && !c.number(value["intensity"], where + ".intensity", 0.0f, kHuge, light.intensity)) {
    return false;
  }
  return true;
}

bool readObject(Checker& c, const json& value, const std::string& where, SceneObjectSpec& object) {
  if (!c.object(value, where, {"name", "mesh", "material", "translate", "rotate", "scale"})) return false;
  if (!value.contains("name")) return c.fail(where, "an object needs a name");
  if (!c.string(value["name"], where + ".name", object.name)) return false;
  if (value.contains("mesh") && !c.string(value["mesh"], where + ".mesh", object.mesh)) return false;
  if (value.contains("material") && !c.string(value["material"], where + ".material", object.material)) return false;
  glm::vec3 translate(0.0f), rotate(0.0f), scale(1.0f);
  if (value.contains("translate") && !c.vector3(value["translate"], where + ".translate", -kHuge, kHuge, translate)) return false;
  if (value.contains("rotate") && !c.vector3(value["rotate"], where + ".rotate", -36000.0f, 36000.0f, rotate)) return false;
  if (value.contains("scale")) {
    const json& s = value["scale"];
    if (s.is_number()) {
      float uniform = 1.0f;
      if (!c.number(s, where + ".scale", 1e-12f, kHuge, uniform)) return false;
      scale = glm::vec3(uniform);
    } else if (!c.vector3(s, where + ".scale", 1e-12f, kHuge, scale)) {
      // Positive only: a zero scale flattens the object into nothing a camera can shade, and a
      // mirroring one would turn its faces inside out (the renderer's fronts are
      // counter-clockwise; a mesh file's own mirrored nodes are handled by its reader).
      return false;
    }
  }
  glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
  m = glm::rotate(m, glm::radians(rotate.z), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotate.y), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotate.x), glm::vec3(1, 0, 0));
  object.objectToWorld = glm::scale(m, scale);
  return true;
}

bool readScene(Checker& c, const json& root, const std::filesystem::path& folder, Scene& scene) {
  if (!c.object(root, "(top level)", {"mxc_scene", "documents", "search_paths", "look", "objects", "lights", "environment",
                                      "camera", "render"})) {
    return false;
  }
  if (!root.contains("mxc_scene")) return c.fail("mxc_scene", fmt::format("missing: the format version, {}", kSceneVersion));
  if (!root["mxc_scene"].is_number_integer() || root["mxc_scene"].get<int64_t>() != kSceneVersion) {
    return c.fail("mxc_scene", fmt::format("this mxc reads version {} only", kSceneVersion));
  }
  auto paths = [&](const char* field, std::vector<std::filesystem::path>& out, bool required) {
    if (!root.contains(field)) return required ? c.fail(field, "missing: a list of files relative to the scene") : true;
    const json& list = root[field];
    if (!list.is_array() || (required && list.empty())) return c.fail(field, "expected a non-empty array of strings");
    for (size_t i = 0; i < list.size(); ++i) {
      std::string text;
      if (!c.string(list[i], fmt::format("{}[{}]", field, i), text)) return false;
      out.push_back(folder / text);  // an absolute path stays absolute
    }
    return true;
  };
  if (!paths("documents", scene.documents, true) || !paths("search_paths", scene.searchPaths, false)) return false;
  if (root.contains("look") && !c.string(root["look"], "look", scene.look)) return false;

  if (!root.contains("objects") || !root["objects"].is_array() || root["objects"].empty()) {
    return c.fail("objects", "expected a non-empty array of objects");
  }
  std::set<std::string> names;
  for (size_t i = 0; i < root["objects"].size(); ++i) {
    const std::string where = fmt::format("objects[{}]", i);
    SceneObjectSpec object;
    if (!readObject(c, root["objects"][i], where, object)) return false;
    if (!names.insert(object.name).second) return c.fail(where + ".name", fmt::format("'{}' names another object too", object.name));
    if (object.material.empty() && scene.look.empty()) {
      return c.fail(where, "an object needs a material, or the scene a look that assigns one");
    }
    // Mesh files are relative to the scene; names (sphere, shaderball) stay names.
    const std::filesystem::path mesh(object.mesh);
    if (mesh.has_extension() || object.mesh.find('/') != std::string::npos) object.mesh = (folder / mesh).string();
    scene.objects.push_back(std::move(object));
  }

  if (root.contains("lights")) {
    const json& lights = root["lights"];
    if (!lights.is_array()) return c.fail("lights", "expected an array of lights");
    if (lights.size() > glsl::kMaxLights) return c.fail("lights", fmt::format("at most {} lights", glsl::kMaxLights));
    for (size_t i = 0; i < lights.size(); ++i) {
      rt::Light light;
      if (!readLight(c, lights[i], fmt::format("lights[{}]", i), light)) return false;
      scene.lights.push_back(light);
    }
  }

  if (root.contains("environment")) {
    const json& e = root["environment"];
    if (!c.object(e, "environment", {"type", "file", "intensity", "rotation"})) return false;
    std::string type = "sky";
    if (e.contains("type") && !c.choice(e["type"], "environment.type", {"image", "sky", "white", "none"}, type)) return false;
    scene.environment.kind = type == "image" ? rt::Environment::Map
                             : type == "sky" ? rt::Environment::Sky
                             : type == "white" ? rt::Environment::White
                                               : rt::Environment::None;
    if (type == "image") {
      std::string file;
      if (!e.contains("file")) return c.fail("environment", "an image environment needs 'file'");
      if (!c.string(e["file"], "environment.file", file)) return false;
      scene.environment.image = folder / file;
    } else if (e.contains("file")) {
      return c.fail("environment.file", fmt::format("only an image environment has a file (this one is {})", type));
    }
    if (e.contains("intensity") && !c.number(e["intensity"], "environment.intensity", 0.0f, kHuge, scene.environment.intensity)) return false;
    if (e.contains("rotation") && !c.number(e["rotation"], "environment.rotation", -36000.0f, 36000.0f, scene.environment.rotationDegrees)) return false;
  }

  if (root.contains("camera")) {
    const json& cam = root["camera"];
    if (!c.object(cam, "camera", {"position", "target", "up", "fov"})) return false;
    rt::Camera camera;
    if (!cam.contains("position")) return c.fail("camera", "a camera needs a position (leave the camera out to frame the objects)");
    if (!c.vector3(cam["position"], "camera.position", -kHuge, kHuge, camera.eye)) return false;
    if (cam.contains("target") && !c.vector3(cam["target"], "camera.target", -kHuge, kHuge, camera.target)) return false;
    if (cam.contains("up") && !c.vector3(cam["up"], "camera.up", -kHuge, kHuge, camera.up)) return false;
    if (cam.contains("fov") && !c.number(cam["fov"], "camera.fov", 1.0f, 170.0f, camera.fovDegrees)) return false;
    // The camera's own sizes first (a unit scene stands in for the objects, checked at render):
    // a far camera made the up vector test below fail on an overflowed length.
    if (auto why = rt::scaleProblem({glm::vec3(0.0f), 1.0f}, camera)) return c.fail("camera", *why);
    if (auto why = rt::cameraProblem(camera)) return c.fail("camera", *why);
    scene.camera = camera;
  }

  if (root.contains("render")) {
    const json& r = root["render"];
    if (!c.object(r, "render", {"size", "spp", "exposure", "tonemap", "background", "accuracy"})) return false;
    if (r.contains("accuracy")) {
      std::string tier;
      if (!c.choice(r["accuracy"], "render.accuracy", {"fast", "balanced", "reference"}, tier)) return false;
      scene.accuracy = parseAccuracy(tier);
    }
    if (r.contains("size")) {
      const json& size = r["size"];
      if (size.is_array()) {
        if (size.size() != 2) return c.fail("render.size", "expected N or [width, height]");
        if (!c.integer(size[0], "render.size[0]", 8, 8192, scene.width) || !c.integer(size[1], "render.size[1]", 8, 8192, scene.height)) return false;
      } else {
        if (!c.integer(size, "render.size", 8, 8192, scene.width)) return false;
        scene.height = scene.width;
      }
    }
    if (r.contains("spp") && !c.integer(r["spp"], "render.spp", 1, 1 << 20, scene.spp)) return false;
    if (r.contains("exposure") && !c.number(r["exposure"], "render.exposure", -64.0f, 64.0f, scene.exposure)) return false;
    if (r.contains("tonemap") && !c.choice(r["tonemap"], "render.tonemap", {"aces", "neutral", "none"}, scene.toneMapping)) return false;
    if (r.contains("background")) {
      glm::vec3 background;
      if (!c.vector3(r["background"], "render.background", 0.0f, kHuge, background)) return false;
      scene.background = background;
    }
  }
  return true;
}

}  // namespace

bool isSceneFile(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
  return extension == ".json";
}

std::variant<Scene, std::string> readScene(const std::filesystem::path& path) {
  auto bytes = readInputFile(path, kMaxSceneBytes);
  if (auto* why = std::get_if<1>(&bytes)) return fmt::format("error: cannot read the scene '{}': {}", path.string(), *why);
  return readSceneText(path, std::get<0>(bytes));
}

std::variant<Scene, std::string> readSceneText(const std::filesystem::path& path, const std::string& text) {
  // A byte offset (0-based) as "file:line:column".
  auto position = [&](size_t offset) {
    offset = std::min(offset, text.size());
    const size_t line = size_t(std::count(text.begin(), text.begin() + long(offset), '\n')) + 1;
    const size_t lineStart = text.rfind('\n', offset == 0 ? 0 : offset - 1);
    const size_t column = offset - (lineStart == std::string::npos || offset == 0 ? 0 : lineStart + 1) + 1;
    return fmt::format("{}:{}:{}", path.string(), line, column);
  };
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    // nlohmann's byte offset is 1-based, at the offending character.
    std::string message = e.what();
    if (const size_t colon = message.find(": syntax error"); colon != std::string::npos) message = message.substr(colon + 2);
    return fmt::format("{}: error: not valid JSON: {}", position(e.byte > 0 ? e.byte - 1 : 0), message);
  } catch (const json::out_of_range& e) {
    // A number beyond a double (1e400): nlohmann gives the number ("number overflow parsing
    // '1e400'") but no offset; its first occurrence as a token of the text is where it stands.
    const std::string message = e.what();
    const size_t open = message.find('\''), close = message.rfind('\'');
    if (open == std::string::npos || close <= open) return fmt::format("{}: error: not valid JSON: {}", path.string(), message);
    const std::string number = message.substr(open + 1, close - open - 1);
    size_t at = text.find(number);
    while (at != std::string::npos && at > 0 && std::strchr("0123456789.-+eE", text[at - 1])) at = text.find(number, at + 1);
    return fmt::format("{}: error: the number {} is beyond the range of a double", at == std::string::npos ? path.string() : position(at),
                       number);
  }
  Scene scene;
  scene.file = path;
  Checker checker;
  if (!readScene(checker, root, path.parent_path(), scene)) {
    return fmt::format("{}: error: {}", path.string(), checker.problem.value_or("invalid scene"));
  }
  return scene;
}

}  // namespace mxc::cli
