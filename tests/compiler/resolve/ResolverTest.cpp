// Graph resolution on valid documents: nodedef choice, input sources, interfaces, graph
// outputs, materials, dependency order.

#include "compiler/resolve/Resolver.h"

#include <gtest/gtest.h>

#include "support/TestSupport.h"

namespace mxc::test {
namespace {

using resolve::InputSource;

TEST(Resolver, PicksTheNodedefByOutputAndInputTypes) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <add name=\"plain\" type=\"color3\">\n    <input name=\"in2\" type=\"color3\" value=\"1,1,1\"/>\n  </add>\n"
      "  <add name=\"scalar\" type=\"color3\">\n    <input name=\"in2\" type=\"float\" value=\"1\"/>\n  </add>\n"
      "  <add name=\"bare\" type=\"vector2\"/>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(r.top.findNode("plain")->nodedef->name, "ND_add_color3");
  EXPECT_EQ(r.top.findNode("scalar")->nodedef->name, "ND_add_color3FA");
  // Unset inputs cannot tell ND_add_vector2 from ND_add_vector2FA: the first declared wins.
  EXPECT_EQ(r.top.findNode("bare")->nodedef->name, "ND_add_vector2");
}

TEST(Resolver, VersionsDefaultAndExplicit) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <standard_surface name=\"latest\" type=\"surfaceshader\"/>\n"
      "  <standard_surface name=\"old\" type=\"surfaceshader\" version=\"1.0.0\"/>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(r.top.findNode("latest")->nodedef->name, "ND_standard_surface_surfaceshader");
  EXPECT_EQ(r.top.findNode("old")->nodedef->name, "ND_standard_surface_surfaceshader_100");
}

TEST(Resolver, InputSources) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <constant name=\"c\" type=\"color3\">\n    <input name=\"value\" type=\"color3\" value=\"0.1, 0.2, 0.3\"/>\n"
      "  </constant>\n"
      "  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
      "    <input name=\"base_color\" type=\"color3\" nodename=\"c\"/>\n"
      "    <input name=\"specular_roughness\" type=\"float\" value=\"0.25\"/>\n"
      "  </open_pbr_surface>\n"
      "  <surfacematerial name=\"m\" type=\"material\">\n"
      "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/>\n  </surfacematerial>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* s = r.top.findNode("s");
  ASSERT_NE(s, nullptr);
  // Every nodedef input is present, in nodedef order.
  EXPECT_EQ(s->inputs.size(), context.libraries.top().signature(*s->nodedef).inputs.size());
  EXPECT_EQ(s->inputs.front().name, "base_weight");
  const resolve::ResolvedInput* color = s->findInput("base_color");
  EXPECT_EQ(color->source, InputSource::Connection);
  EXPECT_EQ(color->upstream.node, r.top.findNode("c"));
  EXPECT_EQ(color->upstream.output, "out");
  EXPECT_EQ(color->location.line(), 7u);
  const resolve::ResolvedInput* roughness = s->findInput("specular_roughness");
  EXPECT_EQ(roughness->source, InputSource::Value);
  EXPECT_FLOAT_EQ(roughness->value->as<float>(), 0.25f);
  const resolve::ResolvedInput* ior = s->findInput("specular_ior");
  EXPECT_EQ(ior->source, InputSource::Default);
  EXPECT_FLOAT_EQ(ior->value->as<float>(), 1.5f);
  EXPECT_EQ(ior->instance, nullptr);
  EXPECT_NE(ior->location.file->path().find("nodedefs/bxdf/open_pbr_surface.mtlx"), std::string::npos);
  const resolve::ResolvedInput* normal = s->findInput("geometry_normal");
  EXPECT_EQ(normal->source, InputSource::GeomProp);
  EXPECT_EQ(normal->geomprop, "Nworld");
  // Producers come before consumers.
  ASSERT_EQ(r.top.nodes.size(), 3u);
  EXPECT_EQ(r.top.nodes[0]->name(), "c");
  EXPECT_EQ(r.top.nodes[2]->name(), "m");
  ASSERT_EQ(r.materials.size(), 1u);
  ASSERT_EQ(r.materials[0].shaders.size(), 1u);
  EXPECT_EQ(r.materials[0].shaders[0].node, s);
  EXPECT_EQ(r.materials[0].shaders[0].input, "surfaceshader");
}

