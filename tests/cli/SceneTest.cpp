// Scene files (cli/Scene.h): the examples load, every malformed field is refused naming it, and
// `mxc render SCENE.json` renders several objects with their materials, looks and lights.

#include <gtest/gtest.h>

#include <fstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "cli/Scene.h"
#include "runtime/ImageIO.h"
#include "support/CommandSupport.h"
#include "support/RenderCommandSupport.h"

namespace mxc::test {
namespace {

std::string readScene(const std::string& name, const std::string& text) {
  const fs::path path = writeTemp(name, text);
  auto scene = cli::readScene(path);
  fs::remove(path);
  return std::holds_alternative<std::string>(scene) ? std::get<std::string>(scene) : std::string();
}

TEST(Scene, ExamplesAreValid) {
  size_t count = 0;
  for (const auto& entry : fs::directory_iterator(sourceDir() / "examples/scenes")) {
    if (entry.path().extension() != ".json") continue;
    auto scene = cli::readScene(entry.path());
    ASSERT_TRUE(std::holds_alternative<cli::Scene>(scene)) << std::get<std::string>(scene);
    EXPECT_FALSE(std::get<cli::Scene>(scene).objects.empty());
    ++count;
  }
  EXPECT_GE(count, 2u);
}

TEST(Scene, ReadsEveryField) {
  const std::string error = readScene("full.json", R"({"mxc_scene": 1, "documents": ["a.mtlx"], "search_paths": ["res"],
    "objects": [{"name": "o", "mesh": "meshes/ball.glb", "material": "M", "translate": [1, 2, 3], "rotate": [0, 90, 0], "scale": [2, 2, 2]}],
    "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -2, 0], "cone_angle": 20, "cone_softness": 5, "intensity": 4}],
    "environment": {"type": "image", "file": "env.exr", "intensity": 2, "rotation": 45},
    "camera": {"position": [0, 1, 5], "target": [0, 1, 0], "up": [0, 1, 0], "fov": 30},
    "render": {"size": [320, 200], "spp": 8, "exposure": -1, "tonemap": "neutral", "background": [0.1, 0.2, 0.3],
               "accuracy": "fast"}})");
  EXPECT_EQ(error, "");
  const fs::path path = writeTemp("full2.json", R"({"mxc_scene": 1, "documents": ["a.mtlx"], "objects": [{"name": "o", "material": "M",
    "translate": [1, 2, 3], "scale": 2}], "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -2, 0], "cone_angle": 20}],
    "render": {"size": 64}})");
  auto read = cli::readScene(path);
  fs::remove(path);
  ASSERT_TRUE(std::holds_alternative<cli::Scene>(read));
  const cli::Scene& scene = std::get<cli::Scene>(read);
  EXPECT_EQ(scene.documents[0], path.parent_path() / "a.mtlx");  // relative to the scene
  EXPECT_EQ(scene.width, 64u);
  EXPECT_EQ(scene.height, 64u);
  // translate * scale: the origin moves to (1, 2, 3), a unit x to (3, 2, 3).
  EXPECT_EQ(glm::vec3(scene.objects[0].objectToWorld * glm::vec4(1, 0, 0, 1)), glm::vec3(3, 2, 3));
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].axis, glm::vec3(0, -1, 0));  // normalised
  EXPECT_NEAR(scene.lights[0].cosOuter, std::cos(glm::radians(20.0f)), 1e-6f);
  EXPECT_NEAR(scene.lights[0].cosInner, std::cos(glm::radians(15.0f)), 1e-6f);  // softness 5 by default
  // A cone of 0.1 degrees still reaches full intensity on its axis: cosOuter < cosInner <= 1.
  const fs::path narrow = writeTemp("narrow.json", R"({"mxc_scene": 1, "documents": ["a.mtlx"], "objects": [{"name": "o", "material": "M"}],
    "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "cone_angle": 0.1}]})");
  auto narrowScene = cli::readScene(narrow);
  fs::remove(narrow);
  ASSERT_TRUE(std::holds_alternative<cli::Scene>(narrowScene));
  const rt::Light& spot = std::get<cli::Scene>(narrowScene).lights[0];
  EXPECT_LT(spot.cosOuter, spot.cosInner);
  EXPECT_LE(spot.cosInner, 1.0f);
}

