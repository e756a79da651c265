// The IR verifier: each rule on a hand-built material that breaks it (and only it), and every
// corpus material verified after lowering and after every pass.

#include "compiler/ir/Verify.h"

#include <gtest/gtest.h>

#include "compiler/ir/ExprBuilder.h"
#include "support/TestSupport.h"

namespace mxc::ir {
namespace {

/// A well-formed material: a rough dielectric over a diffuse base.
struct Fixture {
  Material m;
  ExprBuilder b{m.exprs};
  Index coat, base, baseSlab;

  Fixture() {
    Interface d;
    d.kind = InterfaceKind::Dielectric;
    d.slots.set(Slot::Ior, {b.f(1.5f), {}});
    d.slots.set(Slot::Alpha, {b.vec(Type::Vec2, 0.1f), {}});
    coat = m.addInterface(std::move(d));
    Interface e;
    e.kind = InterfaceKind::Diffuse;
    e.slots.set(Slot::Color, {b.vec(Type::Vec3, 0.8f), {}});
    base = m.addInterface(std::move(e));
    baseSlab = m.slab(base, kNone, kNone, {}, {});
    m.root = m.slab(coat, kNone, baseSlab, {b.f(0.5f), {}}, {});
  }
  /// The rules broken, each once.
  std::vector<VerifyRule> rules() const {
    std::vector<VerifyRule> out;
    for (const VerifyError& e : verify(m)) out.push_back(e.rule);
    return out;
  }
};

TEST(Verify, AWellFormedMaterialPasses) { EXPECT_TRUE(Fixture().rules().empty()); }

TEST(Verify, IndexOutOfRange) {
  Fixture f;
  f.m.nodes[f.m.root].base = 99;
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::IndexInRange});
}

TEST(Verify, ExpressionOutOfRange) {
  Fixture f;
  f.m.interfaces[f.coat].slots.set(Slot::Ior, {12345, {}});
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::ExpressionInRange});
}

TEST(Verify, NodeShape) {
  Fixture f;
  f.m.nodes[f.m.root].a = f.baseSlab;  // a slab has no child `a`
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::NodeShape});
  Fixture g;
  g.m.root = g.m.mix(g.baseSlab, g.baseSlab, {}, {});  // a mix without a weight
  EXPECT_EQ(g.rules(), std::vector<VerifyRule>{VerifyRule::NodeShape});
}

TEST(Verify, Cycle) {
  Fixture f;
  f.m.nodes[f.baseSlab].base = f.m.root;
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::Acyclic});
}

TEST(Verify, SlotOutsideTheSchema) {
  Fixture f;
  // A diffuse lobe has no IOR (the pass fixtures' habit, which the schema now refuses).
  f.m.interfaces[f.base].slots.set(Slot::Ior, {f.b.f(1.5f), {}});
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::SlotAllowed});
}

TEST(Verify, SlotOfTheWrongType) {
  Fixture f;
  f.m.interfaces[f.coat].slots.set(Slot::Alpha, {f.b.f(0.1f), {}});  // alpha is a vec2
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::SlotType});
}

TEST(Verify, ParameterOfTheWrongType) {
  Fixture f;
  f.m.nodes[f.m.root].coverage = {f.b.vec(Type::Vec2, 0.5f), {}};
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::ParamType});
}

TEST(Verify, ConicalEmissionKeepsItsAnglesApartFromTheSchlickExponent) {
  // Before the schema, conical_edf kept its angles in Roughness and Exponent; the schema of a
  // conical emitter has neither Roughness nor an angle in Exponent.
  Fixture f;
  Emission e;
  e.kind = Emission::Kind::Conical;
  e.slots.set(Slot::Roughness, {f.b.f(20.0f), {}});
  ScatterNode emissive;
  emissive.kind = ScatterKind::Emissive;
  emissive.a = f.m.root;
  emissive.emission = f.m.addEmission(std::move(e));
  f.m.root = f.m.addNode(emissive);
  EXPECT_EQ(f.rules(), std::vector<VerifyRule>{VerifyRule::SlotAllowed});
}

TEST(Verify, TheFailureNamesTheStageAndTheRules) {
  Fixture f;
  f.m.nodes[f.m.root].base = 99;
  const std::string what = VerifyFailure("pass collapse-mix", f.m, verify(f.m)).what();
  EXPECT_NE(what.find("after pass collapse-mix"), std::string::npos) << what;
  EXPECT_NE(what.find("index-in-range: node 1 (slab)'s base refers to entry 99"), std::string::npos) << what;
}

/// Every corpus material, verified after lowering and after each pass that edits it.
class VerifyCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(VerifyCorpus, EveryPassKeepsTheRules) {
  test::Context context;
  CompileRequest request;
  request.document = test::sharedDir() / GetParam();
  request.verifyIr = true;
  Compiler compiler(context, request);
  try {
    compiler.materials();
  } catch (const VerifyFailure& failure) {
    ADD_FAILURE() << failure.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, VerifyCorpus, ::testing::ValuesIn(test::corpusDocuments()), test::corpusTestName);

}  // namespace
}  // namespace mxc::ir