TEST(Resolver, GraphInterfaceOutputsAndFilePrefix) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(
      "<materialx version=\"1.39\" fileprefix=\"textures/\">\n"
      "  <nodegraph name=\"NG\">\n"
      "    <input name=\"tiling\" type=\"vector2\" value=\"2, 2\"/>\n"
      "    <tiledimage name=\"tex\" type=\"color3\">\n"
      "      <input name=\"file\" type=\"filename\" value=\"wood.png\"/>\n"
      "      <input name=\"uvtiling\" type=\"vector2\" interfacename=\"tiling\"/>\n"
      "    </tiledimage>\n"
      "    <output name=\"color\" type=\"color3\" nodename=\"tex\"/>\n"
      "  </nodegraph>\n"
      "  <standard_surface name=\"s\" type=\"surfaceshader\">\n"
      "    <input name=\"base_color\" type=\"color3\" nodegraph=\"NG\" output=\"color\"/>\n"
      "  </standard_surface>\n"
      "  <surfacematerial name=\"m\" type=\"material\">\n"
      "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/>\n  </surfacematerial>\n"
      "</materialx>\n");
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedGraph* g = r.findGraph("NG");
  ASSERT_NE(g, nullptr);
  const resolve::ResolvedNode* tex = g->findNode("tex");
  EXPECT_EQ(tex->findInput("file")->value->as<std::string>(), "textures/wood.png");
  EXPECT_EQ(tex->findInput("uvtiling")->source, InputSource::Interface);
  EXPECT_EQ(g->findInterface("tiling")->value->as<glm::vec2>(), glm::vec2(2, 2));
  EXPECT_EQ(tex->findInput("texcoord")->geomprop, "UV0");
  const resolve::ResolvedInput* color = r.top.findNode("s")->findInput("base_color");
  EXPECT_EQ(color->upstream.graph, g);
  EXPECT_EQ(color->upstream.output, "color");
  EXPECT_EQ(g->findOutput("color")->upstream.node, tex);
}

TEST(Resolver, FilenameTokensAreSubstituted) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <nodegraph name=\"NG\">\n    <token name=\"size\" type=\"string\" value=\"2k\"/>\n"
      "    <image name=\"img\" type=\"color3\">\n"
      "      <input name=\"file\" type=\"filename\" value=\"wood_[size]_[size].png\"/>\n    </image>\n"
      "    <output name=\"out\" type=\"color3\" nodename=\"img\"/>\n  </nodegraph>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(r.findGraph("NG")->findNode("img")->findInput("file")->value->as<std::string>(), "wood_2k_2k.png");
}