TEST(Scene, TheSchemaAndTheReaderKnowTheSameFields) {
  // docs/scene.schema.json lists every field; the reader refuses unknown ones. Each field the
  // schema lists, put where it belongs, must not be refused as unknown, and the schema must not
  // allow more fields than it lists.
  std::ifstream in(sourceDir() / "docs/scene.schema.json");
  const nlohmann::json schema = nlohmann::json::parse(in);
  const std::string objects = R"("objects": [{"name": "a", "material": "M"}])";
  auto check = [&](const nlohmann::json& node, const std::string& where, const std::function<std::string(const std::string&)>& scene) {
    ASSERT_EQ(node.value("additionalProperties", true), false) << where;
    for (const auto& [field, definition] : node["properties"].items()) {
      const std::string error = readScene("field.json", scene(field));
      EXPECT_EQ(error.find("unknown field"), std::string::npos) << where << "." << field << ": " << error;
    }
    // And a field the schema does not list is refused.
    EXPECT_NE(readScene("field.json", scene("not_a_field")).find("unknown field"), std::string::npos) << where;
  };
  const std::string head = R"({"mxc_scene": 1, "documents": ["d.mtlx"], )";
  check(schema, "(top level)", [&](const std::string& f) { return head + objects + ", \"" + f + "\": null}"; });
  check(schema["$defs"]["object"], "object", [&](const std::string& f) {
    return head + R"("objects": [{"name": "a", "material": "M", ")" + f + R"(": null}]})";
  });
  check(schema["$defs"]["light"], "light", [&](const std::string& f) {
    return head + objects + R"(, "lights": [{"type": "spot", ")" + f + R"(": null}]})";
  });
  check(schema["$defs"]["environment"], "environment", [&](const std::string& f) {
    return head + objects + R"(, "environment": {")" + f + R"(": null}})";
  });
  check(schema["$defs"]["camera"], "camera", [&](const std::string& f) {
    return head + objects + R"(, "camera": {")" + f + R"(": null}})";
  });
  check(schema["$defs"]["render"], "render", [&](const std::string& f) {
    return head + objects + R"(, "render": {")" + f + R"(": null}})";
  });
}

TEST(Scene, MalformedFieldsAreRefusedNamingTheField) {
  const std::string objects = R"("objects": [{"name": "a", "material": "M"}])";
  const std::string head = R"({"mxc_scene": 1, "documents": ["d.mtlx"], )";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"documents": ["d.mtlx"], )" + objects + "}", "mxc_scene: missing"},
      {R"({"mxc_scene": 2, "documents": ["d.mtlx"], )" + objects + "}", "mxc_scene: this mxc reads version 1 only"},
      {head + objects + R"(, "colour": 1})", "colour: unknown field"},
      {R"({"mxc_scene": 1, "documents": [], )" + objects + "}", "documents: expected a non-empty array"},
      {head + R"("objects": []})", "objects: expected a non-empty array"},
      {head + R"("objects": [{"material": "M"}]})", "objects[0]: an object needs a name"},
      {head + R"("objects": [{"name": "a", "material": "M"}, {"name": "a", "material": "M"}]})", "objects[1].name: 'a' names another object"},
      {head + R"("objects": [{"name": "a"}]})", "objects[0]: an object needs a material"},
      {head + R"("objects": [{"name": "a", "material": "M", "scale": [1, 0, 1]}]})", "objects[0].scale[1]: expected a number from"},
      {head + R"("objects": [{"name": "a", "material": "M", "scale": [-1, 1, 1]}]})", "objects[0].scale[0]: expected a number from"},
      {head + R"("objects": [{"name": "a", "material": "M", "translate": [1, 2]}]})", "objects[0].translate: expected an array of three numbers"},
      {head + R"("objects": [{"name": "a", "material": "M", "colour": 1}]})", "objects[0].colour: unknown field"},
      {head + objects + R"(, "lights": [{"type": "area"}]})", "lights[0].type: expected one of directional, point, spot"},
      {head + objects + R"(, "lights": [{"type": "directional", "direction": [0, 1, 0], "position": [0, 0, 0]}]})",
       "lights[0].position: not a field of a directional light"},
      {head + objects + R"(, "lights": [{"type": "directional", "direction": [0, 0, 0]}]})", "lights[0].direction: must not be zero"},
      {head + objects + R"(, "lights": [{"type": "spot", "position": [0, 1, 0]}]})", "lights[0]: a spot light needs 'direction'"},
      {head + objects + R"(, "lights": [{"type": "point", "position": [0, 1, 0], "intensity": -1}]})", "lights[0].intensity"},
      {head + objects + R"(, "lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "cone_angle": 120}]})",
       "lights[0].cone_angle: expected a number from 0.1 to 90"},
      {head + objects + R"(, "environment": {"type": "image"}})", "environment: an image environment needs 'file'"},
      {head + objects + R"(, "environment": {"type": "sky", "file": "x.exr"}})", "environment.file: only an image environment"},
      {head + objects + R"(, "camera": {"position": [0, 5, 0], "target": [0, 0, 0]}})", "camera: the camera's up vector is along"},
      {head + objects + R"(, "camera": {"target": [0, 0, 0]}})", "camera: a camera needs a position"},
      {head + objects + R"(, "render": {"size": [4, 4]}})", "render.size[0]: expected a whole number from 8 to 8192"},
      {head + objects + R"(, "render": {"spp": 1.5}})", "render.spp: expected a whole number"},
      {head + objects + R"(, "render": {"tonemap": "filmic"}})", "render.tonemap: expected one of aces, neutral, none"},
      {head + objects + R"(, "render": {"accuracy": "exact"}})", "render.accuracy: expected one of fast, balanced, reference"},
      {"[1, 2]", "(top level): expected an object"},
      // A far camera overflowed a length and was called "up along the view direction".
      {head + objects + R"(, "camera": {"position": [1e20, 0, 0]}})",
       "camera: the camera's position is 1e+20 units from the origin, and mxc renders within 1e+10"},
  };
  for (const auto& [text, message] : cases) {
    const std::string error = readScene("bad.json", text);
    EXPECT_NE(error.find(message), std::string::npos) << text << "\n-> " << error;
    EXPECT_NE(error.find("bad.json: error: "), std::string::npos) << error;
  }
  // JSON syntax: the line and column of the fault.
  const std::string error = readScene("syntax.json", "{\n  \"mxc_scene\": 1,\n  \"documents\": [\"a\",]\n}\n");
  EXPECT_NE(error.find("syntax.json:3:"), std::string::npos) << error;
  EXPECT_NE(error.find("not valid JSON"), std::string::npos) << error;
  // A number beyond a double: the JSON library names it but gives no position (it was its raw
  // message, without file or line).
  const std::string huge = readScene("huge.json", "{\"mxc_scene\": 1,\n \"objects\": [{\"scale\": 1e400}]}");
  EXPECT_NE(huge.find("huge.json:2:24: error: the number 1e400 is beyond the range of a double"), std::string::npos) << huge;
  EXPECT_EQ(cli::readScene("/nonexistent/scene.json").index(), 1u);
  EXPECT_EQ(std::get<std::string>(cli::readScene("/nonexistent/scene.json")).rfind("error: cannot read the scene", 0), 0u);
}

