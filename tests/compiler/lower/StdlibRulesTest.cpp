// Value-node rules (compiler/lower/StdlibRules.cpp) against the formulas of MaterialX's own
// definitions: values worked from them by hand, and MaterialX's own graphs of the same nodes run
// beside the rules (materialxGraphCopy); and the colour spaces of the values they read.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "compiler/ir/Evaluate.h"
#include "compiler/driver/Compiler.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

/// The materials of a document whose unlit surface emits the color3 node `source` among
/// `nodes` (lowered, passes run); the test fails on any error.
std::vector<ir::Material> unlitMaterials(const std::string& nodes, const std::string& source) {
  Context context;
  CompileRequest request;
  request.document = "test.mtlx";
  request.text = mtlx(nodes + "  <surface_unlit name=\"surf\" type=\"surfaceshader\">\n"
                      "    <input name=\"emission_color\" type=\"color3\" nodename=\"" + source + "\"/>\n"
                      "  </surface_unlit>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                      "type=\"surfaceshader\" nodename=\"surf\"/></surfacematerial>\n");
  Compiler compiler(context, std::move(request));
  std::vector<ir::Material> materials = std::move(compiler.materials());
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  return materials;
}

/// The colour a value node `node` (its elements, the node named "v") gives, seen through an
/// unlit surface's emission colour (a float result converted to color3).
std::vector<float> valueOf(const std::string& node, const std::string& type) {
  const std::string convert = type == "color3" ? "" :
      "  <convert name=\"c\" type=\"color3\"><input name=\"in\" type=\"" + type + "\" nodename=\"v\"/></convert>\n";
  std::vector<ir::Material> materials = unlitMaterials(node + convert, type == "color3" ? "v" : "c");
  if (materials.empty()) return {};
  const ir::Material& m = materials[0];
  // A black emission is removed by the passes (dark emission): the value was 0.
  if (m.emissions.empty()) return {0.0f, 0.0f, 0.0f};
  std::optional<ir::Constant> c = ir::evaluateExpr(m.exprs, m.emissions[0].slots.value(ir::Slot::Color));
  return c ? c->v : std::vector<float>{};
}

float floatOf(const std::string& node) {
  std::vector<float> v = valueOf(node, "float");
  return v.empty() ? NAN : v[0];
}

TEST(StdlibRules, TriangleWaveHasPeriodOneAndPeaksAtTheHalves) {
  auto wave = [](float x) {
    return floatOf("  <trianglewave name=\"v\" type=\"float\"><input name=\"in\" type=\"float\" value=\"" +
                   std::to_string(x) + "\"/></trianglewave>\n");
  };
  EXPECT_NEAR(wave(0.0f), 0.0f, 1e-6f);
  EXPECT_NEAR(wave(0.25f), 0.25f, 1e-6f);
  EXPECT_NEAR(wave(0.5f), 0.5f, 1e-6f);
  EXPECT_NEAR(wave(1.25f), 0.25f, 1e-6f);
  EXPECT_NEAR(wave(-0.25f), 0.25f, 1e-6f);  // |x|: symmetric about 0
}

TEST(StdlibRules, Ramp4IsBilinearInTheClampedTextureCoordinate) {
  auto ramp = [](const std::string& texcoord) {
    return floatOf("  <ramp4 name=\"v\" type=\"float\">\n"
                   "    <input name=\"valuetl\" type=\"float\" value=\"1\"/><input name=\"valuetr\" type=\"float\" value=\"2\"/>\n"
                   "    <input name=\"valuebl\" type=\"float\" value=\"3\"/><input name=\"valuebr\" type=\"float\" value=\"4\"/>\n"
                   "    <input name=\"texcoord\" type=\"vector2\" value=\"" + texcoord + "\"/>\n  </ramp4>\n");
  };
  EXPECT_NEAR(ramp("0, 1"), 1.0f, 1e-6f);   // top left
  EXPECT_NEAR(ramp("1, 1"), 2.0f, 1e-6f);   // top right
  EXPECT_NEAR(ramp("0, 0"), 3.0f, 1e-6f);   // bottom left
  EXPECT_NEAR(ramp("1, 0"), 4.0f, 1e-6f);   // bottom right
  EXPECT_NEAR(ramp("0.5, 0.5"), 2.5f, 1e-6f);
  EXPECT_NEAR(ramp("2, -1"), 4.0f, 1e-6f);  // clamped to the square
}

TEST(StdlibRules, LineIsOneWithinTheRadiusOfTheSegment) {
  auto line = [](const std::string& texcoord, const std::string& point2 = "0.75, 0.75") {
    return floatOf("  <line name=\"v\" type=\"float\">\n"
                   "    <input name=\"texcoord\" type=\"vector2\" value=\"" + texcoord + "\"/>\n"
                   "    <input name=\"point2\" type=\"vector2\" value=\"" + point2 + "\"/>\n  </line>\n");
  };
  EXPECT_EQ(line("0.5, 0.5"), 1.0f);    // on the segment from (0.25, 0.25) to (0.75, 0.75)
  EXPECT_EQ(line("0.55, 0.5"), 1.0f);   // 0.035 from it, within the radius 0.1
  EXPECT_EQ(line("0.7, 0.5"), 0.0f);    // 0.14 from it
  EXPECT_EQ(line("0.9, 0.9"), 0.0f);    // beyond the end point: 0.21 from it
  EXPECT_EQ(line("0.8, 0.8"), 1.0f);    // beyond the end point: 0.07 from it
  EXPECT_EQ(line("0.3, 0.25", "0.25, 0.25"), 1.0f);  // a segment of length 0: a disc about the point
}

