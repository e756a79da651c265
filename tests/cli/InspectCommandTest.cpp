// The mxc command line: inspect's outputs, exit codes, and atomic output files.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "support/CommandSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

TEST(InspectCommand, TextReportShowsMaterialsInputsAndSources) {
  CommandRun r = mxc("inspect " + corpus("materialx/examples/OpenPbr/open_pbr_carpaint.mtlx"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("material Car_Paint <surfacematerial>"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("<open_pbr_surface> ND_open_pbr_surface_surfaceshader v1.1.1"), std::string::npos);
  // A set input shows its value and line; a default input shows where the nodedef is.
  EXPECT_NE(r.out.find("coat_weight"), std::string::npos);
  EXPECT_NE(r.out.find("(default)  nodedef nodedefs/bxdf/open_pbr_surface.mtlx:"), std::string::npos);
  EXPECT_NE(r.out.find("0 errors, 0 warnings"), std::string::npos);
}

TEST(InspectCommand, JsonFollowsTheSchema) {
  CommandRun r = mxc("inspect --json " + corpus("materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema"], "mxc-inspect-1");
  EXPECT_EQ(j["document"]["version"], "1.39");
  ASSERT_EQ(j["materials"].size(), 1u);
  EXPECT_EQ(j["materials"][0]["name"], "M_BrickPattern");
  EXPECT_EQ(j["materials"][0]["shaders"][0]["node"], "N_StandardSurface");
  ASSERT_EQ(j["graphs"].size(), 1u);
  EXPECT_EQ(j["graphs"][0]["name"], "NG_BrickPattern");
  bool found = false;
  for (const auto& node : j["nodes"]) {
    if (node["id"] != "N_StandardSurface") continue;
    found = true;
    EXPECT_EQ(node["nodedef"], "ND_standard_surface_surfaceshader");
    for (const auto& input : node["inputs"]) {
      if (input["name"] == "base_color") {
        EXPECT_EQ(input["source"], "connection");
        EXPECT_EQ(input["from"]["graph"], "NG_BrickPattern");
        EXPECT_EQ(input["from"]["output"], "base_color_output");
        EXPECT_EQ(input["location"]["line"], 125);
      }
      if (input["name"] == "base") {
        EXPECT_EQ(input["source"], "default");
        EXPECT_EQ(input["value"], 1.0);
      }
    }
  }
  EXPECT_TRUE(found);
}

// --effects: each effect kept or dropped with the input behind it, and the scene's choices.
TEST(InspectCommand, EffectsNameTheInputOrSceneFactBehindEachChoice) {
  const std::string doc = corpus("materialx/examples/OpenPbr/open_pbr_default.mtlx");
  CommandRun r = mxc("inspect --effects " + doc);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto line = [&](const std::string& text, const std::string& effect) {
    const size_t at = text.find(effect);
    return at == std::string::npos ? std::string() : text.substr(text.rfind('\n', at) + 1, text.find('\n', at) - text.rfind('\n', at) - 1);
  };
  EXPECT_NE(line(r.out, " coat ").find("dropped"), std::string::npos) << r.out;
  EXPECT_NE(line(r.out, " coat ").find("coat_weight = 0 (line 32)"), std::string::npos) << r.out;
  EXPECT_NE(line(r.out, " specular ").find("kept"), std::string::npos) << r.out;
  EXPECT_NE(line(r.out, "environment lighting").find("kept"), std::string::npos) << r.out;
  EXPECT_NE(line(r.out, "point and spot light code").find("dropped"), std::string::npos) << r.out;
  EXPECT_NE(line(r.out, "refraction code").find("dropped"), std::string::npos) << r.out;

  // A parameter keeps what it can switch on, and says so with its UI range.
  CommandRun p = mxc("inspect --effects --param coat_weight " + doc);
  ASSERT_EQ(p.exitCode, 0) << p.err;
  EXPECT_NE(line(p.out, " coat ").find("kept"), std::string::npos) << p.out;
  EXPECT_NE(line(p.out, " coat ").find("coat_weight is a parameter (UI range 0.0 to 1.0)"), std::string::npos) << p.out;

  // A scene's lights and environment: the still life has a spot light and the sky; the glass
  // transmits.
  CommandRun scene = mxc("inspect --effects --json " + (sourceDir() / "examples/scenes/still_life.json").string());
  ASSERT_EQ(scene.exitCode, 0) << scene.err;
  nlohmann::json j = nlohmann::json::parse(scene.out);
  EXPECT_EQ(j["schema"], "mxc-effects-1");
  ASSERT_FALSE(j["materials"].empty());
  for (const auto& m : j["materials"]) {
    for (const auto& e : m["effects"]) {
      if (e["effect"] == "point and spot light code" || e["effect"] == "environment lighting") {
        EXPECT_TRUE(e["kept"].get<bool>()) << m["name"] << ": " << e["effect"];
      }
    }
  }
}

// An image not beside the document is found on the search path (--search-path, then
// MATERIALX_SEARCH_PATH), as MaterialX finds its test suite's resources/Images/...; the first
// folder that has it wins, and the IR names the file found (absolute).
TEST(InspectCommand, ImagesAreFoundOnTheSearchPath) {
  TempFolder folder("search_path");
  fs::create_directories(folder / "doc");
  fs::create_directories(folder / "first/resources/Images");
  fs::create_directories(folder / "second/resources/Images");
  writeText(folder / "first/resources/Images/grid.png", "");
  writeText(folder / "second/resources/Images/grid.png", "");
  writeText(folder / "doc/d.mtlx",
            "<materialx version=\"1.39\">\n  <image name=\"img\" type=\"color3\">\n"
            "    <input name=\"file\" type=\"filename\" value=\"resources/Images/grid.png\"/>\n  </image>\n"
            "  <surface_unlit name=\"s\" type=\"surfaceshader\">\n"
            "    <input name=\"emission_color\" type=\"color3\" nodename=\"img\"/>\n  </surface_unlit>\n"
            "  <surfacematerial name=\"m\" type=\"material\">\n"
            "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/>\n  </surfacematerial>\n"
            "</materialx>\n");
  const std::string doc = (folder / "doc/d.mtlx").string();
  CommandRun r = mxc("inspect --ir " + doc, "unset MATERIALX_SEARCH_PATH;");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("texture \"resources/Images/grid.png\""), std::string::npos) << r.out;
  r = mxc("inspect --ir " + doc + " --search-path " + (folder / "missing").string() + " --search-path " +
          (folder / "second").string());
  EXPECT_NE(r.out.find("texture \"" + (folder / "second/resources/Images/grid.png").string() + "\""), std::string::npos)
      << r.out;
  r = mxc("inspect --ir " + doc, "MATERIALX_SEARCH_PATH=" + (folder / "first").string() + ":" +
                                     (folder / "second").string());
  EXPECT_NE(r.out.find("texture \"" + (folder / "first/resources/Images/grid.png").string() + "\""), std::string::npos)
      << r.out;
  // The document's folder comes first.
  fs::create_directories(folder / "doc/resources/Images");
  writeText(folder / "doc/resources/Images/grid.png", "");
  r = mxc("inspect --ir " + doc + " --search-path " + (folder / "second").string());
  EXPECT_NE(r.out.find("texture \"resources/Images/grid.png\""), std::string::npos) << r.out;
}

TEST(InspectCommand, DotIsAGraphvizDigraph) {
  CommandRun r = mxc("inspect --dot " + corpus("materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("digraph ", 0), 0u);
  EXPECT_NE(r.out.find("subgraph \"cluster_NG_BrickPattern\""), std::string::npos);
  EXPECT_NE(r.out.find("\"NG_BrickPattern/node_clamp_0\" -> \"NG_BrickPattern/output:base_color_output\""), std::string::npos);
  // Name and category on two lines: DOT's escape \n, one backslash (two would show a literal "\n").
  EXPECT_NE(r.out.find("[label=\"N_StandardSurface\\n<standard_surface>\"]"), std::string::npos) << r.out.substr(0, 300);
  EXPECT_EQ(r.out.find("\\\\n"), std::string::npos);
  EXPECT_EQ(r.out.back(), '\n');
}

// --set and --param change what is compiled, so they go with --ir (and --effects); the plain
// report shows the document as written and refuses them rather than ignore them.
TEST(InspectCommand, SetAndParamNeedTheIr) {
  const std::string doc = corpus("openpbr-presets/open_pbr_default.mtlx");
  CommandRun r = mxc("inspect " + doc + " --set base_color=0.1,0.2,0.3");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("use them with inspect --ir or --effects"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  r = mxc("inspect --ir " + doc + " --set base_color=0.1,0.2,0.3");
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(InspectCommand, InvalidDocumentExitsOneWithPositionAndNoReport) {
  fs::path bad = writeTemp("bad.mtlx", mtlx("  <add name=\"a\" type=\"float\">\n    <input name=\"in1\" type=\"float\" nodename=\"zz\"/>\n  </add>\n"));
  CommandRun r = mxc("inspect " + bad.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find(bad.string() + ":4:46: error: 'in1' connects to node 'zz'"), std::string::npos) << r.err;
  // The source line and a caret under the column follow the message.
  EXPECT_NE(r.err.find(" 4 |     <input name=\"in1\" type=\"float\" nodename=\"zz\"/>\n   | " + std::string(45, ' ') + "^"),
            std::string::npos)
      << r.err;
  CommandRun partial = mxc("inspect --partial " + bad.string());
  EXPECT_EQ(partial.exitCode, 1);
  EXPECT_NE(partial.out.find("1 error, 0 warnings"), std::string::npos);
  fs::remove(bad);
}

TEST(InspectCommand, MalformedXmlExitsOne) {
  fs::path bad = writeTemp("broken.mtlx", "<materialx version=\"1.39\">\n  <nodegraph name=\"x\">\n</materialx>\n");
  CommandRun r = mxc("inspect " + bad.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(":3:1: error: mismatched end tag </materialx>: the open element is <nodegraph>"), std::string::npos) << r.err;
  fs::remove(bad);
}

TEST(InspectCommand, UsageErrorsExitTwo) {
  EXPECT_EQ(mxc("").exitCode, 2);
  EXPECT_EQ(mxc("inspect").exitCode, 2);
  EXPECT_EQ(mxc("inspect --no-such-flag x.mtlx").exitCode, 2);
  EXPECT_EQ(mxc("frobnicate").exitCode, 2);
  EXPECT_EQ(mxc("inspect --json --dot x.mtlx").exitCode, 2);
  CommandRun help = mxc("--help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("inspect"), std::string::npos);
  EXPECT_NE(help.out.find("Exit codes"), std::string::npos);
  EXPECT_EQ(mxc("inspect --help").exitCode, 0);
}

TEST(InspectCommand, MissingFileExitsOne) {
  CommandRun r = mxc("inspect /no/such/document.mtlx");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cannot read '/no/such/document.mtlx'"), std::string::npos) << r.err;
}

TEST(InspectCommand, OutputFileIsWrittenWholeOrNotAtAll) {
  TempFolder folder("report");
  const fs::path out = folder / "report.json";
  std::ofstream(out) << "previous";
  // A failing run leaves the previous file as it was.
  fs::path bad = writeTemp("bad2.mtlx", mtlx("  <constant name=\"a\" type=\"float\"><input name=\"value\" type=\"float\" "
                                            "value=\"x\"/></constant>\n"));
  EXPECT_EQ(mxc("inspect --json -o " + out.string() + " " + bad.string()).exitCode, 1);
  std::ifstream before(out);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(before), {}), "previous");
  // A good run replaces it with a complete report, and no temporary file is left behind.
  EXPECT_EQ(mxc("inspect --json -o " + out.string() + " " + corpus("openpbr-presets/open_pbr_glass.mtlx")).exitCode, 0);
  std::ifstream after(out);
  nlohmann::json j = nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(after), {}));
  EXPECT_EQ(j["schema"], "mxc-inspect-1");
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"report.json"}));
  // An output folder that does not exist is an output failure (3), not a document error.
  EXPECT_EQ(mxc("inspect -o /no/such/folder/r.txt " + corpus("openpbr-presets/open_pbr_glass.mtlx")).exitCode, 3);
  fs::remove(bad);
}

