// The commands that compile and run materials: compile, render, eval, furnace. Their outputs,
// their exit codes, and that nothing half-written is left behind on failure.

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <set>
#include <tuple>

#include <nlohmann/json.hpp>

#include "runtime/ImageIO.h"
#include "support/CommandSupport.h"
#include "support/RenderCommandSupport.h"

namespace mxc::test {
namespace {

const std::string kDefault = "materialx/examples/OpenPbr/open_pbr_default.mtlx";

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(CompileCommand, WritesValidSpirvAndGlsl) {
  const fs::path spv = writeTemp("out.spv", "");
  const fs::path frag = writeTemp("out.frag", "");
  CommandRun r = mxc("compile " + corpus(kDefault) + " -o " + spv.string() + " --glsl " + frag.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Default: raster shader"), std::string::npos) << r.out;
  const std::string words = readAll(spv);
  ASSERT_GE(words.size(), 20u);
  EXPECT_EQ(static_cast<unsigned char>(words[0]), 0x03);  // SPIR-V magic 0x07230203, little-endian
  EXPECT_EQ(static_cast<unsigned char>(words[3]), 0x07);
  const std::string glsl = readAll(frag);
  EXPECT_EQ(glsl.rfind("#version 400", 0), 0u);
  EXPECT_NE(glsl.find("void mxc_material_closure("), std::string::npos);
  fs::remove(spv);
  fs::remove(frag);
}

// Every --stage gives its own shader: the compute stages differ by their main only.
TEST(CompileCommand, EachStageHasItsMain) {
  for (const auto& [stage, kind, marker] :
       {std::tuple{"comp", "eval", "mxc_out[i] = vec4(f, pdf)"},
        std::tuple{"furnace", "furnace", "vec3 transmitted ="},
        std::tuple{"sample", "sample", "float kind = smp.valid"}}) {
    const fs::path glsl = writeTemp(std::string("out_") + stage + ".comp", "");
    CommandRun r = mxc("compile " + corpus(kDefault) + " --stage " + stage + " --glsl " + glsl.string());
    EXPECT_EQ(r.exitCode, 0) << stage << ": " << r.err;
    EXPECT_NE(r.out.find(std::string("Default: ") + kind + " shader"), std::string::npos) << r.out;
    const std::string text = readAll(glsl);
    EXPECT_NE(text.find(marker), std::string::npos) << stage;
    fs::remove(glsl);
  }
  CommandRun r = mxc("compile " + corpus(kDefault) + " --stage vertex");
  EXPECT_EQ(r.exitCode, 2) << r.err;
}

// --accuracy chooses the tier on every command that compiles: its GLSL says which, the fast
// tier's reads no albedo table, and a white rough metal's furnace shows what the tier costs in
// energy (single scattering loses 1 - E; balanced compensates).
TEST(CompileCommand, AccuracyChoosesTheTier) {
  for (const char* tier : {"fast", "balanced", "reference"}) {
    const fs::path glsl = writeTemp(std::string("tier_") + tier + ".frag", "");
    CommandRun r = mxc("compile " + corpus(kDefault) + " --accuracy " + tier + " --glsl " + glsl.string());
    ASSERT_EQ(r.exitCode, 0) << tier << ": " << r.err;
    const std::string text = readAll(glsl);
    std::string macro = std::string("#define MXC_ACCURACY_") + tier;
    for (size_t i = macro.size() - std::string(tier).size(); i < macro.size(); ++i) macro[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(macro[i])));
    EXPECT_NE(text.find(macro), std::string::npos) << tier;
    fs::remove(glsl);
  }
  CommandRun bad = mxc("compile " + corpus(kDefault) + " --accuracy reference-ish");
  EXPECT_EQ(bad.exitCode, 2) << bad.err;

  const fs::path doc = writeTemp("white_metal.mtlx", R"(<?xml version="1.0"?>
<materialx version="1.39">
  <open_pbr_surface name="s" type="surfaceshader">
    <input name="base_metalness" type="float" value="1" />
    <input name="base_color" type="color3" value="1, 1, 1" />
    <input name="specular_roughness" type="float" value="1" />
  </open_pbr_surface>
  <surfacematerial name="m" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s" /></surfacematerial>
</materialx>
)");
  double albedo[3] = {0.0, 0.0, 0.0};
  const char* tiers[3] = {"fast", "balanced", "reference"};
  for (int k = 0; k < 3; ++k) {
    CommandRun r = mxc("furnace " + doc.string() + " --angles 1 --samples " + (k == 2 ? "4096" : "65536") + " --accuracy " +
                       tiers[k]);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(r.out);
    const nlohmann::json& m = j.contains("materials") ? j["materials"][0] : j;
    albedo[k] = m["angles"][0]["total"][1].get<double>();
  }
  EXPECT_NEAR(albedo[0], 1.0 - std::log(2.0), 0.02);  // physics notes 2.2: E(mu = 1) at roughness 1
  EXPECT_NEAR(albedo[1], 1.0, 0.02);
  EXPECT_NEAR(albedo[2], 1.0, 1e-4);  // every order of scattering on the microsurface, F = 1
  // eval on the reference tier averages --reference-samples walks: finite, non-negative.
  const fs::path dirs = writeTemp("ref_dirs.csv", "0,0,1,0.6,0,0.8\n0.5,0,0.866,-0.5,0,0.866\n");
  CommandRun e = mxc("eval " + doc.string() + " --dirs " + dirs.string() + " --accuracy reference --reference-samples 64");
  ASSERT_EQ(e.exitCode, 0) << e.err;
  EXPECT_NE(e.out.find("material,row,fcos_r"), std::string::npos) << e.out;
  EXPECT_EQ(e.out.find("nan"), std::string::npos) << e.out;
  fs::remove(dirs);
  fs::remove(doc);
}

TEST(CompileCommand, BadSetIsAnErrorAtTheShadingNode) {
  const fs::path spv = fs::temp_directory_path() / ("mxc_cli_none_" + std::to_string(::getpid()) + ".spv");
  CommandRun r = mxc("compile " + corpus(kDefault) + " --set nonsense=1 -o " + spv.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("open_pbr_default.mtlx:7:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("has no input named 'nonsense'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(spv)) << "nothing is written for a failed compile";
  // A value that is not of the input's type: said once, at the argument, with no source line.
  r = mxc("compile " + corpus(kDefault) + " --set base_color=red -o " + spv.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(r.err.rfind("error: --set base_color=red: 'red' is not a color3\n", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find("error:", 1), std::string::npos) << "reported once: " << r.err;
  EXPECT_FALSE(fs::exists(spv));
  r = mxc("compile " + corpus(kDefault) + " --set base_color");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("expected INPUT=VALUE"), std::string::npos) << r.err;
  r = mxc("compile " + corpus(kDefault) + " --material Nope");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("has no material 'Nope' (it has: Default)"), std::string::npos) << r.err;
}

// --set on a document of several materials applies to those whose shading node has the input
// and says which when some lack it; an input none of them has is one error naming them all.
TEST(CompileCommand, SetOnSeveralMaterialsSaysWhichItAppliesTo) {
  const fs::path doc = writeTemp("two_models.mtlx",
                                 "<materialx version=\"1.39\">\n"
                                 "  <open_pbr_surface name=\"o\" type=\"surfaceshader\"/>\n"
                                 "  <surfacematerial name=\"A\" type=\"material\"><input name=\"surfaceshader\" "
                                 "type=\"surfaceshader\" nodename=\"o\"/></surfacematerial>\n"
                                 "  <standard_surface name=\"s\" type=\"surfaceshader\"/>\n"
                                 "  <surfacematerial name=\"B\" type=\"material\"><input name=\"surfaceshader\" "
                                 "type=\"surfaceshader\" nodename=\"s\"/></surfacematerial>\n"
                                 "</materialx>\n");
  TempFolder out("set_several");
  CommandRun r = mxc("compile " + doc.string() + " --set base_color=0.5,0.5,0.5 --set coat_weight=1 -o " +
                     (out / "m.spv").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("note: --set coat_weight=1 applies to A; not to B (<standard_surface>)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("base_color"), std::string::npos) << "both have base_color: nothing to say: " << r.err;
  EXPECT_TRUE(fs::exists(out / "m_A.spv") && fs::exists(out / "m_B.spv"));
  r = mxc("compile " + doc.string() + " --set nonsense=1 -o " + (out / "n.spv").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("error: --set nonsense=1: no material's shading node has an input named 'nonsense': "
                       "A (<open_pbr_surface>), B (<standard_surface>)"),
            std::string::npos)
      << r.err;
  fs::remove(doc);
}

// Two materials of one document whose shaders have the same code compile once: the second
// takes the first's module (ShaderCache), the same bytes.
TEST(CompileCommand, MaterialsOfTheSameShaderCodeCompileOnce) {
  const fs::path doc = writeTemp("one_shader.mtlx", kTwoMaterialsOfOneShader);
  TempFolder out("one_shader");
  CommandRun r = mxc("compile " + doc.string() + " -v -o " + (out / "m.spv").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("A: SPIR-V compiled and validated"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("B: SPIR-V of a shader with the same code, compiled for another material, taken"),
            std::string::npos)
      << r.err;
  const std::string a = readFileBytes(out / "m_A.spv");
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, readFileBytes(out / "m_B.spv"));
  fs::remove(doc);
}

// Beside the SPIR-V, compile writes what a host renderer needs: the interface JSON naming the
// files it goes with, the vertex stage, and with --tables the albedo tables in their format.
TEST(CompileCommand, WritesTheInterfaceVertexStageAndTablesForAHost) {
  TempFolder folder("interface");
  CommandRun r = mxc("compile " + corpus(kDefault) + " -o " + (folder / "m.spv").string() + " --tables " +
                     (folder / "tables").string() + " --param base_color");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(fs::is_regular_file(folder / "m.json"));
  const nlohmann::json j = nlohmann::json::parse(readAll(folder / "m.json"));
  EXPECT_EQ(j["schema"], "mxc-shader-interface-1");
  EXPECT_EQ(j["stages"]["fragment"]["spirv"], "m.spv");
  EXPECT_EQ(j["stages"]["vertex"]["spirv"], "m.vert.spv");
  EXPECT_EQ(j["tables"][0]["file"], "tables/mxc_albedo_tables.bin");
  EXPECT_EQ(readAll(folder / "m.vert.spv").substr(0, 4), std::string("\x03\x02\x23\x07", 4));
  const std::string tables = readAll(folder / "tables/mxc_albedo_tables.bin");
  EXPECT_EQ(tables.substr(0, 8), "MXCTAB01");
  const size_t texels = size_t(j["tables"][0]["width"].get<int>()) * size_t(j["tables"][0]["height"].get<int>());
  EXPECT_EQ(tables.size(), 28 + texels * 4 * sizeof(float)) << "header, then RGBA float32 texels";
  bool kept = false;
  for (const auto& d : j["descriptors"]) {
    if (d["name"] != "MxcParameters") continue;
    for (const auto& m : d["members"]) kept = kept || (m.contains("input") && m["input"] == "base_color");
  }
  EXPECT_TRUE(kept) << "--param base_color is a member naming its input";
  // --param-all: every input of the shading node with a value is a member naming its input.
  r = mxc("compile " + corpus(kDefault) + " -o " + (folder / "all.spv").string() + " --param-all");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json all = nlohmann::json::parse(readAll(folder / "all.json"));
  std::set<std::string> inputs;
  for (const auto& d : all["descriptors"]) {
    if (d["name"] != "MxcParameters") continue;
    for (const auto& m : d["members"]) {
      if (m.contains("input")) inputs.insert(m["input"].get<std::string>());
    }
  }
  for (const char* input : {"base_color", "base_weight", "specular_roughness", "coat_weight", "transmission_weight",
                            "thin_film_thickness", "emission_luminance", "geometry_opacity"}) {
    EXPECT_TRUE(inputs.count(input)) << input;
  }
  EXPECT_GT(inputs.size(), 30u);
  // A compute stage has no vertex stage.
  r = mxc("compile " + corpus(kDefault) + " --stage comp -o " + (folder / "c.spv").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(folder / "c.json"));
  EXPECT_FALSE(fs::exists(folder / "c.vert.spv"));
}

// --set and --param reach the interface inputs of a document's node graphs: brick_color of
// NG_BrickPattern, unqualified (the shading node has no brick_color) or as GRAPH.INPUT.
TEST(CompileCommand, SetAndParamReachAGraphsInterfaceInputs) {
  const std::string brick = corpus("materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx");
  // Kept variable, the graph's input is a parameter named after the graph and the input, whose
  // default is the --set value (unqualified) or the document's.
  TempFolder folder("graph_param");
  auto defaultOf = [&](const std::string& arguments) {
    CommandRun run = mxc("compile " + brick + " " + arguments + " -o " + (folder / "b.spv").string());
    EXPECT_EQ(run.exitCode, 0) << run.err;
    const nlohmann::json j = nlohmann::json::parse(readAll(folder / "b.json"));
    for (const auto& d : j["descriptors"]) {
      if (d["name"] != "MxcParameters") continue;
      for (const auto& m : d["members"]) {
        if (m.contains("graph") && m["graph"] == "NG_BrickPattern" && m["input"] == "brick_color") {
          return m["default"].get<std::vector<float>>();
        }
      }
    }
    return std::vector<float>{};
  };
  EXPECT_EQ(defaultOf("--param NG_BrickPattern.brick_color --set brick_color=0.125,0.5,0.875"),
            (std::vector<float>{0.125f, 0.5f, 0.875f}));
  const std::vector<float> document = defaultOf("--param brick_color");
  ASSERT_EQ(document.size(), 3u) << "found by its unqualified name too";
  EXPECT_NEAR(document[0], 0.661876f, 1e-5f) << "the document's brick_color";
  CommandRun r;
  r = mxc("compile " + brick + " --set NG_BrickPattern.brick_color=red");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("error: --set NG_BrickPattern.brick_color=red: 'red' is not a color3"), std::string::npos) << r.err;
  r = mxc("compile " + brick + " --set nonsense=1");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("graph inputs: "), std::string::npos) << "the error lists what can be set: " << r.err;
  EXPECT_NE(r.err.find("NG_BrickPattern.brick_color"), std::string::npos) << r.err;
}

// A document of definitions or node graphs only is valid and has nothing to compile: compile
// says so and succeeds, writing nothing; render, which needs a shader, refuses it.
TEST(CompileCommand, ADocumentWithoutAShaderHasNothingToCompile) {
  const fs::path doc = writeTemp("graph_only.mtlx",
                                 "<materialx version=\"1.39\">\n  <constant name=\"c\" type=\"color3\"/>\n"
                                 "  <output name=\"out\" type=\"color3\" nodename=\"c\"/>\n</materialx>\n");
  const fs::path spv = fs::temp_directory_path() / ("mxc_cli_nothing_" + std::to_string(::getpid()) + ".spv");
  CommandRun r = mxc("compile " + doc.string() + " -o " + spv.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("nothing to compile: " + doc.string() + " has no material and no surface shader"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(spv));
  r = mxc("render " + doc.string() + " -o " + spv.string() + ".png");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("has no material and no surface shader to compile"), std::string::npos) << r.err;
  fs::remove(doc);
}

// nprlib's viewdirection (-wo) and stdlib's reflect, read on the device: an unlit sphere whose
// red is the facing ratio -V.N (1 at the centre, falling to 0 at the rim) and whose green is
// the z of the view direction reflected about N (for a camera on +z, R = V - 2 (V.N) N: +1 at
// the centre, where it goes back to the camera, falling towards the rim; stored as (R.z + 1) / 2
// so it is non-negative).
TEST(RenderCommand, ViewDirectionAndReflectReachTheShader) {
  const fs::path doc = writeTemp(
      "view_direction.mtlx",
      "<materialx version=\"1.39\">\n"
      "  <viewdirection name=\"v\" type=\"vector3\"/>\n"
      "  <normal name=\"n\" type=\"vector3\"><input name=\"space\" type=\"string\" value=\"world\"/></normal>\n"
      "  <dotproduct name=\"vn\" type=\"float\"><input name=\"in1\" type=\"vector3\" nodename=\"v\"/>"
      "<input name=\"in2\" type=\"vector3\" nodename=\"n\"/></dotproduct>\n"
      "  <multiply name=\"facing\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"vn\"/>"
      "<input name=\"in2\" type=\"float\" value=\"-1\"/></multiply>\n"
      "  <reflect name=\"r\" type=\"vector3\"><input name=\"in\" type=\"vector3\" nodename=\"v\"/></reflect>\n"
      "  <extract name=\"rz\" type=\"float\"><input name=\"in\" type=\"vector3\" nodename=\"r\"/>"
      "<input name=\"index\" type=\"integer\" value=\"2\"/></extract>\n"
      "  <multiply name=\"rz01\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"rzp1\"/>"
      "<input name=\"in2\" type=\"float\" value=\"0.5\"/></multiply>\n"
      "  <add name=\"rzp1\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"rz\"/>"
      "<input name=\"in2\" type=\"float\" value=\"1\"/></add>\n"
      "  <combine3 name=\"rgb\" type=\"color3\"><input name=\"in1\" type=\"float\" nodename=\"facing\"/>"
      "<input name=\"in2\" type=\"float\" nodename=\"rz01\"/></combine3>\n"
      "  <surface_unlit name=\"s\" type=\"surfaceshader\"><input name=\"emission_color\" type=\"color3\" "
      "nodename=\"rgb\"/></surface_unlit>\n"
      "  <surfacematerial name=\"m\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
      "nodename=\"s\"/></surfacematerial>\n"
      "</materialx>\n");
  const rt::RgbaImage image = renderCommand(doc.string() + " --size 64 --spp 1 --env none --light none");
  ASSERT_EQ(image.width, 64u);
  const float* centre = image.at(32, 32);
  EXPECT_NEAR(centre[0], 1.0f, 0.02f) << "facing ratio at the centre";
  EXPECT_NEAR(centre[1], 1.0f, 0.02f) << "(R.z + 1) / 2 at the centre: R points back at the camera";
  // Towards the rim (still on the sphere) the facing ratio falls and R turns away from +z.
  const float* side = image.at(32 + 18, 32);
  ASSERT_GT(side[3], 0.0f) << "the sample is on the sphere";
  EXPECT_LT(side[0], 0.9f * centre[0]);
  EXPECT_LT(side[1], centre[1] - 0.05f);
  fs::remove(doc);
}

TEST(FurnaceCommand, PrintsAlbedoPerAngleAsJson) {
  CommandRun r = mxc("furnace " + corpus(kDefault) + " --angles 3 --samples 4096 --set base_color=1,1,1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["materials"].size(), 1u);
  const auto& angles = j["materials"][0]["angles"];
  ASSERT_EQ(angles.size(), 3u);
  EXPECT_DOUBLE_EQ(angles[0]["theta_deg"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(angles[1]["theta_deg"].get<double>(), 30.0);
  for (const auto& a : angles) EXPECT_NEAR(a["total"][1].get<double>(), 1.0, 0.01);  // white base: lossless
}

TEST(EvalCommand, PrintsFCosPerRowAndReportsBadRows) {
  const fs::path dirs = writeTemp("dirs.csv", "wo_x,wo_y,wo_z,wi_x,wi_y,wi_z\n0,0,1, 0,0,1\n# below\n0,0,1,0.6,0,-0.8\n");
  CommandRun r = mxc("eval " + corpus(kDefault) + " --dirs " + dirs.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::stringstream lines(r.out);
  std::string header, row1, row2;
  std::getline(lines, header);
  std::getline(lines, row1);
  std::getline(lines, row2);
  EXPECT_EQ(header, "material,row,fcos_r,fcos_g,fcos_b,pdf");
  EXPECT_EQ(row1.rfind("Default,1,", 0), 0u) << row1;
  float r1 = 0, g1 = 0, b1 = 0, p1 = 0;
  ASSERT_EQ(std::sscanf(row1.c_str(), "Default,1,%f,%f,%f,%f", &r1, &g1, &b1, &p1), 4) << row1;
  EXPECT_GT(r1, 0.2f);  // a diffuse base seen and lit from the normal
  EXPECT_EQ(row2, "Default,2,0,0,0,0");  // an opaque surface does not transmit
  const fs::path bad = writeTemp("bad.csv", "0,0,1,0,0,1\n0,0,1,0,x,1\n");
  r = mxc("eval " + corpus(kDefault) + " --dirs " + bad.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(bad.string() + ":2:9: error: expected a number as value 5 of 6"), std::string::npos) << r.err;
  fs::remove(dirs);
  fs::remove(bad);
}

// A material of delta lobes only (a smooth metal) has f cos = 0 at every pair eval can be given:
// eval says why its zeros are right and points to furnace; a rough one gets no such note.
TEST(EvalCommand, SaysWhenEveryLobeIsADelta) {
  const fs::path dirs = writeTemp("delta_dirs.csv", "0,0,1,0,0,1\n0,0.6,0.8,0,-0.6,0.8\n");
  CommandRun r = mxc("eval " + corpus(kDefault) + " --dirs " + dirs.string() +
                     " --set base_metalness=1 --set specular_roughness=0");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Default,2,0,0,0,0"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("note: Default: every lobe is a delta"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'mxc furnace'"), std::string::npos) << r.err;
  r = mxc("eval " + corpus(kDefault) + " --dirs " + dirs.string() + " --set base_metalness=1");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("delta"), std::string::npos) << r.err;
  fs::remove(dirs);
}

TEST(RenderCommand, WritesAFiniteImage) {
  const fs::path exr = fs::temp_directory_path() / ("mxc_cli_render_" + std::to_string(::getpid()) + ".exr");
  CommandRun r = mxc("render " + corpus(kDefault) + " -o " + exr.string() + " --size 32 --spp 2 --env white --validation");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("32x32, 2 spp"), std::string::npos) << r.out;
  auto image = rt::readImage(exr);
  ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(image));
  const rt::RgbaImage& img = std::get<rt::RgbaImage>(image);
  EXPECT_EQ(img.width, 32u);
  EXPECT_GT(img.at(16, 16)[3], 0.99f);  // the sphere covers the centre
  EXPECT_EQ(img.at(0, 0)[3], 0.0f);     // and not the corner
  fs::remove(exr);
  r = mxc("render " + corpus(kDefault) + " -o " + exr.string() + " --light sun:1,1,1");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--light sun:1,1,1: expected dir:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(exr));
}

// --exposure scales the rendered radiance of an 8-bit output, not the constant background under
// it: the corner keeps the background's code value, the lit sphere gets brighter.
/// `mxc render` of the default material into temporary file `name` with `options`, read back
/// (empty when the command or the read failed, which the expectations report).
rt::RgbaImage renderDefault(const std::string& name, const std::string& options) {
  const fs::path out = writeTemp(name, "");
  CommandRun r = mxc("render " + corpus(kDefault) + " -o " + out.string() + " " + options);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  auto image = rt::readImage(out);
  fs::remove(out);
  EXPECT_TRUE(std::holds_alternative<rt::RgbaImage>(image));
  return std::holds_alternative<rt::RgbaImage>(image) ? std::get<rt::RgbaImage>(image) : rt::RgbaImage{};
}

TEST(RenderCommand, ExposureScalesTheRenderNotTheBackground) {
  auto render = [](const std::string& exposure) {
    return renderDefault("exposure" + exposure + ".png",
                         "--size 32 --spp 1 --env sky --background 0.5,0.5,0.5 --exposure " + exposure);
  };
  const rt::RgbaImage plain = render("0"), brighter = render("1.5");
  ASSERT_EQ(plain.width, 32u);
  ASSERT_EQ(brighter.width, 32u);
  // The background as 8-bit outputs encode it: tone curve, then sRGB.
  const float background = rt::linearToSrgb(rt::acesFit(0.5f));
  for (const rt::RgbaImage* img : {&plain, &brighter}) EXPECT_NEAR(img->at(0, 0)[1], background, 1.0f / 255.0f);
  EXPECT_GT(brighter.at(16, 16)[1], plain.at(16, 16)[1] + 0.05f);
}

/// An equirectangular EXR of one colour (with `bad` NaN values), w x h, in the temporary folder.
fs::path environmentImage(const std::string& name, uint32_t w, uint32_t h, int bad = 0) {
  rt::RgbaImage image{w, h, {}};
  for (uint32_t i = 0; i < w * h; ++i) image.pixels.insert(image.pixels.end(), {0.2f, 0.4f, 0.8f, 1.0f});
  for (int k = 0; k < bad; ++k) image.pixels[size_t(k) * 4] = std::nanf("");
  const fs::path path = writeTemp(name, "");
  EXPECT_EQ(rt::writeImage(path, image), std::nullopt);
  return path;
}

// An environment image lights the material and, unless --background says otherwise, is the
// background of every output (EXR included; its alpha stays the coverage), scaled by
// --env-intensity.
TEST(RenderCommand, EnvironmentImageLightsAndFillsTheBackground) {
  const fs::path env = environmentImage("env.exr", 32, 16);
  auto render = [&](const std::string& options) {
    return renderDefault("env-render.exr", "--size 32 --spp 2 --env " + env.string() + " " + options);
  };
  const rt::RgbaImage plain = render(""), doubled = render("--env-intensity 2 --env-rotation 90");
  ASSERT_EQ(plain.width, 32u);
  ASSERT_EQ(doubled.width, 32u);
  const float want[3] = {0.2f, 0.4f, 0.8f};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(plain.at(0, 0)[c], want[c], 1e-4f);
    EXPECT_NEAR(doubled.at(0, 0)[c], 2.0f * want[c], 2e-4f);
  }
  EXPECT_EQ(plain.at(0, 0)[3], 0.0f);
  EXPECT_GT(plain.at(16, 16)[3], 0.999f);
  // The sphere is lit by the blue environment alone (no default key light with an image).
  EXPECT_GT(plain.at(16, 16)[2], plain.at(16, 16)[0]);
  fs::remove(env);
}