TEST(StdlibRules, CircleAndCheckerboard) {
  auto circle = [](const std::string& texcoord) {
    return floatOf("  <circle name=\"v\" type=\"float\">\n"
                   "    <input name=\"texcoord\" type=\"vector2\" value=\"" + texcoord + "\"/>\n"
                   "    <input name=\"center\" type=\"vector2\" value=\"0.5, 0.5\"/>\n"
                   "    <input name=\"radius\" type=\"float\" value=\"0.25\"/>\n  </circle>\n");
  };
  EXPECT_EQ(circle("0.5, 0.5"), 1.0f);
  EXPECT_EQ(circle("0.7, 0.5"), 1.0f);
  EXPECT_EQ(circle("0.7, 0.7"), 0.0f);  // 0.28 from the centre
  auto checker = [](const std::string& texcoord) {
    return valueOf("  <checkerboard name=\"v\" type=\"color3\">\n"
                   "    <input name=\"color1\" type=\"color3\" value=\"1, 0.5, 0.25\"/>\n"
                   "    <input name=\"color2\" type=\"color3\" value=\"0.1, 0.1, 0.1\"/>\n"
                   "    <input name=\"texcoord\" type=\"vector2\" value=\"" + texcoord + "\"/>\n  </checkerboard>\n",
                   "color3");
  };
  // The default tiling is 8 cells per unit: (0.01, 0.01) is in cell (0, 0), (0.13, 0.01) in (1, 0).
  EXPECT_EQ(checker("0.01, 0.01"), (std::vector<float>{0.1f, 0.1f, 0.1f}));
  EXPECT_EQ(checker("0.13, 0.01"), (std::vector<float>{1.0f, 0.5f, 0.25f}));
  EXPECT_EQ(checker("0.13, 0.13"), (std::vector<float>{0.1f, 0.1f, 0.1f}));
}

TEST(StdlibRules, GridLinesOnTheCellEdgesAndStaggeredRows) {
  auto grid = [](const std::string& texcoord, bool staggered) {
    return valueOf(std::string("  <grid name=\"v\" type=\"color3\">\n") +
                       "    <input name=\"texcoord\" type=\"vector2\" value=\"" + texcoord + "\"/>\n" +
                       "    <input name=\"staggered\" type=\"boolean\" value=\"" + (staggered ? "true" : "false") +
                       "\"/>\n  </grid>\n",
                   "color3")[0];
  };
  // thickness 0.05: a line where |2 mod(x, 1) - 1| > 0.95, i.e. within 0.025 of a cell edge.
  EXPECT_EQ(grid("0.5, 0.5", false), 0.0f);
  EXPECT_EQ(grid("0.99, 0.5", false), 1.0f);
  EXPECT_EQ(grid("0.5, 0.01", false), 1.0f);
  // Row 1 (1 < v < 2) is shifted by half a cell when staggered: u = 0.49 lands on an edge.
  EXPECT_EQ(grid("0.49, 1.5", false), 0.0f);
  EXPECT_EQ(grid("0.49, 1.5", true), 1.0f);
}

// The encodings of colour values, decoded by the lowering and folded at compile time
// (compiler/lower/Context.cpp, toWorkingSpace). Grey stays grey through a primaries conversion
// (white maps to white), so each channel is the decoded value.
TEST(StdlibRules, ColourValuesAreDecodedFromTheirEncoding) {
  auto decoded = [](const std::string& value, const std::string& space, float plus = 0.0f) {
    std::vector<float> v = valueOf("  <add name=\"v\" type=\"color3\">\n"
                                   "    <input name=\"in1\" type=\"color3\" value=\"" + value + ", " + value + ", " +
                                       value + "\" colorspace=\"" + space + "\"/>\n"
                                   "    <input name=\"in2\" type=\"float\" value=\"" + std::to_string(plus) +
                                       "\"/>\n  </add>\n",
                                   "color3");
    return v.size() == 3 ? v[0] : NAN;
  };
  // IEC 61966-2-1: 0.5 encodes 0.21404 linear; the linear segment below 0.04045.
  EXPECT_NEAR(decoded("0.5", "srgb_texture"), 0.214041f, 1e-5f);
  EXPECT_NEAR(decoded("0.02", "srgb_texture"), 0.02f / 12.92f, 1e-7f);
  EXPECT_NEAR(decoded("1", "srgb_texture"), 1.0f, 1e-6f);
  // Adobe RGB's exponent 563/256 (MaterialX cmlib), clamped at 0 before the power: -0.5 is 0,
  // seen as 1 after adding 1 (a power of -0.5 would not fold, and the value would be missing).
  EXPECT_NEAR(decoded("0.5", "adobergb"), std::pow(0.5f, 563.0f / 256.0f), 1e-5f);
  EXPECT_NEAR(decoded("-0.5", "adobergb", 1.0f), 1.0f, 1e-6f);
}