// A node of a category no nodedef defines is read with a warning (MaterialX reads it so): inspect
// exits 0; compiling a material that needs it exits 1, naming the node.
TEST(InspectCommand, AnUnknownCategoryIsAWarningUntilAMaterialNeedsIt) {
  TempFolder folder("unknown");
  writeText(folder / "light.mtlx", mtlx("  <lightcompoundtest name=\"rig\" type=\"lightshader\"/>\n"
                                        "  <open_pbr_surface name=\"s\" type=\"surfaceshader\"/>\n"
                                        "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                                        "type=\"surfaceshader\" nodename=\"s\"/></surfacematerial>\n"));
  CommandRun inspect = mxc("inspect " + (folder / "light.mtlx").string());
  EXPECT_EQ(inspect.exitCode, 0) << inspect.err;
  EXPECT_NE(inspect.err.find("light.mtlx:3:3: warning: unknown node category <lightcompoundtest>"), std::string::npos) << inspect.err;
  EXPECT_EQ(mxc("compile " + (folder / "light.mtlx").string() + " -o " + (folder / "m.spv").string()).exitCode, 0);
  writeText(folder / "shader.mtlx", mtlx("  <mystery_surface name=\"s\" type=\"surfaceshader\"/>\n"
                                         "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                                         "type=\"surfaceshader\" nodename=\"s\"/></surfacematerial>\n"));
  EXPECT_EQ(mxc("inspect " + (folder / "shader.mtlx").string()).exitCode, 0);
  CommandRun compile = mxc("compile " + (folder / "shader.mtlx").string() + " -o " + (folder / "s.spv").string());
  EXPECT_EQ(compile.exitCode, 1);
  EXPECT_NE(compile.err.find("shader.mtlx:3:3: error: node 's' is a <mystery_surface>, which no nodedef defines"),
            std::string::npos)
      << compile.err;
  EXPECT_FALSE(fs::exists(folder / "s.spv"));
}