TEST(RenderCommand, RefusesEnvironmentImagesItCannotUse) {
  const fs::path square = environmentImage("square.exr", 16, 16);
  const fs::path nan = environmentImage("nan.exr", 16, 8, 3);
  const fs::path missing = fs::temp_directory_path() / "mxc-no-such-environment.exr";
  const std::vector<std::pair<fs::path, std::string>> cases = {
      {square, "not an equirectangular"}, {nan, "3 values are NaN or infinite"}, {missing, missing.string()}};
  for (const auto& [env, message] : cases) {
    const fs::path png = fs::temp_directory_path() / "mxc-refused-env.png";
    fs::remove(png);
    CommandRun r = mxc("render " + corpus(kDefault) + " -o " + png.string() + " --size 16 --spp 1 --env " + env.string());
    EXPECT_EQ(r.exitCode, 1) << env << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--env"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(png)) << "nothing is written when the environment is refused";
  }
  fs::remove(square);
  fs::remove(nan);
}

TEST(RenderCommand, RendersTheShaderBallFoundOnTheSearchPath) {
  const fs::path tree = sharedDir() / "conformance/materialx-tree";
  if (!fs::exists(tree / "resources/Geometry/shaderball.glb")) GTEST_SKIP() << "no shader ball under " << tree;
  // By --search-path, and by MATERIALX_SEARCH_PATH (after an empty and a missing entry).
  for (const auto& [shell, option] : {std::pair<std::string, std::string>{"", "--search-path " + tree.string()},
                                      {"MATERIALX_SEARCH_PATH=:/nonexistent:" + tree.string(), ""}}) {
    const fs::path out = writeTemp("ball.exr", "");
    CommandRun r = mxc("render " + corpus(kDefault) + " -o " + out.string() + " --mesh shaderball --size 48x32 --spp 1 " + option, shell);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto read = rt::readImage(out);
    fs::remove(out);
    ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(read));
    const rt::RgbaImage& image = std::get<rt::RgbaImage>(read);
    ASSERT_EQ(image.width, 48u);
    ASSERT_EQ(image.height, 32u);
    // Framed to fit: the centre is covered, the corners are not, and the ball takes a fair share.
    EXPECT_EQ(image.at(24, 16)[3], 1.0f);
    EXPECT_EQ(image.at(0, 0)[3], 0.0f);
    EXPECT_EQ(image.at(47, 31)[3], 0.0f);
    double covered = 0.0;
    for (uint32_t y = 0; y < 32; ++y) {
      for (uint32_t x = 0; x < 48; ++x) covered += image.at(x, y)[3];
    }
    EXPECT_GT(covered / (48.0 * 32.0), 0.15);
    EXPECT_LT(covered / (48.0 * 32.0), 0.6);
  }
}