TEST(SceneRender, RendersTheStillLifeExample) {
  const rt::RgbaImage image = renderCommand((sourceDir() / "examples/scenes/still_life.json").string() + " --size 64x40 --spp 2");
  ASSERT_EQ(image.width, 64u);
  ASSERT_EQ(image.height, 40u);
  double covered = 0.0;
  for (size_t i = 3; i < image.pixels.size(); i += 4) {
    ASSERT_TRUE(std::isfinite(image.pixels[i - 1]));
    covered += image.pixels[i];
  }
  EXPECT_GT(covered / (64.0 * 40.0), 0.3);  // the floor and both spheres
  // The scene states its mesh: --mesh is refused, and nothing is written.
  CommandRun r = mxc("render " + (sourceDir() / "examples/scenes/still_life.json").string() + " -o x.png --mesh sphere");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--mesh cannot be used with a scene file"), std::string::npos) << r.err;
}

/// A document of two constant-colour materials, Red and Blue, and a look assigning them.
fs::path twoMaterials() {
  auto material = [](const std::string& name, const std::string& color) {
    return "  <standard_surface name=\"" + name + "_s\" type=\"surfaceshader\"><input name=\"base_color\" type=\"color3\" value=\"" +
           color + "\"/><input name=\"specular\" type=\"float\" value=\"0\"/></standard_surface>\n  <surfacematerial name=\"" + name +
           "\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"" + name + "_s\"/></surfacematerial>\n";
  };
  return writeTemp("two.mtlx", "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n" + material("Red", "1, 0, 0") +
                                   material("Blue", "0, 0, 1") +
                                   "  <look name=\"Sides\">\n    <materialassign name=\"l\" geom=\"/left\" material=\"Red\"/>\n"
                                   "    <materialassign name=\"r\" geom=\"right, other\" material=\"Blue\"/>\n  </look>\n</materialx>\n");
}

