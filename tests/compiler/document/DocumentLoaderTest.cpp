// Loading from files: xi:include (relative paths, diamonds, cycles), the 1.38 upgrade, and
// the document model read from a real corpus file.

#include "compiler/document/DocumentLoader.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/TestSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

/// A fresh folder under the test's temporary directory.
fs::path scratch(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("mxc_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

TEST(DocumentLoader, IncludesResolveRelativeToTheIncludingFile) {
  fs::path dir = scratch("include");
  fs::create_directories(dir / "sub");
  write(dir / "main.mtlx", mtlx("  <xi:include href=\"sub/a.mtlx\"/>\n  <xi:include href=\"sub/b.mtlx\"/>\n"));
  write(dir / "sub/a.mtlx", mtlx("  <xi:include href=\"common.mtlx\"/>\n  <constant name=\"a\" type=\"float\"/>\n"));
  write(dir / "sub/b.mtlx", mtlx("  <xi:include href=\"common.mtlx\"/>\n  <constant name=\"b\" type=\"float\"/>\n"));
  write(dir / "sub/common.mtlx", mtlx("  <constant name=\"common\" type=\"float\"/>\n"));
  Context context;
  const doc::Document* d = context.loader.loadFile(dir / "main.mtlx");
  ASSERT_NE(d, nullptr);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  // The diamond (a and b both include common) loads common once.
  EXPECT_EQ(context.loader.documents().size(), 4u);
  resolve::ResolvedDocument r = resolve::resolveDocument(*d, context.libraries.top(), context.diagnostics);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_NE(r.top.findNode("a"), nullptr);
  EXPECT_NE(r.top.findNode("common"), nullptr);
  fs::remove_all(dir);
}

TEST(DocumentLoader, IncludeCycleIsReportedAtTheInclude) {
  fs::path dir = scratch("cycle");
  write(dir / "a.mtlx", mtlx("  <xi:include href=\"b.mtlx\"/>\n"));
  write(dir / "b.mtlx", mtlx("  <xi:include href=\"a.mtlx\"/>\n"));
  Context context;
  context.loader.loadFile(dir / "a.mtlx");
  Diagnostic e = context.firstError();
  EXPECT_NE(e.message.find("include cycle: a.mtlx -> b.mtlx -> a.mtlx"), std::string::npos) << e.message;
  EXPECT_EQ(fs::path(e.location.file->path()).filename(), "b.mtlx");
  EXPECT_EQ(e.location.line(), 3u);
  fs::remove_all(dir);
}

TEST(DocumentLoader, ALongIncludeChainEndingInACycle) {
  // 3,000 documents, each including the next, the last including the 2,000th: every one is
  // loaded once, and the cycle is reported once, from where it starts. (The chain is
  // looked up in a set, so loading is linear in its length: tests/bench/ScaleBench.cpp prints
  // the growth.)
  fs::path dir = scratch("chain");
  constexpr int kFiles = 3000;
  for (int i = 0; i < kFiles; ++i) {
    const int next = i + 1 < kFiles ? i + 1 : 2000;
    write(dir / ("c" + std::to_string(i) + ".mtlx"),
          mtlx("  <xi:include href=\"c" + std::to_string(next) + ".mtlx\"/>\n  <constant name=\"k" + std::to_string(i) +
               "\" type=\"float\"/>\n"));
  }
  Context context;
  context.loader.loadFile(dir / "c0.mtlx");
  EXPECT_EQ(context.loader.documents().size(), size_t(kFiles));
  EXPECT_EQ(context.diagnostics.errorCount(), 1u);
  Diagnostic e = context.firstError();
  EXPECT_EQ(e.message.rfind("include cycle: c2000.mtlx -> c2001.mtlx", 0), 0u) << e.message.substr(0, 80);
  EXPECT_EQ(fs::path(e.location.file->path()).filename(), "c2999.mtlx");
  fs::remove_all(dir);
}

TEST(DocumentLoader, SameNameInTwoIncludedDocumentsIsAnError) {
  fs::path dir = scratch("clash");
  write(dir / "main.mtlx", mtlx("  <xi:include href=\"other.mtlx\"/>\n  <constant name=\"x\" type=\"float\"/>\n"));
  write(dir / "other.mtlx", mtlx("  <constant name=\"x\" type=\"float\"/>\n"));
  Context context;
  const doc::Document* d = context.loader.loadFile(dir / "main.mtlx");
  ASSERT_NE(d, nullptr);
  resolve::resolveDocument(*d, context.libraries.top(), context.diagnostics);
  EXPECT_NE(context.firstError().message.find("'x' is also defined at"), std::string::npos);
  fs::remove_all(dir);
}

TEST(DocumentLoader, MissingFileAndDirectory) {
  Context context;
  EXPECT_EQ(context.loader.loadFile("/no/such/file.mtlx"), nullptr);
  EXPECT_NE(context.firstError().message.find("cannot read '/no/such/file.mtlx'"), std::string::npos);
  Context again;
  EXPECT_EQ(again.loader.loadFile(fs::temp_directory_path()), nullptr);
  EXPECT_NE(again.firstError().message.find("it is a directory"), std::string::npos);
}

TEST(DocumentLoader, Upgrades138ThinFilmLayerIntoTheBsdfs) {
  // The MaterialX 1.38 form: layer(thin_film_bsdf, mix(conductor, dielectric)).
  const char* text =
      "<materialx version=\"1.38\">\n"
      "  <thin_film_bsdf name=\"film\" type=\"BSDF\">\n"
      "    <input name=\"thickness\" type=\"float\" value=\"400\"/>\n"
      "  </thin_film_bsdf>\n"
      "  <conductor_bsdf name=\"metal\" type=\"BSDF\"/>\n"
      "  <dielectric_bsdf name=\"spec\" type=\"BSDF\"/>\n"
      "  <mix name=\"both\" type=\"BSDF\">\n"
      "    <input name=\"fg\" type=\"BSDF\" nodename=\"metal\"/>\n"
      "    <input name=\"bg\" type=\"BSDF\" nodename=\"spec\"/>\n"
      "  </mix>\n"
      "  <layer name=\"filmed\" type=\"BSDF\">\n"
      "    <input name=\"top\" type=\"BSDF\" nodename=\"film\"/>\n"
      "    <input name=\"base\" type=\"BSDF\" nodename=\"both\"/>\n"
      "  </layer>\n"
      "  <surface name=\"surf\" type=\"surfaceshader\">\n"
      "    <input name=\"bsdf\" type=\"BSDF\" nodename=\"filmed\"/>\n"
      "  </surface>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  ASSERT_EQ(r.document->upgradeNotes.size(), 1u);
  EXPECT_EQ(r.top.findNode("filmed"), nullptr);
  EXPECT_EQ(r.top.findNode("film"), nullptr);
  const resolve::ResolvedNode* surf = r.top.findNode("surf");
  ASSERT_NE(surf, nullptr);
  EXPECT_EQ(surf->findInput("bsdf")->upstream.node->name(), "both");
  for (const char* name : {"metal", "spec"}) {
    const resolve::ResolvedInput* t = r.top.findNode(name)->findInput("thinfilm_thickness");
    ASSERT_EQ(t->source, resolve::InputSource::Value) << name;
    EXPECT_FLOAT_EQ(t->value->as<float>(), 400.0f);
    // The film's IOR was not written: the 1.38 default of thin_film_bsdf (1.5) applies.
    EXPECT_FLOAT_EQ(r.top.findNode(name)->findInput("thinfilm_ior")->value->as<float>(), 1.5f);
  }
}

TEST(DocumentLoader, Upgrades138SubsurfaceRadiusAndAtan2) {
  const char* text =
      "<materialx version=\"1.38\">\n"
      "  <constant name=\"r\" type=\"vector3\"/>\n"
      "  <subsurface_bsdf name=\"sss\" type=\"BSDF\">\n"
      "    <input name=\"radius\" type=\"vector3\" nodename=\"r\"/>\n"
      "  </subsurface_bsdf>\n"
      "  <atan2 name=\"angle\" type=\"float\">\n"
      "    <input name=\"in1\" type=\"float\" value=\"1\"/>\n"
      "    <input name=\"in2\" type=\"float\" value=\"2\"/>\n"
      "  </atan2>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedInput* radius = r.top.findNode("sss")->findInput("radius");
  ASSERT_EQ(radius->source, resolve::InputSource::Connection);
  EXPECT_EQ(radius->upstream.node->category(), "convert");
  EXPECT_EQ(radius->upstream.type, "color3");
  // The added convert is placed at the radius input it serves (line 4), not at its node.
  EXPECT_EQ(radius->upstream.node->node->location.line(), 4u);
  EXPECT_EQ(radius->upstream.node->findInput("in")->location.line(), 4u);
  EXPECT_FLOAT_EQ(r.top.findNode("angle")->findInput("iny")->value->as<float>(), 1.0f);
  EXPECT_FLOAT_EQ(r.top.findNode("angle")->findInput("inx")->value->as<float>(), 2.0f);
}

TEST(DocumentModel, Upgrades138SwizzleNodes) {
  // MaterialX 1.39 removed <swizzle>: a connected one becomes a dot taking the channels of its
  // input (the 1.38 form the resolver applies), one of a value a constant of the components.
  const std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<materialx version=\"1.38\">\n"
      "  <constant name=\"c\" type=\"color3\"><input name=\"value\" type=\"color3\" value=\"0.1, 0.2, 0.3\"/></constant>\n"
      "  <swizzle name=\"connected\" type=\"color4\">\n"
      "    <input name=\"in\" type=\"color3\" nodename=\"c\"/>\n"
      "    <input name=\"channels\" type=\"string\" value=\"bgr1\"/>\n"
      "  </swizzle>\n"
      "  <swizzle name=\"valued\" type=\"vector3\">\n"
      "    <input name=\"in\" type=\"vector3\" value=\"0.1, 0.2, 0.3\"/>\n"
      "    <input name=\"channels\" type=\"string\" value=\"z0x\"/>\n"
      "  </swizzle>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* connected = r.top.findNode("connected");
  ASSERT_NE(connected, nullptr);
  EXPECT_EQ(connected->category(), "dot");
  ASSERT_NE(connected->findInput("in"), nullptr);
  EXPECT_EQ(connected->findInput("in")->channels, "bgr1");
  EXPECT_EQ(connected->findInput("in")->upstream.node->name(), "c");
  const resolve::ResolvedNode* valued = r.top.findNode("valued");
  ASSERT_NE(valued, nullptr);
  EXPECT_EQ(valued->category(), "constant");
  ASSERT_NE(valued->findInput("value"), nullptr);
  ASSERT_TRUE(valued->findInput("value")->value.has_value());
  const std::vector<float> v = valued->findInput("value")->value->components();
  EXPECT_EQ(v, (std::vector<float>{0.3f, 0.0f, 0.1f}));
}

// MaterialX 1.39 renamed ND_normalmap to ND_normalmap_float and removed normalmap's `space`:
// an object-space map becomes normalize(in * 2 - 1), a tangent-space one given a normal or a
// tangent gets the bitangent 1.38 derived, normalize(cross(N, T)). A swizzle's nodedef name
// goes with the swizzle, and a switch's constant `which` of 5 or more (in1 in 1.38) becomes 0.
// (MaterialX's test suite: stdlib/upgrade/syntax_1_38.mtlx.)
TEST(DocumentModel, Upgrades138NormalMapsSwizzleNodeDefsAndSwitches) {
  const std::string text =
      "<materialx version=\"1.38\">\n"
      "  <constant name=\"t\" type=\"vector3\"/>\n"
      "  <normalmap name=\"named\" type=\"vector3\" nodedef=\"ND_normalmap\">\n"
      "    <input name=\"in\" type=\"vector3\" nodename=\"t\"/>\n"
      "  </normalmap>\n"
      "  <normalmap name=\"object\" type=\"vector3\" nodedef=\"ND_normalmap\">\n"
      "    <input name=\"in\" type=\"vector3\" nodename=\"t\"/>\n"
      "    <input name=\"space\" type=\"string\" value=\"object\"/>\n"
      "  </normalmap>\n"
      "  <normalmap name=\"framed\" type=\"vector3\">\n"
      "    <input name=\"in\" type=\"vector3\" nodename=\"t\"/>\n"
      "    <input name=\"space\" type=\"string\" value=\"tangent\"/>\n"
      "    <input name=\"tangent\" type=\"vector3\" nodename=\"t\"/>\n"
      "  </normalmap>\n"
      "  <swizzle name=\"s\" type=\"color3\" nodedef=\"ND_swizzle_color3_color3\">\n"
      "    <input name=\"in\" type=\"color3\" value=\"0.4, 0.5, 0.6\"/>\n"
      "    <input name=\"channels\" type=\"string\" value=\"bgr\"/>\n"
      "  </swizzle>\n"
      "  <switch name=\"far\" type=\"float\">\n"
      "    <input name=\"in1\" type=\"float\" value=\"1\"/>\n"
      "    <input name=\"which\" type=\"integer\" value=\"7\"/>\n"
      "  </switch>\n"
      "  <switch name=\"near\" type=\"float\">\n"
      "    <input name=\"which\" type=\"integer\" value=\"4\"/>\n"
      "  </switch>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* named = r.top.findNode("named");
  ASSERT_NE(named, nullptr);
  ASSERT_NE(named->nodedef, nullptr);
  EXPECT_EQ(named->nodedef->name, "ND_normalmap_float");
  EXPECT_EQ(named->findInput("space"), nullptr);

  const resolve::ResolvedNode* object = r.top.findNode("object");
  ASSERT_NE(object, nullptr);
  EXPECT_EQ(object->category(), "normalize");
  const resolve::ResolvedNode* centred = object->findInput("in")->upstream.node;
  ASSERT_NE(centred, nullptr);
  EXPECT_EQ(centred->category(), "subtract");
  EXPECT_FLOAT_EQ(centred->findInput("in2")->value->as<float>(), 1.0f);
  const resolve::ResolvedNode* decoded = centred->findInput("in1")->upstream.node;
  ASSERT_NE(decoded, nullptr);
  EXPECT_EQ(decoded->category(), "multiply");
  EXPECT_EQ(decoded->findInput("in1")->upstream.node->name(), "t");
  EXPECT_FLOAT_EQ(decoded->findInput("in2")->value->as<float>(), 2.0f);

  const resolve::ResolvedNode* framed = r.top.findNode("framed");
  ASSERT_NE(framed, nullptr);
  const resolve::ResolvedInput* bitangent = framed->findInput("bitangent");
  ASSERT_NE(bitangent, nullptr);
  ASSERT_EQ(bitangent->source, resolve::InputSource::Connection);
  EXPECT_EQ(bitangent->upstream.node->category(), "normalize");
  const resolve::ResolvedNode* cross = bitangent->upstream.node->findInput("in")->upstream.node;
  ASSERT_NE(cross, nullptr);
  EXPECT_EQ(cross->category(), "crossproduct");
  EXPECT_EQ(cross->findInput("in1")->upstream.node->category(), "normal");  // the geometry's normal
  EXPECT_EQ(cross->findInput("in2")->upstream.node->name(), "t");            // the tangent given

  const resolve::ResolvedNode* s = r.top.findNode("s");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->category(), "constant");
  EXPECT_EQ(s->nodedef->name, "ND_constant_color3");
  EXPECT_EQ(r.top.findNode("far")->findInput("which")->value->as<int32_t>(), 0);
  EXPECT_EQ(r.top.findNode("near")->findInput("which")->value->as<int32_t>(), 4);
}

// A number MaterialX's reader takes (the longest prefix that is a number: its test suite's
// vector_math.mtlx writes "0.5.0") is read as it reads it, with a warning after the number.
TEST(DocumentModel, NumbersMaterialXReadsAreReadWithAWarning) {
  const std::string text =
      "<materialx version=\"1.39\">\n"
      "  <constant name=\"c\" type=\"vector3\">\n"
      "    <input name=\"value\" type=\"vector3\" value=\"1, 0.5.0, 2\"/>\n"
      "  </constant>\n"
      "</materialx>\n";
  Context context;
  resolve::ResolvedDocument r = context.resolve(text);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* c = r.top.findNode("c");
  ASSERT_NE(c, nullptr);
  ASSERT_TRUE(c->findInput("value")->value.has_value());
  EXPECT_EQ(c->findInput("value")->value->components(), (std::vector<float>{1.0f, 0.5f, 2.0f}));
  const std::string messages = context.diagnostics.format();
  EXPECT_NE(messages.find(":3:53: warning: vector3 value \"1, 0.5.0, 2\" for 'value': '0.5.0' is read as 0.5"), std::string::npos)
      << messages;
}

TEST(DocumentModel, ReadsACorpusDocument) {
  Context context;
  const doc::Document* d =
      context.loader.loadFile(sharedDir() / "corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->version, "1.39");
  EXPECT_EQ(d->colorspace, "lin_rec709");
  ASSERT_EQ(d->nodegraphs.size(), 1u);
  const doc::NodeGraph& g = d->nodegraphs[0];
  EXPECT_EQ(g.name, "NG_BrickPattern");
  EXPECT_EQ(g.inputs.size(), 7u);
  EXPECT_EQ(g.outputs.size(), 3u);
  const doc::Input* tiling = g.findInput("uvtiling");
  ASSERT_NE(tiling, nullptr);
  EXPECT_FLOAT_EQ(tiling->value->as<float>(), 3.0f);
  EXPECT_EQ(tiling->element.attribute("uisoftmax"), "16");
  // fileprefix is inherited from <materialx> by every input.
  EXPECT_EQ(g.findNode("node_tiledimage_float_7")->findInput("file")->fileprefix, "../../../Images/");
  EXPECT_EQ(d->nodes.size(), 2u);
  EXPECT_EQ(d->nodes[1].category, "surfacematerial");
  EXPECT_EQ(d->nodes[1].location.line(), 129u);
}

}  // namespace
}  // namespace mxc::test