// Tokens are looked up from the innermost element out (MaterialX's token_graph_material.mtlx):
// a node's own tokens, then its graph's, then the document's; a graph's interface input takes
// its graph's tokens; an implementation graph sees its nodedef's.
TEST(Resolver, TheInnermostTokenIsSubstituted) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <token name=\"ext\" type=\"string\" value=\"jpg\"/>\n"
      "  <token name=\"res\" type=\"string\" value=\"1k\"/>\n"
      "  <nodegraph name=\"NG\">\n    <token name=\"name\" type=\"string\" value=\"cloth\"/>\n"
      "    <input name=\"f\" type=\"filename\" value=\"[name]_[res].[ext]\"/>\n"
      "    <image name=\"a\" type=\"color3\">\n      <input name=\"file\" type=\"filename\" interfacename=\"f\"/>\n    </image>\n"
      "    <image name=\"b\" type=\"color3\">\n      <token name=\"ext\" type=\"string\" value=\"png\"/>\n"
      "      <input name=\"file\" type=\"filename\" value=\"[name].[ext][missing]\"/>\n    </image>\n"
      "    <output name=\"out\" type=\"color3\" nodename=\"a\"/>\n  </nodegraph>\n"
      "  <nodedef name=\"ND_tok\" node=\"tok\">\n    <token name=\"name\" type=\"string\" value=\"grid\"/>\n"
      "    <output name=\"out\" type=\"color3\"/>\n  </nodedef>\n"
      "  <nodegraph name=\"NG_tok\" nodedef=\"ND_tok\">\n    <image name=\"c\" type=\"color3\">\n"
      "      <input name=\"file\" type=\"filename\" value=\"[name].[ext]\"/>\n    </image>\n"
      "    <output name=\"out\" type=\"color3\" nodename=\"c\"/>\n  </nodegraph>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedGraph* g = r.findGraph("NG");
  EXPECT_EQ(g->findInterface("f")->value->as<std::string>(), "cloth_1k.jpg");
  EXPECT_EQ(g->findNode("b")->findInput("file")->value->as<std::string>(), "cloth.png[missing]");
  EXPECT_EQ(r.findGraph("NG_tok")->findNode("c")->findInput("file")->value->as<std::string>(), "grid.jpg");
}

// The document is a node graph too (MaterialX 1.39): inputs, outputs and tokens written directly
// under <materialx> are its interface, outputs and tokens (MaterialX's test suite:
// top_level_input.mtlx, token_graph_material.mtlx, and about 20 documents with outputs).
TEST(Resolver, TheDocumentHasItsOwnInterfaceOutputsAndTokens) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <input name=\"tint\" type=\"color3\" value=\"0, 0, 1\"/>\n"
      "  <token name=\"size\" type=\"string\" value=\"2k\"/>\n"
      "  <image name=\"img\" type=\"color3\">\n"
      "    <input name=\"file\" type=\"filename\" value=\"wood_[size].png\"/>\n  </image>\n"
      "  <multiply name=\"mul\" type=\"color3\">\n"
      "    <input name=\"in1\" type=\"color3\" nodename=\"img\"/>\n"
      "    <input name=\"in2\" type=\"color3\" interfacename=\"tint\"/>\n  </multiply>\n"
      "  <output name=\"out\" type=\"color3\" nodename=\"mul\"/>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(r.top.findNode("img")->findInput("file")->value->as<std::string>(), "wood_2k.png");
  const resolve::ResolvedNode* mul = r.top.findNode("mul");
  EXPECT_EQ(mul->findInput("in2")->source, InputSource::Interface);
  EXPECT_EQ(r.top.findInterface("tint")->value->as<glm::vec3>(), glm::vec3(0, 0, 1));
  ASSERT_NE(r.top.findOutput("out"), nullptr);
  EXPECT_EQ(r.top.findOutput("out")->upstream.node, mul);
}

// At document level `nodename` may name a node graph, as MaterialX reads it
// (cascade_nodegraphs.mtlx): the connection is to that graph's output.
TEST(Resolver, ADocumentOutputsNodenameMayNameAGraph) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <nodegraph name=\"NG\">\n    <constant name=\"c\" type=\"color3\"/>\n"
      "    <output name=\"o1\" type=\"color3\" nodename=\"c\"/>\n    <output name=\"o2\" type=\"color3\" nodename=\"c\"/>\n"
      "  </nodegraph>\n  <output name=\"out\" type=\"color3\" nodename=\"NG\" output=\"o2\"/>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  ASSERT_NE(r.top.findOutput("out"), nullptr);
  EXPECT_EQ(r.top.findOutput("out")->upstream.graph, r.findGraph("NG"));
  EXPECT_EQ(r.top.findOutput("out")->upstream.output, "o2");
}