TEST(RenderCommand, RefusesBadSizesMeshesAndCamerasWritingNothing) {
  const fs::path png = fs::temp_directory_path() / "mxc-refused-mesh.png";
  const std::vector<std::tuple<std::string, int, std::string>> cases = {
      {"--size 7", 2, "--size 7"},
      {"--size 64x", 2, "expected N or WxH"},
      {"--size 9000x64", 2, "from 8 to 8192"},
      {"--mesh nosuch", 1, "no mesh file named 'nosuch'"},
      {"--mesh nosuch --search-path /nonexistent", 1, "/nonexistent/resources/Geometry/nosuch.glb"},
      {"--mesh /nonexistent/ball.glb", 1, "/nonexistent/ball.glb"},
      {"--camera-position 0,0,3 --camera-up 0,0,1", 2, "along its view direction"},
      {"--camera-position 0,0,0 --camera-target 0,0,0", 2, "at its target"},
      {"--camera-target 1,0,0", 2, "needs --camera-position"},
      {"--camera-position 1,2", 2, "expected X,Y,Z"}};
  for (const auto& [options, code, message] : cases) {
    fs::remove(png);
    CommandRun r = mxc("render " + corpus(kDefault) + " -o " + png.string() + " --spp 1 " + options, "MATERIALX_SEARCH_PATH=");
    EXPECT_EQ(r.exitCode, code) << options << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << options << ": " << r.err;
    EXPECT_FALSE(fs::exists(png)) << options;
  }
}