// pbrlib's hair helpers, whose MaterialX implementations are GLSL files (not graphs): the
// formulas of their papers, at values worked by hand.
TEST(StdlibRules, HairAbsorptionFromMelaninUsesDEonsCoefficients) {
  // d'Eon et al. 2011: eumelanin absorbs (0.419, 0.697, 1.37) and pheomelanin (0.187, 0.4,
  // 1.05) per unit; concentration 0.5 is -ln(0.5) = 0.6931 units, split evenly at redness 0.5.
  std::vector<float> a = valueOf("  <deon_hair_absorption_from_melanin name=\"v\" type=\"vector3\">\n"
                                 "    <input name=\"melanin_concentration\" type=\"float\" value=\"0.5\"/>\n"
                                 "    <input name=\"melanin_redness\" type=\"float\" value=\"0.5\"/>\n"
                                 "  </deon_hair_absorption_from_melanin>\n",
                                 "vector3");
  ASSERT_EQ(a.size(), 3u);
  const float half = 0.5f * std::log(2.0f);
  EXPECT_NEAR(a[0], half * (0.419f + 0.187f), 2e-4f);
  EXPECT_NEAR(a[1], half * (0.697f + 0.4f), 2e-4f);
  EXPECT_NEAR(a[2], half * (1.37f + 1.05f), 2e-4f);
}

TEST(StdlibRules, HairAbsorptionFromColourInvertsChiangsFit) {
  // Chiang et al. 2016 eq. 9 at colour 0.5 and azimuthal roughness 0.2.
  std::vector<float> a = valueOf("  <chiang_hair_absorption_from_color name=\"v\" type=\"vector3\">\n"
                                 "    <input name=\"color\" type=\"color3\" value=\"0.5, 0.5, 0.5\"/>\n"
                                 "  </chiang_hair_absorption_from_color>\n",
                                 "vector3");
  ASSERT_EQ(a.size(), 3u);
  const double b = 0.2;
  const double poly = 5.969 - 0.215 * b + 2.532 * b * b - 10.73 * b * b * b + 5.574 * std::pow(b, 4) + 0.245 * std::pow(b, 5);
  EXPECT_NEAR(a[0], std::pow(std::log(0.5) / poly, 2.0), 1e-6);
}

TEST(StdlibRules, HairRoughnessFollowsChiangsFitsPerLobe) {
  auto lobe = [](const std::string& output) {
    return valueOf("  <chiang_hair_roughness name=\"r\" type=\"multioutput\">\n"
                   "    <input name=\"longitudinal\" type=\"float\" value=\"0.1\"/>\n"
                   "    <input name=\"azimuthal\" type=\"float\" value=\"0.1\"/>\n"
                   "  </chiang_hair_roughness>\n"
                   "  <dot name=\"v\" type=\"vector2\"><input name=\"in\" type=\"vector2\" nodename=\"r\" output=\"" +
                       output + "\"/></dot>\n",
                   "vector2");
  };
  // Eqs. 7-8: v = (0.726 b + 0.812 b^2 + 3.7 b^20)^2, s = 0.265 b + 1.194 b^2 + 5.372 b^22;
  // TT and TRT widen the longitudinal lobe by 1/2 and 2 (v by 1/4 and 4).
  const double v = std::pow(0.726 * 0.1 + 0.812 * 0.01 + 3.7e-20, 2.0);
  const double s = 0.265 * 0.1 + 1.194 * 0.01;
  for (auto [output, scale] : {std::pair{"roughness_R", 1.0}, {"roughness_TT", 0.25}, {"roughness_TRT", 4.0}}) {
    std::vector<float> r = lobe(output);
    ASSERT_GE(r.size(), 2u) << output;
    EXPECT_NEAR(r[0], v * scale, 1e-6) << output;
    EXPECT_NEAR(r[1], s, 1e-6) << output;
  }
}