// MaterialX namespaces: a nodedef, node graph or implementation in a namespace (its own
// attribute or the document's) is known as "ns:name", defines the category "ns:node", and its
// references are read in the namespace (toon_shade.mtlx of MaterialX's test suite).
TEST(Resolver, NamespacesQualifyDefinitionsAndTheirReferences) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <nodedef name=\"ND_t\" node=\"t\" namespace=\"acme\">\n"
      "    <input name=\"k\" type=\"float\" value=\"2\"/>\n    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"
      "  <nodegraph name=\"NG_t\" nodedef=\"ND_t\" namespace=\"acme\">\n"
      "    <multiply name=\"m\" type=\"float\"><input name=\"in1\" type=\"float\" interfacename=\"k\"/></multiply>\n"
      "    <output name=\"out\" type=\"float\" nodename=\"m\"/>\n  </nodegraph>\n"
      "  <acme:t name=\"x\" type=\"float\"><input name=\"k\" type=\"float\" value=\"3\"/></acme:t>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const resolve::ResolvedNode* x = r.top.findNode("x");
  ASSERT_NE(x, nullptr);
  ASSERT_NE(x->nodedef, nullptr);
  EXPECT_EQ(x->nodedef->name, "acme:ND_t");
  const doc::NodeGraph* graph = r.definitions->implementationGraph(*x->nodedef);
  ASSERT_NE(graph, nullptr);
  EXPECT_EQ(graph->name, "acme:NG_t");
}

// A nodedef without `node` defines no category (MaterialX's _options.mtlx keeps settings in one).
TEST(Resolver, ANodedefWithoutANodeDefinesNothing) {
  Context context;
  context.resolve(mtlx("  <nodedef name=\"Options\">\n    <input name=\"x\" type=\"float\" value=\"1\"/>\n  </nodedef>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
}

TEST(Resolver, ShaderBehindAGraphOutputIsTheMaterialsShader) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(
      "  <nodegraph name=\"NG\">\n    <oren_nayar_diffuse_bsdf name=\"d\" type=\"BSDF\"/>\n"
      "    <surface name=\"s\" type=\"surfaceshader\">\n      <input name=\"bsdf\" type=\"BSDF\" nodename=\"d\"/>\n"
      "    </surface>\n    <output name=\"out\" type=\"surfaceshader\" nodename=\"s\"/>\n  </nodegraph>\n"
      "  <surfacematerial name=\"m\" type=\"material\">\n"
      "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodegraph=\"NG\"/>\n  </surfacematerial>\n"));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  ASSERT_EQ(r.materials.size(), 1u);
  ASSERT_EQ(r.materials[0].shaders.size(), 1u);
  EXPECT_EQ(r.materials[0].shaders[0].node->name(), "s");
}

TEST(Resolver, Channels138SwizzleIsKeptOnTheConnection) {
  Context context;
  resolve::ResolvedDocument r = context.resolve(
      "<materialx version=\"1.38\">\n  <constant name=\"c\" type=\"color3\"/>\n"
      "  <add name=\"a\" type=\"vector2\">\n    <input name=\"in1\" type=\"vector2\" nodename=\"c\" channels=\"bg\"/>\n"
      "  </add>\n</materialx>\n");
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(r.top.findNode("a")->findInput("in1")->channels, "bg");
}

TEST(Resolver, LongChainsResolveWithoutDeepRecursion) {
  // 20000 nodes in a chain: ordering is iterative, so the call stack does not grow with it.
  std::string body = "  <constant name=\"n0\" type=\"float\"/>\n";
  for (int i = 1; i < 20000; ++i) {
    body += "  <add name=\"n" + std::to_string(i) + "\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"n" +
            std::to_string(i - 1) + "\"/></add>\n";
  }
  Context context;
  resolve::ResolvedDocument r = context.resolve(mtlx(body));
  EXPECT_FALSE(context.diagnostics.hasErrors());
  ASSERT_EQ(r.top.nodes.size(), 20000u);
  EXPECT_EQ(r.top.nodes.front()->name(), "n0");
  EXPECT_EQ(r.top.nodes.back()->name(), "n19999");
}

}  // namespace
}  // namespace mxc::test