TEST(SceneRender, ALookAssignsMaterialsByObjectName) {
  const fs::path document = twoMaterials();
  const std::string objects = R"("objects": [{"name": "left", "translate": [-1.2, 0, 0]}, {"name": "right", "translate": [1.2, 0, 0]}],
    "environment": {"type": "white"}, "camera": {"position": [0, 0, 6]}, "render": {"size": [64, 32], "spp": 1}})";
  const fs::path scene = writeTemp("look.json", R"({"mxc_scene": 1, "documents": [")" + document.string() + R"("], "look": "Sides", )" + objects);
  const rt::RgbaImage image = renderCommand(scene.string());
  ASSERT_EQ(image.width, 64u);
  // Under a white furnace the left sphere is red, the right one blue. The view spans 2 * 6 *
  // tan(22.5 deg) = 4.97 units over 32 rows: the centres are 1.2 * 6.4 = 7.7 pixels either side.
  const float* left = image.at(24, 16);
  const float* right = image.at(40, 16);
  EXPECT_GT(left[0], 4.0f * left[2]);
  EXPECT_GT(right[2], 4.0f * right[0]);
  // A look no document has, and a material no document has: refused naming them.
  const fs::path badLook = writeTemp("badlook.json", R"({"mxc_scene": 1, "documents": [")" + document.string() + R"("], "look": "Nope", )" + objects);
  CommandRun r = mxc("render " + badLook.string() + " -o x.png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("no document of the scene has a look named 'Nope'"), std::string::npos) << r.err;
  const fs::path badMaterial = writeTemp("badmaterial.json", R"({"mxc_scene": 1, "documents": [")" + document.string() +
                                                                 R"("], "objects": [{"name": "a", "material": "Green"}]})");
  r = mxc("render " + badMaterial.string() + " -o x.png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("objects[0] ('a'): no document of the scene has a material named 'Green'"), std::string::npos) << r.err;
  for (const fs::path& p : {document, scene, badLook, badMaterial}) fs::remove(p);
}

TEST(SceneRender, ScenesTooSmallOrTooLargeForFloatsAreRefusedNotBlank) {
  // A sphere scaled by 1e-12 or 1e20 rendered the background alone, with exit 0.
  const fs::path document = twoMaterials();
  for (const auto& [scale, message] : std::vector<std::pair<std::string, std::string>>{
           {"1e-12", "error: the scene's bounding sphere has a radius of 1e-12 units, and mxc renders radii of 1e-05 units and more"},
           {"1e20", "error: the scene overflows 32-bit floats"},
           {"1e10", "error: the scene reaches 1e+10 units from the origin, and mxc renders scenes within 1e+09"}}) {
    SCOPED_TRACE(scale);
    const fs::path scene = writeTemp("scale.json", R"({"mxc_scene": 1, "documents": [")" + document.string() + R"("],
      "objects": [{"name": "ball", "mesh": "sphere", "material": "Red", "scale": )" + scale + R"(}], "render": {"size": 16, "spp": 1}})");
    const fs::path out = fs::temp_directory_path() / "mxc_scale.png";
    const CommandRun run = mxc("render " + scene.string() + " -o " + out.string());
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
    fs::remove(scene);
  }
  // The ends of the range render the sphere as the unit one does (framed, so the same image).
  std::vector<rt::RgbaImage> images;
  for (const std::string scale : {"1e-5", "1", "1e9"}) {
    const fs::path scene = writeTemp("scale.json", R"({"mxc_scene": 1, "documents": [")" + document.string() + R"("],
      "objects": [{"name": "ball", "mesh": "sphere", "material": "Red", "scale": )" + scale + R"(}], "render": {"size": 16, "spp": 1}})");
    images.push_back(renderCommand(scene.string()));
    fs::remove(scene);
  }
  ASSERT_EQ(images.size(), 3u);
  for (const rt::RgbaImage& image : images) ASSERT_EQ(image.width, 16u);
  EXPECT_GT(images[1].at(8, 8)[3], 0.5f) << "the unit sphere covers the centre";
  for (size_t k : {0u, 2u}) {
    double difference = 0.0;
    for (size_t i = 0; i < images[1].pixels.size(); ++i) difference = std::max(difference, double(std::abs(images[k].pixels[i] - images[1].pixels[i])));
    EXPECT_LT(difference, 0.01) << "scale " << (k == 0 ? "1e-5" : "1e9");
  }
  fs::remove(document);
}

