// Upgrading MaterialX 1.22-1.37 documents (compiler/document/UpgradeLegacy.cpp): the results
// are the ones MaterialX 1.39.5's own upgrade gives for the same text (read with
// MaterialX.readFromXmlFile and written back), checked here on the resolved graph.

#include <algorithm>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/TestSupport.h"

namespace mxc::test {
namespace {

const resolve::ResolvedInput* inputOf(const resolve::ResolvedDocument& r, std::string_view node, std::string_view input) {
  const resolve::ResolvedNode* n = r.top.findNode(node);
  return n ? n->findInput(input) : nullptr;
}

TEST(UpgradeLegacy, A137MaterialBecomesAShaderNodeAndASurfacematerial) {
  const char* text =
      "<materialx version=\"1.37\">\n"
      "  <material name=\"M\">\n"
      "    <shaderref name=\"SR\" node=\"standard_surface\">\n"
      "      <bindinput name=\"base_color\" type=\"color3\" value=\"0.2, 0.2, 0.6\"/>\n"
      "      <bindparam name=\"thin_walled\" type=\"boolean\" value=\"true\"/>\n"
      "    </shaderref>\n"
      "  </material>\n"
      "  <atan2 name=\"angle\" type=\"float\">\n"
      "    <input name=\"in1\" type=\"float\" value=\"0.5\"/>\n"
      "    <input name=\"in2\" type=\"float\" value=\"1.0\"/>\n"
      "  </atan2>\n"
      "  <rotate3d name=\"turned\" type=\"vector3\">\n"
      "    <parameter name=\"axis\" type=\"vector3\" value=\"0, 0, 1\"/>\n"
      "  </rotate3d>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* material = r.top.findNode("M");
  ASSERT_NE(material, nullptr);
  EXPECT_EQ(material->category(), "surfacematerial");
  const resolve::ResolvedNode* shader = material->findInput("surfaceshader")->upstream.node;
  ASSERT_NE(shader, nullptr);
  EXPECT_EQ(shader->name(), "SR");
  EXPECT_EQ(shader->category(), "standard_surface");
  EXPECT_EQ(inputOf(r, "SR", "base_color")->value->as<glm::vec3>(), glm::vec3(0.2f, 0.2f, 0.6f));
  EXPECT_TRUE(inputOf(r, "SR", "thin_walled")->value->as<bool>());
  // 1.37's atan2(in1, in2) is 1.39's atan2(inx = in1, iny = in2), as MaterialX upgrades it.
  EXPECT_FLOAT_EQ(inputOf(r, "angle", "inx")->value->as<float>(), 0.5f);
  EXPECT_FLOAT_EQ(inputOf(r, "angle", "iny")->value->as<float>(), 1.0f);
  EXPECT_EQ(inputOf(r, "turned", "axis")->value->as<glm::vec3>(), glm::vec3(0, 0, 1));
}

// MaterialX 1.22 (its test suite's stdlib/upgrade/syntax_1_22.mtlx): an <opgraph> of constants
// whose input is `color`, graph outputs connected by a child <parameter type="opgraphnode">, a
// node input connected the same way, a <shader shadername=> whose inputs name a graph output
// (graphname, graphoutput), and a material with a shaderref of the shader's name. The 1.39 form:
// a standard_surface node whose inputs are connected to the graph's outputs.
TEST(UpgradeLegacy, A122OpGraphShaderAndMaterial) {
  const char* text =
      "<materialx require=\"matopgraph\" version=\"1.22\">\n"
      "  <opgraph name=\"paint\">\n"
      "    <constant name=\"tint\" type=\"color3\">\n"
      "      <parameter name=\"color\" type=\"color3\" value=\"0.1, 0.6, 0.85\"/>\n"
      "    </constant>\n"
      "    <multiply name=\"half\" type=\"color3\">\n"
      "      <parameter name=\"in1\" type=\"opgraphnode\" value=\"tint\"/>\n"
      "      <parameter name=\"in2\" type=\"float\" value=\"0.5\"/>\n"
      "    </multiply>\n"
      "    <constant name=\"gloss\" type=\"float\">\n"
      "      <parameter name=\"color\" type=\"float\" value=\"0.4\"/>\n"
      "    </constant>\n"
      "    <output name=\"color_out\" type=\"color3\">\n"
      "      <parameter name=\"in\" type=\"opgraphnode\" value=\"half\"/>\n"
      "    </output>\n"
      "    <output name=\"rough_out\" type=\"float\">\n"
      "      <parameter name=\"in\" type=\"opgraphnode\" value=\"gloss\"/>\n"
      "    </output>\n"
      "  </opgraph>\n"
      "  <shader name=\"paint_shader\" shadertype=\"surface\" shadername=\"standard_surface\">\n"
      "    <input name=\"base_color\" graphoutput=\"color_out\" graphname=\"paint\" type=\"color3\"/>\n"
      "    <input name=\"specular_roughness\" graphoutput=\"rough_out\" graphname=\"paint\" type=\"float\"/>\n"
      "  </shader>\n"
      "  <material name=\"paint_material\">\n"
      "    <shaderref name=\"paint_shader\" shadertype=\"surface\"/>\n"
      "  </material>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* material = r.top.findNode("paint_material");
  ASSERT_NE(material, nullptr);
  EXPECT_EQ(material->category(), "surfacematerial");
  const resolve::ResolvedNode* shader = material->findInput("surfaceshader")->upstream.node;
  ASSERT_NE(shader, nullptr);
  EXPECT_EQ(shader->category(), "standard_surface");
  const resolve::ResolvedInput* base = shader->findInput("base_color");
  ASSERT_NE(base, nullptr);
  ASSERT_EQ(base->source, resolve::InputSource::Connection);
  ASSERT_NE(base->upstream.graph, nullptr);
  EXPECT_EQ(base->upstream.graph->name(), "paint");
  EXPECT_EQ(base->upstream.output, "color_out");
  auto feeding = [](const resolve::ResolvedInput* port) {  // the node behind a graph output
    const resolve::ResolvedInput* out = port->upstream.graph->findOutput(port->upstream.output);
    return out ? out->upstream.node : nullptr;
  };
  const resolve::ResolvedNode* half = feeding(base);
  ASSERT_NE(half, nullptr);
  EXPECT_EQ(half->name(), "half");
  const resolve::ResolvedInput* tint = half->findInput("in1");
  ASSERT_EQ(tint->source, resolve::InputSource::Connection);
  EXPECT_EQ(tint->type, "color3");  // the connected node's type
  EXPECT_EQ(tint->upstream.node->findInput("value")->value->as<glm::vec3>(), glm::vec3(0.1f, 0.6f, 0.85f));
  const resolve::ResolvedInput* rough = shader->findInput("specular_roughness");
  ASSERT_EQ(rough->source, resolve::InputSource::Connection);
  ASSERT_NE(feeding(rough), nullptr);
  EXPECT_FLOAT_EQ(feeding(rough)->findInput("value")->value->as<float>(), 0.4f);
  // The 1.26 edits have a note of their own: the one opgraphnode node input typed, two constants'
  // `color` named `value`; no node was renamed to a 1.37 category.
  const std::vector<std::string>& notes = r.document->upgradeNotes;
  EXPECT_NE(std::find(notes.begin(), notes.end(),
                      "3 1.26 forms upgraded (opgraphnode inputs typed, constant color named value)"),
            notes.end())
      << fmt::format("{}", fmt::join(notes, "; "));
  for (const std::string& note : notes) EXPECT_EQ(note.find("1.37 categories"), std::string::npos) << note;
}

TEST(UpgradeLegacy, A137GraphGetsTheNewBsdfsLayersAndArtisticIor) {
  const char* text =
      "<materialx version=\"1.37\">\n"
      "  <nodedef name=\"ND_plastic\" node=\"plastic\">\n"
      "    <input name=\"color\" type=\"color3\" value=\"0.5, 0.5, 0.5\"/>\n"
      "    <output name=\"out\" type=\"surfaceshader\"/>\n"
      "  </nodedef>\n"
      "  <nodegraph name=\"NG_plastic\" nodedef=\"ND_plastic\">\n"
      "    <diffuse_brdf name=\"diffuse\" type=\"BSDF\">\n"
      "      <input name=\"color\" type=\"color3\" interfacename=\"color\"/>\n"
      "    </diffuse_brdf>\n"
      "    <conductor_brdf name=\"metal\" type=\"BSDF\">\n"
      "      <input name=\"reflectivity\" type=\"color3\" interfacename=\"color\"/>\n"
      "    </conductor_brdf>\n"
      "    <mix name=\"both\" type=\"BSDF\">\n"
      "      <input name=\"fg\" type=\"BSDF\" nodename=\"metal\"/>\n"
      "      <input name=\"bg\" type=\"BSDF\" nodename=\"diffuse\"/>\n"
      "    </mix>\n"
      "    <dielectric_brdf name=\"coat\" type=\"BSDF\">\n"
      "      <input name=\"ior\" type=\"float\" value=\"1.5\"/>\n"
      "      <input name=\"base\" type=\"BSDF\" nodename=\"both\"/>\n"
      "    </dielectric_brdf>\n"
      "    <dielectric_btdf name=\"glass\" type=\"BSDF\"/>\n"
      "    <surface name=\"surf\" type=\"surfaceshader\">\n"
      "      <input name=\"bsdf\" type=\"BSDF\" nodename=\"coat\"/>\n"
      "    </surface>\n"
      "    <output name=\"out\" type=\"surfaceshader\" nodename=\"surf\"/>\n"
      "  </nodegraph>\n"
      "  <material name=\"M\">\n"
      "    <shaderref name=\"SR\" node=\"plastic\"/>\n"
      "  </material>\n"
      "</materialx>\n";
  Context context;
  const doc::Document* d = context.load(text);
  ASSERT_NE(d, nullptr);
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const doc::NodeGraph& g = d->nodegraphs.at(0);
  EXPECT_EQ(g.findNode("diffuse")->category, "oren_nayar_diffuse_bsdf");
  // The coat keeps its place under the name "coat" as a layer over its old base.
  const doc::Node* layer = g.findNode("coat");
  ASSERT_NE(layer, nullptr);
  EXPECT_EQ(layer->category, "layer");
  EXPECT_EQ(layer->findInput("base")->nodename, "both");
  const doc::Node* top = g.findNode(layer->findInput("top")->nodename);
  ASSERT_NE(top, nullptr);
  EXPECT_EQ(top->category, "dielectric_bsdf");
  EXPECT_EQ(top->findInput("base"), nullptr);
  // conductor_brdf's artistic inputs moved to an artistic_ior node feeding ior and extinction.
  const doc::Node* metal = g.findNode("metal");
  EXPECT_EQ(metal->category, "conductor_bsdf");
  EXPECT_EQ(metal->findInput("reflectivity"), nullptr);
  const doc::Node* artistic = g.findNode(metal->findInput("ior")->nodename);
  ASSERT_NE(artistic, nullptr);
  EXPECT_EQ(artistic->category, "artistic_ior");
  EXPECT_EQ(artistic->findInput("reflectivity")->interfacename, "color");
  EXPECT_EQ(metal->findInput("extinction")->output, "extinction");
  const doc::Node* glass = g.findNode("glass");
  EXPECT_EQ(glass->category, "dielectric_bsdf");
  EXPECT_EQ(glass->findInput("scatter_mode")->valueString, "T");
  // The whole graph resolves and compiles against the 1.39 library.
  resolve::ResolvedDocument r = resolve::resolveDocument(*d, context.libraries.top(), context.diagnostics);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(r.top.findNode("M")->findInput("surfaceshader")->upstream.node->category(), "plastic");
}

TEST(UpgradeLegacy, A125ShaderWithOverridesBindsThroughPublicNames) {
  const char* text =
      "<materialx version=\"1.25\">\n"
      "  <shader name=\"standard_surface\" shadertype=\"surface\" shaderprogram=\"standard_surface\">\n"
      "    <input name=\"base\" type=\"float\" value=\"1.0\" publicname=\"base_public\"/>\n"
      "    <input name=\"coat\" type=\"float\" value=\"0.0\" publicname=\"coat_public\"/>\n"
      "  </shader>\n"
      "  <material name=\"carpaint\">\n"
      "    <shaderref name=\"standard_surface\" shadertype=\"surface\"/>\n"
      "    <override name=\"base_public\" type=\"float\" value=\"0.5\"/>\n"
      "    <override name=\"coat_public\" type=\"float\" value=\"1.0\"/>\n"
      "  </material>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  // The <shader> definition is gone; the node resolves against the library's standard_surface.
  EXPECT_TRUE(r.document->nodedefs.empty());
  const resolve::ResolvedNode* shader = r.top.findNode("carpaint")->findInput("surfaceshader")->upstream.node;
  ASSERT_NE(shader, nullptr);
  EXPECT_EQ(shader->category(), "standard_surface");
  EXPECT_FLOAT_EQ(inputOf(r, "standard_surface", "base")->value->as<float>(), 0.5f);
  EXPECT_FLOAT_EQ(inputOf(r, "standard_surface", "coat")->value->as<float>(), 1.0f);
}

TEST(UpgradeLegacy, A135CompareSizedNodesAndUdimTokensAreRenamed) {
  const char* text =
      "<materialx version=\"1.35\">\n"
      "  <compare name=\"choose\" type=\"float\">\n"
      "    <input name=\"intest\" type=\"float\" value=\"0.3\"/>\n"
      "    <parameter name=\"cutoff\" type=\"float\" value=\"0.5\"/>\n"
      "    <input name=\"in1\" type=\"float\" value=\"1\"/>\n"
      "    <input name=\"in2\" type=\"float\" value=\"2\"/>\n"
      "  </compare>\n"
      "  <combine name=\"c\" type=\"vector3\">\n"
      "    <input name=\"in1\" type=\"float\" value=\"1\"/>\n"
      "    <input name=\"in2\" type=\"float\" value=\"2\"/>\n"
      "    <input name=\"in3\" type=\"float\" value=\"3\"/>\n"
      "  </combine>\n"
      "  <rotate name=\"r\" type=\"vector2\"/>\n"
      "  <image name=\"img\" type=\"color3\">\n"
      "    <parameter name=\"file\" type=\"filename\" value=\"tiles.%UDIM.png\"/>\n"
      "  </image>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* choose = r.top.findNode("choose");
  EXPECT_EQ(choose->category(), "ifgreatereq");
  EXPECT_FLOAT_EQ(inputOf(r, "choose", "value1")->value->as<float>(), 0.3f);
  EXPECT_FLOAT_EQ(inputOf(r, "choose", "value2")->value->as<float>(), 0.5f);
  // compare took in1 when intest <= cutoff; ifgreatereq takes in1 when value1 >= value2.
  EXPECT_FLOAT_EQ(inputOf(r, "choose", "in1")->value->as<float>(), 2.0f);
  EXPECT_FLOAT_EQ(inputOf(r, "choose", "in2")->value->as<float>(), 1.0f);
  EXPECT_EQ(r.top.findNode("c")->category(), "combine3");
  EXPECT_EQ(r.top.findNode("r")->category(), "rotate2d");
  EXPECT_EQ(r.document->findNode("img")->findInput("file")->valueString, "tiles.<UDIM>.png");
}

TEST(UpgradeLegacy, ChannelsAreReadInOlderDocumentsAndRefusedIn139) {
  auto document = [](const char* version) {
    return fmt::format(
        "<materialx version=\"{}\">\n"
        "  <constant name=\"k\" type=\"float\"/>\n"
        "  <add name=\"a\" type=\"color3\">\n"
        "    <input name=\"in1\" type=\"color3\" nodename=\"k\" channels=\"rrr\"/>\n"
        "  </add>\n"
        "</materialx>\n",
        version);
  };
  Context older;
  older.resolve(document("1.37"));
  EXPECT_FALSE(older.diagnostics.hasErrors()) << older.diagnostics.format();
  Context current;
  current.resolve(document("1.39"));
  EXPECT_NE(current.firstError().message.find("removed in 1.39"), std::string::npos) << current.diagnostics.format();
}

}  // namespace
}  // namespace mxc::test
