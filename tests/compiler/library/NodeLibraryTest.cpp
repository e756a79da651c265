// Node libraries: the built-in library against MaterialX's definitions, layering and
// shadowing, inheritance, and implementations.

#include "compiler/library/NodeLibrary.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/TestSupport.h"

namespace mxc::test {
namespace {

TEST(NodeLibrary, BuiltinLibraryLoadsCleanly) {
  Context context;
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(context.libraries.top().nodeDefCount(), 811u);
  EXPECT_NE(context.libraries.top().findNodeDef("ND_open_pbr_surface_surfaceshader"), nullptr);
  EXPECT_NE(context.libraries.top().findGeomPropDef("Nworld"), nullptr);
  EXPECT_TRUE(context.libraries.top().isKnownType("BSDF"));
}

/// Enum lists compare without the spaces after commas that some libraries write.
std::string withoutSpaces(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c != ' ') out += c;
  }
  return out;
}

bool sameValue(const doc::Input& a, const doc::Input& b) {
  if (a.value.has_value() != b.value.has_value()) return false;
  if (!a.value) return true;
  std::vector<float> x = a.value->components();
  std::vector<float> y = b.value->components();
  if (x.empty() && y.empty()) return a.value->str() == b.value->str();
  if (x.size() != y.size()) return false;
  for (size_t i = 0; i < x.size(); ++i) {
    if (std::abs(x[i] - y[i]) > 1e-6f * std::max(1.0f, std::abs(y[i]))) return false;
  }
  return true;
}

// Every MaterialX nodedef has ours under the same name with the same signature: category,
// inputs (order, type, default, defaultgeomprop, uniform, enum) and outputs.
TEST(NodeLibrary, BuiltinIsSignatureCompatibleWithMaterialX) {
  Context ours;
  Context theirs(false);
  ASSERT_TRUE(theirs.libraries.addFolder(sharedDir() / "reference/materialx/libraries"));
  ASSERT_FALSE(theirs.diagnostics.hasErrors()) << theirs.diagnostics.format();
  const lib::NodeLibrary& mine = ours.libraries.top();
  const lib::NodeLibrary& mx = theirs.libraries.top();
  size_t compared = 0;
  for (const doc::Document* d : mx.documents()) {
    for (const doc::NodeDef& theirDef : d->nodedefs) {
      // Helpers that only MaterialX's own OpenPBR graph uses; mxc lowers OpenPBR in C++.
      if (theirDef.name == "ND_open_pbr_anisotropy") continue;
      // Only the definitions of the libraries mxc provides (not translations).
      std::string path = d->path();
      bool provided = path.find("_defs.mtlx") != std::string::npos || path.find("bxdf/standard_surface") != std::string::npos ||
                      path.find("bxdf/usd_preview_surface") != std::string::npos ||
                      path.find("bxdf/open_pbr_surface") != std::string::npos ||
                      path.find("bxdf/disney_principled") != std::string::npos ||
                      path.find("bxdf/lama/") != std::string::npos ||
                      theirDef.name == "ND_UsdPreviewSurface_surfaceshader" || theirDef.name == "ND_gltf_pbr_surfaceshader" ||
                      theirDef.name.starts_with("ND_gltf_image_") || theirDef.name == "ND_gltf_colorimage" ||
                      theirDef.name == "ND_gltf_normalmap_vector3_1_0" ||
                      theirDef.name == "ND_gltf_iridescence_thickness_float_1_0" || theirDef.name == "ND_gltf_anisotropy_image";
      if (!provided) continue;
      const doc::NodeDef* myDef = mine.findNodeDef(theirDef.name);
      ASSERT_NE(myDef, nullptr) << theirDef.name;
      EXPECT_EQ(myDef->node, theirDef.node) << theirDef.name;
      EXPECT_EQ(myDef->version, theirDef.version) << theirDef.name;
      EXPECT_EQ(myDef->inherit, theirDef.inherit) << theirDef.name;
      const lib::Signature& a = mine.signature(*myDef);
      const lib::Signature& b = mx.signature(theirDef);
      ASSERT_EQ(a.inputs.size(), b.inputs.size()) << theirDef.name;
      for (size_t i = 0; i < a.inputs.size(); ++i) {
        const doc::Input& x = *a.inputs[i];
        const doc::Input& y = *b.inputs[i];
        EXPECT_EQ(x.name, y.name) << theirDef.name;
        EXPECT_EQ(x.type, y.type) << theirDef.name << "." << y.name;
        EXPECT_TRUE(sameValue(x, y)) << theirDef.name << "." << y.name << ": " << (x.value ? x.value->str() : "-")
                                     << " vs " << (y.value ? y.value->str() : "-");
        EXPECT_EQ(x.defaultgeomprop, y.defaultgeomprop) << theirDef.name << "." << y.name;
        EXPECT_EQ(x.uniform, y.uniform) << theirDef.name << "." << y.name;
        EXPECT_EQ(withoutSpaces(x.enumNames), withoutSpaces(y.enumNames)) << theirDef.name << "." << y.name;
      }
      ASSERT_EQ(a.outputs.size(), b.outputs.size()) << theirDef.name;
      for (size_t i = 0; i < a.outputs.size(); ++i) {
        EXPECT_EQ(a.outputs[i]->name, b.outputs[i]->name) << theirDef.name;
        EXPECT_EQ(a.outputs[i]->type, b.outputs[i]->type) << theirDef.name;
      }
      ++compared;
    }
  }
  // Every nodedef of the libraries mxc provides: stdlib 703, pbrlib 42, cmlib 20, nprlib 3,
  // lights 3, Standard Surface 2, OpenPBR 1, UsdPreviewSurface 1 and its 11 texture nodes
  // (UsdUVTexture 2.2 and 2.3, 8 UsdPrimvarReader, UsdTransform2d), glTF PBR 1 and its 8 texture
  // lookups, Disney Principled 1, Lama 15.
  EXPECT_EQ(compared, 811u);
}