/// MaterialX's definition of nodedef `nodedef` (from `defs`, a file of MaterialX's libraries)
/// and the node graph implementing it (from `graphs`), renamed to category "copy" (nodedef
/// ND_copy) so that a document runs MaterialX's graph where the category would run mxc's rule.
std::string materialxGraphCopy(const std::string& defs, const std::string& graphs, const std::string& nodedef) {
  auto read = [](const std::string& library) {
    std::ifstream file(sharedDir() / "conformance/materialx-tree/libraries" / library);
    std::stringstream buffer;
    buffer << file.rdbuf();
    return buffer.str();
  };
  auto element = [](const std::string& text, size_t start, const std::string& close) {
    const size_t end = start == std::string::npos ? std::string::npos : text.find(close, start);
    return end == std::string::npos ? std::string() : text.substr(start, end + close.size() - start);
  };
  const std::string defsText = read(defs);
  const std::string text = read(graphs);
  const std::string def = element(defsText, defsText.find("<nodedef name=\"" + nodedef + "\""), "</nodedef>");
  std::string graph;
  for (size_t at = text.find("<nodegraph "); at != std::string::npos; at = text.find("<nodegraph ", at + 1)) {
    if (text.substr(at, text.find('>', at) - at).find("nodedef=\"" + nodedef + "\"") != std::string::npos) {
      graph = element(text, at, "</nodegraph>");
      break;
    }
  }
  if (def.empty() || graph.empty()) return {};
  std::string copy = def + "\n" + graph + "\n";
  const size_t graphName = copy.find("<nodegraph name=\"") + 17;
  copy.replace(graphName, copy.find('"', graphName) - graphName, "NG_copy");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\"" + nodedef + "\"", "\"ND_copy\""},
                                 {"node=\"" + def.substr(def.find("node=\"") + 6, def.find('"', def.find("node=\"") + 6) - def.find("node=\"") - 6) + "\"", "node=\"copy\""}}) {
    for (size_t at = copy.find(from); at != std::string::npos; at = copy.find(from, at + to.size())) {
      copy.replace(at, from.size(), to);
    }
  }
  return copy;
}

// glTF's texture placement (gltfPlaced in StdlibRules.cpp) against MaterialX's own graph of
// gltf_image (libraries/bxdf/gltf_pbr.mtlx), run as a graph: the texture coordinate each one
// samples at, for a transform with every part set, in both operation orders.
TEST(StdlibRules, GltfImagePlacementMatchesMaterialXsGraph) {
  const std::string definitions = materialxGraphCopy("bxdf/gltf_pbr.mtlx", "bxdf/gltf_pbr.mtlx", "ND_gltf_image_color3_color3_1_0");
  ASSERT_GT(definitions.size(), 500u) << "MaterialX's gltf_image definition was not found";
  auto sampledAt = [](const std::string& text) -> std::vector<float> {
    Context context;
    CompileRequest request;
    request.document = "test.mtlx";
    request.text = mtlx(text + "  <surface_unlit name=\"surf\" type=\"surfaceshader\"><input name=\"emission_color\" "
                               "type=\"color3\" nodename=\"v\"/></surface_unlit>\n  <surfacematerial name=\"M\" "
                               "type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"surf\"/>"
                               "</surfacematerial>\n");
    Compiler compiler(context, std::move(request));
    std::vector<ir::Material> materials = std::move(compiler.materials());
    EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
    if (materials.empty()) return {};
    const ir::ExprGraph& g = materials[0].exprs;
    for (ir::ExprId id = 0; id < g.size(); ++id) {
      if (g[id].op != ir::Op::ImageSample) continue;
      std::optional<ir::Constant> uv = ir::evaluateExpr(g, g.arg(id, 1));
      return uv ? uv->v : std::vector<float>{};
    }
    return {};
  };
  for (const char* order : {"0", "1"}) {
    const std::string inputs = std::string("<input name=\"file\" type=\"filename\" value=\"missing.png\"/>") +
                               "<input name=\"texcoord\" type=\"vector2\" value=\"0.3, 0.7\"/>"
                               "<input name=\"scale\" type=\"vector2\" value=\"2, 3\"/>"
                               "<input name=\"rotate\" type=\"float\" value=\"30\"/>"
                               "<input name=\"offset\" type=\"vector2\" value=\"0.1, 0.2\"/>"
                               "<input name=\"operationorder\" type=\"integer\" value=\"" + order + "\"/>";
    const std::vector<float> ours = sampledAt("  <gltf_image name=\"v\" type=\"color3\">" + inputs + "</gltf_image>\n");
    const std::vector<float> theirs = sampledAt(definitions + "  <copy name=\"v\" type=\"color3\">" + inputs + "</copy>\n");
    ASSERT_EQ(ours.size(), 2u) << "operationorder " << order;
    ASSERT_EQ(theirs.size(), 2u) << "operationorder " << order;
    EXPECT_NEAR(ours[0], theirs[0], 1e-5f) << "operationorder " << order;
    EXPECT_NEAR(ours[1], theirs[1], 1e-5f) << "operationorder " << order;
    // And the placement moved the coordinate: the test sees the transform.
    EXPECT_GT(std::abs(ours[0] - 0.3f) + std::abs(ours[1] - 0.7f), 0.1f) << "operationorder " << order;
  }
}