TEST(RenderCommand, ToneMappingIsChosenAndNamedInTheFile) {
  // The constant background (linear 0.5) as each curve encodes it, and the curve's name in the
  // PNG's text chunks.
  const std::vector<std::pair<std::string, float>> cases = {
      {"none", 0.5f}, {"aces", rt::acesFit(0.5f)}, {"neutral", rt::pbrNeutral(glm::vec3(0.5f)).r}};
  for (const auto& [tone, linear] : cases) {
    const fs::path out = writeTemp("tone.png", "");
    CommandRun r = mxc("render " + corpus(kDefault) + " -o " + out.string() +
                       " --size 16 --spp 1 --background 0.5,0.5,0.5 --tonemap " + tone);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string bytes = readAll(out);
    EXPECT_NE(bytes.find("mxc:tonemap"), std::string::npos) << tone;
    EXPECT_NE(bytes.find(tone), std::string::npos) << tone;
    auto image = rt::readImage(out);
    fs::remove(out);
    ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(image));
    EXPECT_NEAR(std::get<rt::RgbaImage>(image).at(0, 0)[1], rt::linearToSrgb(linear), 1.0f / 255.0f) << tone;
  }
  CommandRun r = mxc("render " + corpus(kDefault) + " -o x.png --tonemap filmic");
  EXPECT_EQ(r.exitCode, 2) << r.err;
}