TEST(NodeLibrary, LaterLayersShadowEarlierDefinitions) {
  Context context;
  const doc::Document* d = context.load(mtlx(
      "  <nodedef name=\"ND_add_float\" node=\"add\">\n    <input name=\"in1\" type=\"float\" value=\"5\"/>\n"
      "    <input name=\"in2\" type=\"float\" value=\"0\"/>\n    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"));
  lib::NodeLibrary layer(&context.libraries.top());
  layer.addDocument(*d, context.diagnostics);
  layer.finalize(context.diagnostics);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const doc::NodeDef* add = layer.findNodeDef("ND_add_float");
  EXPECT_EQ(add->document, d);
  EXPECT_FLOAT_EQ(layer.signature(*add).findInput("in1")->value->as<float>(), 5.0f);
  // The category lists the shadowing definition once, and the others of the lower layer.
  size_t floats = 0;
  for (const doc::NodeDef* nd : layer.nodeDefsFor("add")) floats += nd->name == "ND_add_float";
  EXPECT_EQ(floats, 1u);
  EXPECT_GT(layer.nodeDefsFor("add").size(), 10u);
}

TEST(NodeLibrary, SameNameTwiceInOneLayerIsAnError) {
  Context context;
  const doc::Document* a = context.load(mtlx("  <nodedef name=\"ND_x\" node=\"x\"><output name=\"out\" type=\"float\"/></nodedef>\n"), "a.mtlx");
  const doc::Document* b = context.load(mtlx("  <nodedef name=\"ND_x\" node=\"x\"><output name=\"out\" type=\"float\"/></nodedef>\n"), "b.mtlx");
  lib::NodeLibrary layer;
  layer.addDocument(*a, context.diagnostics);
  layer.addDocument(*b, context.diagnostics);
  Diagnostic e = context.firstError();
  EXPECT_NE(e.message.find("nodedef 'ND_x' is defined twice (also at a.mtlx:3:3)"), std::string::npos) << e.message;
  EXPECT_EQ(e.location.file->path(), "b.mtlx");
}

TEST(NodeLibrary, InheritanceOverridesDefaultsInPlace) {
  Context context;
  const lib::NodeLibrary& library = context.libraries.top();
  const doc::NodeDef* v101 = library.findNodeDef("ND_standard_surface_surfaceshader");
  const doc::NodeDef* v100 = library.findNodeDef("ND_standard_surface_surfaceshader_100");
  ASSERT_TRUE(v101 && v100);
  const lib::Signature& s101 = library.signature(*v101);
  const lib::Signature& s100 = library.signature(*v100);
  EXPECT_EQ(s101.inputs.size(), s100.inputs.size());
  EXPECT_EQ(s101.inputs[0]->name, "base");
  // 1.0.1 changed only defaults and inherits everything else from 1.0.0.
  EXPECT_FLOAT_EQ(s101.findInput("base")->value->as<float>(), 1.0f);
  EXPECT_FLOAT_EQ(s100.findInput("base")->value->as<float>(), 0.8f);
  EXPECT_EQ(s101.outputType(), "surfaceshader");
  EXPECT_EQ(s101.findInput("coat_IOR"), s100.findInput("coat_IOR"));  // inherited, not redeclared
}

TEST(NodeLibrary, ImplementationElementBindsAGraph) {
  Context context;
  const doc::Document* d = context.load(mtlx(
      "  <nodedef name=\"ND_double\" node=\"double\">\n    <input name=\"in\" type=\"float\" value=\"1\"/>\n"
      "    <output name=\"out\" type=\"float\"/>\n  </nodedef>\n"
      "  <nodegraph name=\"NG_double\">\n    <add name=\"sum\" type=\"float\">\n"
      "      <input name=\"in1\" type=\"float\" interfacename=\"in\"/>\n"
      "      <input name=\"in2\" type=\"float\" interfacename=\"in\"/>\n    </add>\n"
      "    <output name=\"out\" type=\"float\" nodename=\"sum\"/>\n  </nodegraph>\n"
      "  <implementation name=\"IM_double\" nodedef=\"ND_double\" nodegraph=\"NG_double\"/>\n"));
  resolve::ResolvedDocument r = resolve::resolveDocument(*d, context.libraries.top(), context.diagnostics);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  const doc::NodeDef* nd = r.definitions->findNodeDef("ND_double");
  ASSERT_NE(nd, nullptr);
  EXPECT_EQ(r.definitions->implementationGraph(*nd), &d->nodegraphs[0]);
  const resolve::ResolvedGraph* g = r.findGraph("NG_double");
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->implements, nd);
  ASSERT_EQ(g->interface.size(), 1u);
  EXPECT_EQ(g->interface[0].source, resolve::InputSource::Default);
}

}  // namespace
}  // namespace mxc::test