TEST(InspectCommand, LibraryFolderOptions) {
  const std::string mx = (sharedDir() / "reference/materialx/libraries").string();
  CommandRun r = mxc("inspect --no-builtin --library " + mx + " " + corpus("materialx/examples/OpenPbr/open_pbr_glass.mtlx"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("libraries  " + mx + " ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("materialx/libraries/bxdf/open_pbr_surface.mtlx"), std::string::npos);
  EXPECT_EQ(mxc("inspect --no-builtin " + corpus("materialx/examples/OpenPbr/open_pbr_glass.mtlx")).exitCode, 1);
  CommandRun missing = mxc("inspect --library /no/such/lib " + corpus("materialx/examples/OpenPbr/open_pbr_glass.mtlx"));
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("cannot read the library '/no/such/lib'"), std::string::npos);
}

TEST(InspectCommand, IncludesAndLooksAreReported) {
  CommandRun r = mxc("inspect " + corpus("materialx/examples/StandardSurface/standard_surface_look_wood_tiled.mtlx"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("includes   standard_surface_wood_tiled.mtlx"), std::string::npos);
  EXPECT_NE(r.out.find("look Wood_Look"), std::string::npos);
  EXPECT_NE(r.out.find("materialassign preview: material Tiled_Wood -> geom \"Preview_Mesh\""), std::string::npos);
  EXPECT_NE(r.out.find("material Tiled_Wood"), std::string::npos);
}

TEST(InspectCommand, IrTreeAndJson) {
  CommandRun text = mxc("inspect --ir " + corpus("materialx/examples/OpenPbr/open_pbr_glass.mtlx"));
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("material Glass (open_pbr_surface, line 6)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("effects: dispersion (transmission_dispersion_scale line 11), specular"), std::string::npos);
  EXPECT_NE(text.out.find("top: #0 dielectric RT ior=1.52"), std::string::npos);
  EXPECT_NE(text.out.find("medium: bulk ior=1.52 abbe_number=64"), std::string::npos) << text.out;

  EXPECT_EQ(text.out.rfind("accuracy: balanced (", 0), 0u) << text.out;

  CommandRun json = mxc("inspect --ir --json " + corpus("materialx/examples/OpenPbr/open_pbr_carpaint.mtlx"));
  ASSERT_EQ(json.exitCode, 0) << json.err;
  nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["schema"], "mxc-ir-1");
  EXPECT_EQ(j["accuracy"]["tier"], "balanced");
  ASSERT_EQ(j["materials"].size(), 1u);
  const nlohmann::json& m = j["materials"][0];
  EXPECT_EQ(m["name"], "Car_Paint");
  std::vector<std::string> effects;
  for (const auto& e : m["effects"]) effects.push_back(e["name"]);
  EXPECT_EQ(effects, (std::vector<std::string>{"coat", "diffuse", "specular"}));
  EXPECT_EQ(m["effects"][0]["input"], "coat_weight");
  // slab(coat) over slab(gloss) over slab(diffuse): each slab has top, medium, base, coverage.
  const nlohmann::json& coat = m["root"];
  EXPECT_EQ(coat["kind"], "slab");
  EXPECT_EQ(coat["top"]["kind"], "bsdf");
  EXPECT_EQ(coat["top"]["bsdf"], "dielectric");
  EXPECT_EQ(coat["top"]["scatter"], "RT");
  EXPECT_EQ(coat["top"]["params"]["ior"]["value"], 1.6f);
  EXPECT_TRUE(coat["medium"].is_null());
  EXPECT_TRUE(coat.contains("coverage"));
  EXPECT_EQ(coat["base"]["base"]["top"]["bsdf"], "diffuse");
  EXPECT_EQ(coat["base"]["base"]["top"]["model"], "eon");
  EXPECT_TRUE(coat["base"]["base"]["base"].is_null());
}

TEST(InspectCommand, IrThroughMaterialXGraphsNeedsTheirLibrary) {
  const std::string mx = (sharedDir() / "reference/materialx/libraries").string();
  CommandRun r = mxc("inspect --ir --shading-model-graphs --library " + mx + " " +
                     corpus("materialx/examples/OpenPbr/open_pbr_default.mtlx"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("[dielectric_reflection "), std::string::npos) << r.out;  // from MaterialX's graph
  EXPECT_EQ(mxc("inspect --shading-model-graphs " + corpus("materialx/examples/OpenPbr/open_pbr_default.mtlx")).exitCode,
            2);  // needs --ir
}

}  // namespace
}  // namespace mxc::test

namespace mxc::test {
namespace {

// --accuracy is shown by inspect, with what the tier does; the IR itself does not change.
TEST(InspectCommand, ShowsTheAccuracyTier) {
  const std::string doc = corpus("materialx/examples/OpenPbr/open_pbr_glass.mtlx");
  CommandRun fast = mxc("inspect --ir --accuracy fast " + doc);
  CommandRun balanced = mxc("inspect --ir --accuracy balanced " + doc);
  ASSERT_EQ(fast.exitCode, 0) << fast.err;
  ASSERT_EQ(balanced.exitCode, 0) << balanced.err;
  EXPECT_EQ(fast.out.rfind("accuracy: fast (", 0), 0u) << fast.out;
  EXPECT_NE(fast.out.find("no multiple-scattering compensation"), std::string::npos);
  EXPECT_EQ(fast.out.substr(fast.out.find("\n\n")), balanced.out.substr(balanced.out.find("\n\n")));
  CommandRun bad = mxc("inspect --ir --accuracy exact " + doc);
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--accuracy"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace mxc::test
