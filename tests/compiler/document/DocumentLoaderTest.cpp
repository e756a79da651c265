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