TEST(SceneRender, ASpotLightLightsOnlyItsCone) {
  // A floor seen from above under a spot straight down, 2 units over it, with a 20 degree cone:
  // lit within tan(20 deg) * 2 = 0.73 of the centre, black beyond it (no environment).
  const fs::path document = twoMaterials();
  const fs::path scene = writeTemp("spot.json", R"({"mxc_scene": 1, "documents": [")" + document.string() + R"("],
    "objects": [{"name": "floor", "mesh": "plane", "material": "Red", "scale": 2}],
    "lights": [{"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "cone_angle": 20, "cone_softness": 2, "intensity": 8}],
    "environment": {"type": "none"}, "camera": {"position": [0, 6, 0], "up": [0, 0, -1], "fov": 45},
    "render": {"size": 64, "spp": 1}})");
  const rt::RgbaImage image = renderCommand(scene.string());
  ASSERT_EQ(image.width, 64u);
  // The floor spans 4 units; at distance 6 under 45 degrees the view spans 2 * 6 * tan(22.5) =
  // 4.97 units, 12.9 pixels per unit.
  EXPECT_GT(image.at(32, 32)[0], 0.1f);                  // under the light
  EXPECT_GT(image.at(32 + 7, 32)[0], 0.1f);              // 0.54 units out: inside the cone
  EXPECT_EQ(image.at(32 + 16, 32)[0], 0.0f);             // 1.24 units out: outside
  EXPECT_EQ(image.at(32 + 16, 32)[3], 1.0f);             // ... yet on the floor
  fs::remove(document);
  fs::remove(scene);
}

TEST(SceneRender, ADocumentsLookDressesTheShaderBallsParts) {
  // standard_surface_look_wood_tiled.mtlx assigns Tiled_Wood to Preview_Mesh and
  // Greysphere_Calibration to Calibration_Mesh, the shader ball's two nodes, as MaterialX's
  // viewer shows it.
  const fs::path tree = sharedDir() / "conformance/materialx-tree";
  if (!fs::exists(tree / "resources/Geometry/shaderball.glb")) GTEST_SKIP() << "no shader ball under " << tree;
  const std::string document = corpus("materialx/examples/StandardSurface/standard_surface_look_wood_tiled.mtlx");
  const fs::path out = writeTemp("look.exr", "");
  CommandRun r = mxc("render " + document + " -o " + out.string() + " --mesh shaderball --search-path " + tree.string() +
                     " --look Wood_Look --size 48 --spp 1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Wood_Look: wrote"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 materials"), std::string::npos) << r.out;
  auto image = rt::readImage(out);
  fs::remove(out);
  ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(image));
  EXPECT_EQ(std::get<rt::RgbaImage>(image).at(24, 24)[3], 1.0f);
  r = mxc("render " + document + " -o " + out.string() + " --mesh shaderball --search-path " + tree.string() + " --look Nope");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(document + ": error: look: no document of the scene has a look named 'Nope'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(SceneCompile, CompilesEveryMaterialTheSceneUsesOnce) {
  const fs::path folder = fs::temp_directory_path() / ("mxc_scene_compile_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  CommandRun r = mxc("compile " + (sourceDir() / "examples/scenes/still_life.json").string() + " -o " + (folder / "m.spv").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"CoatedCopper", "GlazedCeramic", "NoisePlastic"}) {
    EXPECT_TRUE(fs::exists(folder / (std::string("m_") + name + ".spv"))) << name;
  }
  EXPECT_NE(r.out.find("compiled 3 material(s)"), std::string::npos) << r.out;
  // The scene's accuracy tier reaches the shader: the fast tier's module differs from the
  // balanced one's.
  auto compiled = [&](const std::string& render, const std::string& name) {
    const fs::path scene = writeTemp(name + ".json", R"({"mxc_scene": 1, "documents": [")" +
                                                         (sourceDir() / "examples/open_pbr_coated_copper.mtlx").string() +
                                                         R"("], "objects": [{"name": "a", "material": "CoatedCopper"}])" + render + "}");
    CommandRun run = mxc("compile " + scene.string() + " -q -o " + (folder / (name + ".spv")).string());
    EXPECT_EQ(run.exitCode, 0) << run.err;
    fs::remove(scene);
    std::ifstream in(folder / (name + ".spv"), std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string fast = compiled(R"(, "render": {"accuracy": "fast"})", "fast");
  const std::string balanced = compiled("", "balanced");
  EXPECT_FALSE(fast.empty());
  EXPECT_NE(fast, balanced);
  // The scene names its materials.
  r = mxc("compile " + (sourceDir() / "examples/scenes/still_life.json").string() + " --material NoisePlastic");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--material cannot be used with a scene file"), std::string::npos) << r.err;
  fs::remove_all(folder);
}

}  // namespace
}  // namespace mxc::test