TEST(RenderCommand, ProgressBarFitsTheTerminalAndIsClearedAtTheEnd) {
  // Under a 40-column pseudo-terminal (util-linux `script`), a render of about two seconds.
  const fs::path out = writeTemp("progress.png", "");
  const fs::path log = writeTemp("progress.log", "");
  const std::string command = std::string(MXC_BINARY) + " render " + corpus(kDefault) + " -o " + out.string() +
                              " --size 256 --spp 48";
  const std::string shell = "script -qc 'stty cols 40; " + command + "' /dev/null > " + log.string();
  ASSERT_EQ(std::system(shell.c_str()), 0);
  const std::string text = readAll(log);
  fs::remove(out);
  fs::remove(log);
  ASSERT_NE(text.find("ETA"), std::string::npos) << text;
  // Each drawing of the bar starts with "\r\033[K" and stays within 39 columns; the last
  // clear comes before the command's own output line.
  const std::string clear = "\r\033[K";
  std::vector<std::string> pieces;
  for (size_t at = 0;;) {
    const size_t next = text.find(clear, at);
    pieces.push_back(text.substr(at, next == std::string::npos ? std::string::npos : next - at));
    if (next == std::string::npos) break;
    at = next + clear.size();
  }
  ASSERT_GE(pieces.size(), 3u) << text;
  for (size_t i = 1; i + 1 < pieces.size(); ++i) EXPECT_LE(pieces[i].size(), 39u) << pieces[i];
  EXPECT_EQ(pieces.back().rfind("Default: wrote", 0), 0u) << pieces.back();
}

}  // namespace
}  // namespace mxc::test