// The 2D procedural patterns' rules against MaterialX's own graphs of them
// (libraries/stdlib/stdlib_ng.mtlx), run as graphs: the same value at points of every cell
// part, regular and staggered.
TEST(StdlibRules, ProceduralPatternsMatchMaterialXsGraphs) {
  struct Pattern {
    const char* nodedef;
    const char* category;
    const char* type;
    const char* inputs;
  };
  const Pattern patterns[] = {
      {"ND_ramp4_float", "ramp4", "float",
       "<input name=\"valuetl\" type=\"float\" value=\"1\"/><input name=\"valuetr\" type=\"float\" value=\"2\"/>"
       "<input name=\"valuebl\" type=\"float\" value=\"3\"/><input name=\"valuebr\" type=\"float\" value=\"4\"/>"},
      {"ND_line_float", "line", "float", "<input name=\"radius\" type=\"float\" value=\"0.15\"/>"},
      {"ND_circle_float", "circle", "float", "<input name=\"center\" type=\"vector2\" value=\"0.4, 0.5\"/>"},
      {"ND_checkerboard_color3", "checkerboard", "color3", "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 5\"/>"},
      {"ND_grid_color3", "grid", "color3", "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/>"},
      {"ND_grid_color3", "grid", "color3",
       "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/><input name=\"staggered\" type=\"boolean\" value=\"true\"/>"},
      {"ND_crosshatch_color3", "crosshatch", "color3",
       "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/><input name=\"thickness\" type=\"float\" value=\"0.1\"/>"},
      {"ND_crosshatch_color3", "crosshatch", "color3",
       "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/><input name=\"thickness\" type=\"float\" value=\"0.1\"/>"
       "<input name=\"staggered\" type=\"boolean\" value=\"true\"/>"},
      {"ND_tiledcircles_color3", "tiledcircles", "color3", "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/>"},
      {"ND_tiledcircles_color3", "tiledcircles", "color3",
       "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/><input name=\"staggered\" type=\"boolean\" value=\"true\"/>"},
      {"ND_cloverleaf_float", "cloverleaf", "float",
       "<input name=\"center\" type=\"vector2\" value=\"0.5, 0.45\"/><input name=\"radius\" type=\"float\" value=\"0.4\"/>"},
      {"ND_tiledcloverleafs_color3", "tiledcloverleafs", "color3", "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/>"},
      {"ND_tiledcloverleafs_color3", "tiledcloverleafs", "color3",
       "<input name=\"uvtiling\" type=\"vector2\" value=\"3, 3\"/><input name=\"staggered\" type=\"boolean\" value=\"true\"/>"},
  };
  int differing = 0;
  for (const Pattern& pattern : patterns) {
    const std::string definitions = materialxGraphCopy("stdlib/stdlib_defs.mtlx", "stdlib/stdlib_ng.mtlx", pattern.nodedef);
    ASSERT_FALSE(definitions.empty()) << pattern.nodedef;
    std::set<std::vector<float>> seen;
    for (int k = 0; k < 48; ++k) {
      // Points spread over the unit square (a 0.37 / 0.61 lattice), off the cells' exact edges.
      const float u = std::fmod(0.013f + 0.37f * float(k), 1.0f), v = std::fmod(0.029f + 0.61f * float(k), 1.0f);
      const std::string inputs = std::string(pattern.inputs) + "<input name=\"texcoord\" type=\"vector2\" value=\"" +
                                 std::to_string(u) + ", " + std::to_string(v) + "\"/>";
      const std::vector<float> ours = valueOf("  <" + std::string(pattern.category) + " name=\"v\" type=\"" + pattern.type +
                                                  "\">" + inputs + "</" + pattern.category + ">\n",
                                              pattern.type);
      const std::vector<float> theirs =
          valueOf(definitions + "  <copy name=\"v\" type=\"" + pattern.type + "\">" + inputs + "</copy>\n", pattern.type);
      ASSERT_EQ(ours.size(), 3u) << pattern.nodedef;
      ASSERT_EQ(theirs.size(), 3u) << pattern.nodedef;
      for (int ch = 0; ch < 3; ++ch) {
        if (std::abs(ours[ch] - theirs[ch]) > 1e-5f) ++differing;
        EXPECT_NEAR(ours[ch], theirs[ch], 1e-5f) << pattern.nodedef << " " << pattern.inputs << " at " << u << ", " << v;
      }
      seen.insert(ours);
    }
    // The points see more than one value: the comparison is not of two constants.
    EXPECT_GT(seen.size(), 1u) << pattern.nodedef << " " << pattern.inputs;
  }
  EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace mxc::test

namespace mxc::test {
namespace {

/// The lattice points at which the emission colour of a document's material reads cell noise
/// (each CellNoise2D's argument, folded), in the order found from the colour down.
std::vector<std::vector<float>> cellNoisePoints(const std::string& body) {
  std::vector<ir::Material> materials = unlitMaterials(body, "v");
  std::vector<std::vector<float>> points;
  if (materials.empty() || materials[0].emissions.empty()) return points;
  const ir::Material& m = materials[0];
  std::set<ir::ExprId> seen;
  std::vector<ir::ExprId> stack{m.emissions[0].slots.value(ir::Slot::Color)};
  while (!stack.empty()) {
    const ir::ExprId e = stack.back();
    stack.pop_back();
    if (e == ir::kNoExpr || !seen.insert(e).second) continue;
    if (m.exprs[e].op == ir::Op::CellNoise2D) {
      std::optional<ir::Constant> at = ir::evaluateExpr(m.exprs, m.exprs.argsOf(e)[0]);
      points.push_back(at ? at->v : std::vector<float>{});
      continue;
    }
    for (ir::ExprId a : m.exprs.argsOf(e)) stack.push_back(a);
  }
  std::sort(points.begin(), points.end());
  return points;
}

// randomfloat and randomcolor hash where MaterialX's graphs of them do: the same cell-noise
// lattice points (the input scaled by 4096 for a float, the seeds offset per channel), so the
// rule and the graph read the same random numbers. (The numbers themselves are mxc's cell
// noise, folded nowhere: the points are what the rule decides.)
TEST(StdlibRules, RandomNodesHashWhereMaterialXsGraphsDo) {
  struct Case {
    const char* nodedef;
    const char* category;
    const char* inputs;
    size_t points;
  };
  const Case cases[] = {
      {"ND_randomfloat_float", "randomfloat", "<input name=\"in\" type=\"float\" value=\"0.37\"/><input name=\"seed\" type=\"integer\" value=\"5\"/>", 1},
      {"ND_randomfloat_integer", "randomfloat", "<input name=\"in\" type=\"integer\" value=\"12\"/><input name=\"seed\" type=\"integer\" value=\"3\"/>", 1},
      {"ND_randomcolor_float", "randomcolor", "<input name=\"in\" type=\"float\" value=\"2.5\"/><input name=\"seed\" type=\"integer\" value=\"7\"/>"
       "<input name=\"saturationlow\" type=\"float\" value=\"0.2\"/><input name=\"brightnesslow\" type=\"float\" value=\"0.5\"/>", 3},
      {"ND_randomcolor_integer", "randomcolor", "<input name=\"in\" type=\"integer\" value=\"4\"/><input name=\"seed\" type=\"integer\" value=\"-2\"/>"
       "<input name=\"saturationlow\" type=\"float\" value=\"0.2\"/><input name=\"brightnesslow\" type=\"float\" value=\"0.5\"/>", 3},
  };
  for (const Case& k : cases) {
    const std::string definitions = materialxGraphCopy("stdlib/stdlib_defs.mtlx", "stdlib/stdlib_ng.mtlx", k.nodedef);
    ASSERT_FALSE(definitions.empty()) << k.nodedef;
    const std::string type = std::string(k.category) == "randomfloat" ? "float" : "color3";
    const std::string convert = type == "float" ? "  <convert name=\"v\" type=\"color3\"><input name=\"in\" type=\"float\" nodename=\"r\"/></convert>\n" : "";
    const std::string name = type == "float" ? "r" : "v";
    const auto ours = cellNoisePoints(fmt::format("  <{0} name=\"{1}\" type=\"{2}\">{3}</{0}>\n", k.category, name, type, k.inputs) + convert);
    const auto theirs = cellNoisePoints(definitions + fmt::format("  <copy name=\"{0}\" type=\"{1}\">{2}</copy>\n", name, type, k.inputs) + convert);
    EXPECT_EQ(ours.size(), k.points) << k.nodedef;
    EXPECT_EQ(ours, theirs) << k.nodedef;
  }
}

}  // namespace
}  // namespace mxc::test

namespace mxc::test {
namespace {

// blackbody: the colour's chromaticity is on the Planckian locus. Linear Rec.709 back to CIE
// XYZ (IEC 61966-2-1), then x = X / (X + Y + Z), y = Y / (X + Y + Z), against the locus's
// tabulated chromaticities (CIE 15:2004; Kang et al. 2002's fit is within 3e-4 of them).
TEST(StdlibRules, BlackbodyLiesOnThePlanckianLocus) {
  struct Point {
    float kelvin, x, y;
  };
  const Point locus[] = {{2000, 0.5267f, 0.4133f}, {3000, 0.4369f, 0.4041f}, {5000, 0.3451f, 0.3516f}, {6500, 0.3135f, 0.3236f}};
  for (const Point& p : locus) {
    const std::vector<float> rgb =
        valueOf(fmt::format("  <blackbody name=\"v\" type=\"color3\"><input name=\"temperature\" type=\"float\" value=\"{}\"/>"
                            "</blackbody>\n", p.kelvin),
                "color3");
    ASSERT_EQ(rgb.size(), 3u);
    const float X = 0.4124f * rgb[0] + 0.3576f * rgb[1] + 0.1805f * rgb[2];
    const float Y = 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
    const float Z = 0.0193f * rgb[0] + 0.1192f * rgb[1] + 0.9505f * rgb[2];
    EXPECT_NEAR(Y, 1.0f, 0.02f) << p.kelvin << " K: luminance 1";
    EXPECT_NEAR(X / (X + Y + Z), p.x, 3e-3f) << p.kelvin << " K";
    EXPECT_NEAR(Y / (X + Y + Z), p.y, 3e-3f) << p.kelvin << " K";
  }
}

}  // namespace
}  // namespace mxc::test

namespace mxc::test {
namespace {

/// `e` evaluated with every texture sample replaced by `texel` (its first components), other
/// operations folded as the compiler folds them; nullopt when a leaf is not constant.
/// `missing` is what ImageMissing reads (whether the file could not be read).
std::optional<ir::Constant> withTexel(const ir::ExprGraph& g, ir::ExprId e, const std::vector<float>& texel,
                                      bool missing = false) {
  if (g[e].op == ir::Op::ImageSample) {
    const int n = ir::componentCount(g[e].type);
    return ir::Constant{g[e].type, std::vector<float>(texel.begin(), texel.begin() + n)};
  }
  if (g[e].op == ir::Op::ImageMissing) return ir::Constant{ir::Type::Bool, {missing ? 1.0f : 0.0f}};
  if (g[e].op == ir::Op::Constant) return ir::evaluateExpr(g, e);
  std::vector<ir::Constant> args;
  for (ir::ExprId a : g.argsOf(e)) {
    std::optional<ir::Constant> v = withTexel(g, a, texel, missing);
    if (!v) return std::nullopt;
    args.push_back(*v);
  }
  return ir::evaluate(g[e].op, g[e].type, args, g[e].payload, ir::hasTextPayload(g[e].op) ? g.text(e) : std::string());
}

/// The emission colour of an unlit surface fed by the float node "v" (its elements `nodes`),
/// for a texel: the arithmetic a texture node's rule does on what it samples.
float floatFromTexel(const std::string& nodes, const std::vector<float>& texel, bool missing = false) {
  std::vector<ir::Material> materials = unlitMaterials(
      nodes + "  <convert name=\"c\" type=\"color3\"><input name=\"in\" type=\"float\" nodename=\"v\"/></convert>\n", "c");
  if (materials.empty() || materials[0].emissions.empty()) return NAN;
  std::optional<ir::Constant> v =
      withTexel(materials[0].exprs, materials[0].emissions[0].slots.value(ir::Slot::Color), texel, missing);
  return v && !v->v.empty() ? v->v[0] : NAN;
}

// glTF's iridescence thickness and anisotropy textures: what the rules compute from a texel,
// against the KHR extensions (and, for the anisotropy, MaterialX's own graph run beside).
TEST(StdlibRules, GltfIridescenceAndAnisotropyTextures) {
  const std::string file = "<input name=\"file\" type=\"filename\" value=\"missing.png\"/>";
  // KHR_materials_iridescence: thickness = mix(min, max, g): g = 0.25 between 100 and 500 is 200.
  // (MaterialX 1.39's graph mixes the other way round, 400.)
  EXPECT_NEAR(floatFromTexel("  <gltf_iridescence_thickness name=\"v\" type=\"float\">" + file +
                                 "<input name=\"thicknessMin\" type=\"float\" value=\"100\"/>"
                                 "<input name=\"thicknessMax\" type=\"float\" value=\"500\"/></gltf_iridescence_thickness>\n",
                             {0.9f, 0.25f, 0.7f}),
              200.0f, 1e-3f);
  // KHR_materials_anisotropy: strength x blue; rotation + atan2(2g - 1, 2r - 1).
  const std::string definitions = materialxGraphCopy("bxdf/gltf_pbr.mtlx", "bxdf/gltf_pbr.mtlx", "ND_gltf_anisotropy_image");
  ASSERT_GT(definitions.size(), 500u);
  const std::string inputs = file + "<input name=\"anisotropy_strength\" type=\"float\" value=\"0.8\"/>"
                                    "<input name=\"anisotropy_rotation\" type=\"float\" value=\"0.5\"/>";
  const std::vector<float> texel = {0.5f, 1.0f, 0.25f};  // the direction (0, 1): a quarter turn
  for (const char* output : {"anisotropy_strength_out", "anisotropy_rotation_out"}) {
    auto graph = [&](const std::string& category, const std::string& defs) {
      return defs + "  <" + category + " name=\"a\" type=\"multioutput\">" + inputs + "</" + category + ">\n" +
             "  <dot name=\"v\" type=\"float\"><input name=\"in\" type=\"float\" nodename=\"a\" output=\"" + output +
             "\"/></dot>\n";
    };
    const float ours = floatFromTexel(graph("gltf_anisotropy_image", ""), texel);
    const float theirs = floatFromTexel(graph("copy", definitions), texel);
    const float expected = std::string(output) == "anisotropy_strength_out" ? 0.8f * 0.25f : 0.5f + 1.5707964f;
    EXPECT_NEAR(ours, expected, 1e-5f) << output;
    EXPECT_NEAR(ours, theirs, 1e-5f) << output;
  }
}

// UsdUVTexture (UsdPreviewSurface specification, "Texture Reader"): each component of the texel
// times scale plus bias; where the file cannot be read, the fallback as it is; with wrapS black,
// transparent black outside [0, 1] (then scaled and biased). Every output reads the same rgba.
TEST(StdlibRules, UsdUvTextureScalesBiasesAndFallsBack) {
  const std::vector<float> texel = {0.2f, 0.4f, 0.6f, 0.8f};
  auto texture = [](const std::string& st, const std::string& wrapS, const std::string& output) {
    return "  <UsdUVTexture name=\"t\" type=\"multioutput\">"
           "<input name=\"file\" type=\"filename\" value=\"missing.png\"/>"
           "<input name=\"st\" type=\"vector2\" value=\"" + st + "\"/>"
           "<input name=\"wrapS\" type=\"string\" value=\"" + wrapS + "\"/>"
           "<input name=\"fallback\" type=\"color4\" value=\"0.3, 0.35, 0.4, 0.45\"/>"
           "<input name=\"scale\" type=\"color4\" value=\"2, 1, 0.5, 1\"/>"
           "<input name=\"bias\" type=\"color4\" value=\"0.1, 0, 0.05, -0.2\"/></UsdUVTexture>\n"
           "  <dot name=\"v\" type=\"float\"><input name=\"in\" type=\"float\" nodename=\"t\" output=\"" + output +
           "\"/></dot>\n";
  };
  const char* outputs[] = {"r", "g", "b", "a"};
  const float scaled[] = {0.5f, 0.4f, 0.35f, 0.6f};
  const float fallback[] = {0.3f, 0.35f, 0.4f, 0.45f};
  const float bias[] = {0.1f, 0.0f, 0.05f, -0.2f};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(floatFromTexel(texture("0.5, 0.5", "periodic", outputs[k]), texel), scaled[k], 1e-6f) << outputs[k];
    EXPECT_NEAR(floatFromTexel(texture("0.5, 0.5", "periodic", outputs[k]), texel, true), fallback[k], 1e-6f) << outputs[k];
    // Outside [0, 1] along s: repeat reads the texel, black reads transparent black.
    EXPECT_NEAR(floatFromTexel(texture("1.5, 0.5", "periodic", outputs[k]), texel), scaled[k], 1e-6f) << outputs[k];
    EXPECT_NEAR(floatFromTexel(texture("1.5, 0.5", "black", outputs[k]), texel), bias[k], 1e-6f) << outputs[k];
    EXPECT_NEAR(floatFromTexel(texture("0.5, 1.5", "black", outputs[k]), texel), scaled[k], 1e-6f) << outputs[k] << " (t repeats)";
  }
}

// UsdTransform2d: scale, then rotate counter-clockwise (degrees), then translate; and
// UsdPrimvarReader: `st` is the first texture coordinate set, other names a primvar of that name
// with the fallback where the geometry has none.
TEST(StdlibRules, UsdTransform2dAndPrimvarReader) {
  auto component = [](int k) {
    return "  <UsdTransform2d name=\"p\" type=\"vector2\"><input name=\"in\" type=\"vector2\" value=\"0.5, 0.25\"/>"
           "<input name=\"scale\" type=\"vector2\" value=\"2, 4\"/><input name=\"rotation\" type=\"float\" value=\"90\"/>"
           "<input name=\"translation\" type=\"vector2\" value=\"0.1, 0.2\"/></UsdTransform2d>\n"
           "  <extract name=\"v\" type=\"float\"><input name=\"in\" type=\"vector2\" nodename=\"p\"/>"
           "<input name=\"index\" type=\"integer\" value=\"" + std::to_string(k) + "\"/></extract>\n";
  };
  // (0.5, 0.25) * (2, 4) = (1, 1); a quarter turn: (-1, 1); plus (0.1, 0.2).
  EXPECT_NEAR(floatOf(component(0)), -0.9f, 1e-5f);
  EXPECT_NEAR(floatOf(component(1)), 1.2f, 1e-5f);

  auto reader = [](const std::string& varname) {
    std::vector<ir::Material> materials = unlitMaterials(
        "  <UsdPrimvarReader name=\"p\" type=\"vector3\"><input name=\"varname\" type=\"string\" value=\"" + varname +
            "\"/><input name=\"fallback\" type=\"vector3\" value=\"0.1, 0.2, 0.3\"/></UsdPrimvarReader>\n"
            "  <UsdPrimvarReader name=\"q\" type=\"vector2\"><input name=\"varname\" type=\"string\" value=\"st\"/>"
            "</UsdPrimvarReader>\n  <convert name=\"v\" type=\"color3\"><input name=\"in\" type=\"vector3\" "
            "nodename=\"p\"/></convert>\n  <add name=\"w\" type=\"color3\"><input name=\"in1\" type=\"color3\" nodename=\"v\"/>"
            "<input name=\"in2\" type=\"float\" nodename=\"x\"/></add>\n  <extract name=\"x\" type=\"float\">"
            "<input name=\"in\" type=\"vector2\" nodename=\"q\"/><input name=\"index\" type=\"integer\" value=\"0\"/></extract>\n",
        "w");
    std::set<std::string> geomprops;
    if (materials.empty()) return geomprops;
    const ir::ExprGraph& g = materials[0].exprs;
    for (ir::ExprId id = 0; id < g.size(); ++id) {
      if (g[id].op == ir::Op::GeomProp) geomprops.insert(g.text(id));
    }
    return geomprops;
  };
  const std::set<std::string> read = reader("rest");
  EXPECT_TRUE(read.count("rest")) << "the primvar named";
  EXPECT_TRUE(read.count("UV0")) << "st is the texture coordinate";
  EXPECT_FALSE(read.count("st"));
}

}  // namespace
}  // namespace mxc::test
