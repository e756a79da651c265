// Each IR pass on small hand-built materials: what it rewrites, what it leaves, and the edit
// counts the pass manager relies on to reach a fixed point.

#include "compiler/ir/passes/Pass.h"

#include <gtest/gtest.h>

#include "compiler/ir/Features.h"
#include "compiler/ir/Evaluate.h"
#include "compiler/ir/ExprBuilder.h"
#include "compiler/ir/Print.h"
#include "compiler/ir/Walk.h"

namespace mxc::ir {
namespace {

/// A material with helpers to add interfaces and slabs quickly.
struct Fixture {
  Material m;
  ExprBuilder b{m.exprs};

  Param p(ExprId e) { return {e, {}}; }
  Param pf(float v) { return p(b.f(v)); }
  Index iface(InterfaceKind kind, ScatterMode mode = ScatterMode::RT, float ior = 1.5f) {
    Interface i;
    i.kind = kind;
    i.scatter = mode;
    i.slots.set(Slot::Ior, pf(ior));
    i.slots.set(Slot::Alpha, p(b.vec(Type::Vec2, 0.1f)));
    return m.addInterface(std::move(i));
  }
  Index slab(Index top, Index medium = kNone, Index base = kNone, Param coverage = {}) {
    return m.slab(top, medium, base, coverage, {});
  }
  Index medium(Medium::Extent extent, float absorption, bool refracting = false) {
    Medium md;
    md.extent = extent;
    md.slots.set(Slot::Absorption, p(b.vec(Type::Vec3, absorption)));
    if (refracting) md.slots.set(Slot::Ior, pf(1.5f));
    return m.addMedium(std::move(md));
  }
  std::string structure() const { return structureSignature(m); }
};

// --- Expressions ---

TEST(ConstantFolding, FoldsOperationsOnConstants) {
  Fixture f;
  ExprId sum = f.b.add(f.b.f(2.0f), f.b.f(3.0f));
  ExprId color = f.b.mul(f.b.vec(Type::Vec3, 0.5f), f.b.f(4.0f));
  ExprId chosen = f.b.select(f.b.greater(f.b.f(1.0f), f.b.f(0.0f)), f.b.vec(Type::Vec3, 1.0f), f.b.vec(Type::Vec3, 0.0f));
  Index top = f.iface(InterfaceKind::Diffuse);
  f.m.interfaces[top].slots.set(Slot::Roughness, f.p(sum));
  f.m.interfaces[top].slots.set(Slot::Color, f.p(color));
  f.m.interfaces[top].slots.set(Slot::Normal, f.p(chosen));
  f.m.root = f.slab(top);
  EXPECT_GT(constantFolding(f.m), 0);
  const Interface& i = f.m.interfaces[top];
  EXPECT_TRUE(f.m.exprs.isConstantEqual(i.slots.value(Slot::Roughness), 5.0f));
  EXPECT_TRUE(f.m.exprs.isConstantEqual(i.slots.value(Slot::Color), 2.0f));
  EXPECT_TRUE(f.m.exprs.isConstantEqual(i.slots.value(Slot::Normal), 1.0f));
  EXPECT_EQ(constantFolding(f.m), 0);  // a fixed point
}

TEST(ConstantFolding, AppliesIdentitiesToNonConstants) {
  Fixture f;
  ExprId n = f.m.exprs.named(Op::GeomProp, Type::Vec3, "Nworld");
  ExprId uv = f.m.exprs.named(Op::GeomProp, Type::Vec2, "UV0");
  ExprId x = f.b.extract(uv, 0);
  Index top = f.iface(InterfaceKind::Diffuse);
  Slots& s = f.m.interfaces[top].slots;
  s.set(Slot::Normal, f.p(f.b.normalize(f.b.mul(n, f.b.f(1.0f)))));          // normalize(N * 1) = N
  s.set(Slot::Roughness, f.p(f.b.lerp(x, f.b.f(7.0f), f.b.f(0.0f))));         // mix(x, 7, 0) = x
  s.set(Slot::Color, f.p(f.b.mul(f.b.splat(x, Type::Vec3), f.b.vec(Type::Vec3, 0.0f))));  // v * 0 = 0
  s.set(Slot::Weight, f.p(f.b.min(f.b.clamp(x, f.b.f(0.0f), f.b.f(1.0f)), f.b.f(1.0f))));  // min(clamp(x,0,1),1)
  f.m.root = f.slab(top);
  constantFolding(f.m);
  const Slots& out = f.m.interfaces[top].slots;
  EXPECT_EQ(f.m.exprs[out.value(Slot::Normal)].op, Op::GeomProp);
  EXPECT_EQ(f.m.exprs[out.value(Slot::Roughness)].op, Op::Extract);
  EXPECT_TRUE(f.m.exprs.isConstantEqual(out.value(Slot::Color), 0.0f));
  EXPECT_EQ(f.m.exprs[out.value(Slot::Weight)].op, Op::Clamp);
}

TEST(ConstantFolding, LeavesNonFiniteResultsToTheShader) {
  Fixture f;
  Index top = f.iface(InterfaceKind::Diffuse);
  f.m.interfaces[top].slots.set(Slot::Roughness, f.p(f.b.div(f.b.f(1.0f), f.b.f(0.0f))));
  f.m.interfaces[top].slots.set(Slot::Color, f.p(f.b.sqrt(f.b.f(-1.0f))));
  f.m.root = f.slab(top);
  constantFolding(f.m);
  EXPECT_EQ(f.m.exprs[f.m.interfaces[top].slots.value(Slot::Roughness)].op, Op::Div);
  EXPECT_EQ(f.m.exprs[f.m.interfaces[top].slots.value(Slot::Color)].op, Op::Sqrt);
}

TEST(CommonSubexpressions, EqualExpressionsAreOneExpression) {
  Fixture f;
  ExprId uv = f.m.exprs.named(Op::GeomProp, Type::Vec2, "UV0");
  ExprId a = f.b.mul(f.b.extract(uv, 0), f.b.f(2.0f));
  ExprId b = f.b.mul(f.b.extract(uv, 0), f.b.f(2.0f));
  EXPECT_EQ(a, b);
  EXPECT_NE(a, f.b.mul(f.b.extract(uv, 1), f.b.f(2.0f)));
}

TEST(CommonSubexpressions, MergesEqualInterfacesAndNodes) {
  Fixture f;
  Index d1 = f.iface(InterfaceKind::Diffuse);
  Index d2 = f.iface(InterfaceKind::Diffuse);
  f.m.root = f.m.mix(f.slab(d1), f.slab(d2), f.pf(0.3f), {});
  EXPECT_GT(commonSubexpressions(f.m), 0);
  // The two slabs became one node, so the mix has the same child twice...
  const ScatterNode& mix = f.m.nodes[f.m.root];
  EXPECT_EQ(mix.a, mix.b);
  // ...which collapse-mix then removes.
  collapseMix(f.m);
  EXPECT_EQ(f.structure(), "slab(diffuse,-,-)");
}

TEST(DeadCode, DropsWhatNothingReaches) {
  Fixture f;
  f.b.add(f.b.f(1.0f), f.m.exprs.named(Op::GeomProp, Type::Float, "unused"));
  f.iface(InterfaceKind::Sheen);  // unreferenced
  Index top = f.iface(InterfaceKind::Diffuse);
  f.slab(top);  // unreferenced node
  f.m.root = f.slab(top);
  const size_t exprs = f.m.exprs.size();
  EXPECT_GT(deadCode(f.m), 0);
  EXPECT_LT(f.m.exprs.size(), exprs);
  EXPECT_EQ(f.m.nodes.size(), 1u);
  EXPECT_EQ(f.m.interfaces.size(), 1u);
  EXPECT_EQ(f.m.interfaces[0].kind, InterfaceKind::Diffuse);
  EXPECT_EQ(deadCode(f.m), 0);
}

// --- Structure ---

TEST(PruneCoverage, ZeroCoverageLeavesTheBase) {
  Fixture f;
  Index base = f.slab(f.iface(InterfaceKind::Diffuse));
  f.m.root = f.slab(f.iface(InterfaceKind::Dielectric), kNone, base, f.pf(0.0f));
  EXPECT_EQ(pruneCoverage(f.m), 1);
  EXPECT_EQ(f.structure(), "slab(diffuse,-,-)");
}

TEST(PruneCoverage, FullCoverageIsDroppedAndZeroLeafIsBlack) {
  Fixture f;
  Index leaf = f.slab(f.iface(InterfaceKind::Diffuse), kNone, kNone, f.pf(0.0f));
  f.m.root = f.slab(f.iface(InterfaceKind::Dielectric), kNone, leaf, f.pf(1.0f));
  pruneCoverage(f.m);
  EXPECT_EQ(f.structure(), "slab(dielectric:RT,-,absorber)");
  EXPECT_FALSE(f.m.nodes[f.m.root].coverage.present());
}

TEST(CollapseMix, ConstantWeightsAndEqualChildren) {
  Fixture f;
  Index a = f.slab(f.iface(InterfaceKind::Diffuse));
  Index b = f.slab(f.iface(InterfaceKind::Conductor));
  f.m.root = f.m.mix(f.m.mix(a, b, f.pf(1.0f), {}), f.m.mix(a, b, f.pf(0.0f), {}), f.pf(0.5f), {});
  collapseMix(f.m);
  EXPECT_EQ(f.structure(), "mix(slab(conductor,-,-),slab(diffuse,-,-))");
  Fixture g;
  Index only = g.slab(g.iface(InterfaceKind::Diffuse));
  g.m.root = g.m.mix(only, only, g.p(g.m.exprs.named(Op::GeomProp, Type::Float, "w")), {});
  EXPECT_EQ(collapseMix(g.m), 1);
  EXPECT_EQ(g.structure(), "slab(diffuse,-,-)");
}

TEST(RemoveEmptyMedia, ClearMediaGoRefractingOnesStay) {
  Fixture f;
  Index clearCoat = f.slab(f.iface(InterfaceKind::Dielectric), f.medium(Medium::Extent::Finite, 0.0f),
                           f.slab(f.iface(InterfaceKind::Diffuse)));
  Index glass = f.slab(f.iface(InterfaceKind::Dielectric), f.medium(Medium::Extent::Bulk, 0.0f, true));
  Index sheet = f.slab(f.iface(InterfaceKind::Dielectric), f.medium(Medium::Extent::ThinWall, 0.0f));
  Index tinted = f.slab(f.iface(InterfaceKind::Dielectric), f.medium(Medium::Extent::Finite, 0.3f),
                        f.slab(f.iface(InterfaceKind::Conductor)));
  f.m.root = f.m.mix(f.m.mix(clearCoat, glass, f.pf(0.5f), {}), f.m.mix(sheet, tinted, f.pf(0.5f), {}), f.pf(0.5f), {});
  EXPECT_EQ(removeEmptyMedia(f.m), 1);
  EXPECT_EQ(f.structure(),
            "mix(mix(slab(dielectric:RT,-,slab(diffuse,-,-)),slab(dielectric:RT,bulk,-)),"
            "mix(slab(dielectric:RT,thin_wall,-),slab(dielectric:RT,-,slab(conductor,-,-))))");
  EXPECT_NE(f.m.nodes[tinted].medium, kNone);  // absorbing: kept (finite media are not in the signature)
}

TEST(RemoveThinFilm, NoThicknessOrNoCoverage) {
  Fixture f;
  Index a = f.iface(InterfaceKind::Dielectric);
  Index b = f.iface(InterfaceKind::Conductor);
  Index c = f.iface(InterfaceKind::Schlick);
  f.m.interfaces[a].thinFilm = {f.pf(0.0f), f.pf(1.4f), {}, {}};
  f.m.interfaces[b].thinFilm = {f.pf(300.0f), f.pf(1.4f), f.pf(0.0f), {}};
  f.m.interfaces[c].thinFilm = {f.pf(300.0f), f.pf(1.4f), f.pf(1.0f), {}};
  f.m.root = f.m.mix(f.m.mix(f.slab(a), f.slab(b), f.pf(0.5f), {}), f.slab(c), f.pf(0.5f), {});
  EXPECT_EQ(removeThinFilm(f.m), 3);
  EXPECT_FALSE(f.m.interfaces[a].thinFilm.present());
  EXPECT_FALSE(f.m.interfaces[b].thinFilm.present());
  EXPECT_TRUE(f.m.interfaces[c].thinFilm.present());
  EXPECT_FALSE(f.m.interfaces[c].thinFilm.coverage.present());  // coverage 1 is the default
}

TEST(RemoveDefaultSlots, DefaultsAreDropped) {
  Fixture f;
  Index top = f.iface(InterfaceKind::Dielectric);
  f.m.interfaces[top].slots.set(Slot::FresnelScale, f.pf(1.0f));
  f.m.interfaces[top].slots.set(Slot::ReflectionTint, f.p(f.b.vec(Type::Vec3, 1.0f)));
  f.m.interfaces[top].slots.set(Slot::TransmissionTint, f.p(f.b.vec(Type::Vec3, 0.5f)));
  f.m.root = f.slab(top);
  EXPECT_EQ(removeDefaultSlots(f.m), 2);
  EXPECT_EQ(f.m.interfaces[top].slots.find(Slot::FresnelScale), nullptr);
  EXPECT_NE(f.m.interfaces[top].slots.find(Slot::TransmissionTint), nullptr);
  EXPECT_NE(f.m.interfaces[top].slots.find(Slot::Ior), nullptr);  // no default: kept
}

TEST(RemoveDarkEmission, BlackEmissionGoes) {
  Fixture f;
  Emission e;
  e.slots.set(Slot::Color, f.p(f.b.vec(Type::Vec3, 0.0f)));
  ScatterNode emissive;
  emissive.kind = ScatterKind::Emissive;
  emissive.a = f.slab(f.iface(InterfaceKind::Diffuse));
  emissive.emission = f.m.addEmission(std::move(e));
  f.m.root = f.m.addNode(std::move(emissive));
  EXPECT_EQ(removeDarkEmission(f.m), 1);
  EXPECT_EQ(f.structure(), "slab(diffuse,-,-)");
}

TEST(MergeDielectricLobes, ReflectionOverTransmissionIsOneInterface) {
  Fixture f;
  Index r = f.iface(InterfaceKind::Dielectric, ScatterMode::R);
  Index t = f.iface(InterfaceKind::Dielectric, ScatterMode::T);
  f.m.interfaces[r].thinFilm = {f.pf(400.0f), f.pf(1.3f), {}, {}};  // the film on the R node only
  f.m.interfaces[t].slots.set(Slot::TransmissionTint, f.p(f.b.vec(Type::Vec3, 0.7f)));
  Index volume = f.medium(Medium::Extent::Bulk, 0.2f);
  f.m.root = f.slab(r, kNone, f.slab(t, volume));
  EXPECT_GT(mergeDielectricLobes(f.m), 0);
  EXPECT_EQ(f.structure(), "slab(dielectric:RT+film,bulk,-)");
  const Interface& merged = f.m.interfaces[f.m.nodes[f.m.root].top];
  EXPECT_NE(merged.slots.find(Slot::TransmissionTint), nullptr);
}

TEST(MergeDielectricLobes, DifferentSurfacesStayTwoSlabs) {
  Fixture f;
  Index r = f.iface(InterfaceKind::Dielectric, ScatterMode::R, 1.8f);
  Index t = f.iface(InterfaceKind::Dielectric, ScatterMode::T, 1.5f);
  f.m.root = f.slab(r, kNone, f.slab(t));
  mergeDielectricLobes(f.m);
  // The R node has something under it, so it transmits into it: RT; the T node stays T.
  EXPECT_EQ(f.structure(), "slab(dielectric:RT,-,slab(dielectric:T,-,-))");
}

TEST(MergeDielectricLobes, IndexMatchedMediumTakesTheInterfaceAbove) {
  Fixture f;
  Index sss = f.medium(Medium::Extent::Bulk, 0.1f);
  f.m.root = f.slab(f.iface(InterfaceKind::Dielectric, ScatterMode::R), kNone, f.slab(kNone, sss));
  mergeDielectricLobes(f.m);
  EXPECT_EQ(f.structure(), "slab(dielectric:RT,bulk,-)");
}

TEST(MergeDielectricLobes, IndexMatchedMediumStaysOutOfACoveredLayer) {
  // Standard Surface's sheen (coverage: sheen) over its subsurface bulk: where the sheen is
  // absent the bulk is still there, so it is not the sheen layer's medium.
  Fixture f;
  Index sss = f.medium(Medium::Extent::Bulk, 0.1f);
  Index sheen = f.iface(InterfaceKind::Sheen);
  f.m.root = f.slab(sheen, kNone, f.slab(kNone, sss), f.pf(0.5f));
  EXPECT_EQ(mergeDielectricLobes(f.m), 0);
  EXPECT_EQ(f.structure(), "slab(sheen,-,slab(-,bulk,-),cov)");
}

TEST(BulkUnderTransmission, TransmittingBottomGetsItsBulk) {
  Fixture f;
  f.m.root = f.m.mix(f.slab(f.iface(InterfaceKind::Dielectric, ScatterMode::RT)),
                     f.slab(f.iface(InterfaceKind::Dielectric, ScatterMode::R)), f.pf(0.5f), {});
  EXPECT_EQ(bulkUnderTransmission(f.m), 1);
  EXPECT_EQ(f.structure(), "mix(slab(dielectric:RT,bulk,-),slab(dielectric:R,-,-))");
  const Medium& bulk = f.m.media[f.m.nodes[f.m.nodes[f.m.root].a].medium];
  EXPECT_TRUE(f.m.exprs.isConstantEqual(bulk.slots.value(Slot::Ior), 1.5f));
  Fixture thin;
  thin.m.thinWalled = thin.p(thin.m.exprs.constantBool(true));
  thin.m.root = thin.slab(thin.iface(InterfaceKind::Dielectric));
  bulkUnderTransmission(thin.m);
  EXPECT_EQ(thin.structure(), "slab(dielectric:RT,thin_wall,-)");
}

TEST(DistributeOverMix, SlabsDistributeIntoStacks) {
  Fixture f;
  Index coat = f.iface(InterfaceKind::Dielectric);
  Index metal = f.slab(f.iface(InterfaceKind::Conductor));
  Index plastic = f.slab(f.iface(InterfaceKind::Diffuse));
  f.m.root = f.slab(coat, kNone, f.m.mix(plastic, metal, f.p(f.m.exprs.named(Op::GeomProp, Type::Float, "m")), {}),
                    f.p(f.m.exprs.named(Op::GeomProp, Type::Float, "c")));
  EXPECT_EQ(distributeOverMix(f.m), 1);
  EXPECT_EQ(f.structure(), "mix(slab(dielectric:RT,-,slab(diffuse,-,-),cov),slab(dielectric:RT,-,slab(conductor,-,-),cov))");
  // Both stacks share the one coat interface.
  const ScatterNode& mix = f.m.nodes[f.m.root];
  EXPECT_EQ(f.m.nodes[mix.a].top, f.m.nodes[mix.b].top);
  EXPECT_EQ(distributeOverMix(f.m), 0);
}

TEST(FoldThinFilmMix, MixWithAndWithoutFilmIsFilmCoverage) {
  Fixture f;
  Index plain = f.iface(InterfaceKind::Dielectric);
  Index filmed = f.iface(InterfaceKind::Dielectric);
  f.m.interfaces[filmed].thinFilm = {f.pf(500.0f), f.pf(1.4f), {}, {}};
  Index base = f.slab(f.iface(InterfaceKind::Diffuse));
  ExprId w = f.m.exprs.named(Op::GeomProp, Type::Float, "w");
  f.m.root = f.m.mix(f.slab(plain, kNone, base), f.slab(filmed, kNone, base), f.p(w), {});
  EXPECT_EQ(foldThinFilmMix(f.m), 1);
  EXPECT_EQ(f.structure(), "slab(dielectric:RT+film,-,slab(diffuse,-,-))");
  const Interface& top = f.m.interfaces[f.m.nodes[f.m.root].top];
  EXPECT_EQ(top.thinFilm.coverage.value, w);
}

TEST(PassManager, RunsToAFixedPointAndReportsEdits) {
  Fixture f;
  Index coat = f.iface(InterfaceKind::Dielectric);
  Index base = f.slab(f.iface(InterfaceKind::Diffuse));
  // Coverage clamp(0, 0, 1) folds to 0, which then prunes the coat.
  f.m.root = f.slab(coat, f.medium(Medium::Extent::Finite, 0.0f), base,
                    f.p(f.b.clamp(f.b.f(0.0f), f.b.f(0.0f), f.b.f(1.0f))));
  std::vector<PassReport> reports = runPasses(f.m);
  EXPECT_EQ(f.structure(), "slab(diffuse,-,-)");
  int folding = 0, pruning = 0, dead = 0;
  for (const PassReport& r : reports) {
    if (r.name == "constant-folding") folding = r.edits;
    if (r.name == "prune-coverage") pruning = r.edits;
    if (r.name == "dead-code") dead = r.edits;
  }
  EXPECT_GT(folding, 0);
  EXPECT_EQ(pruning, 1);
  EXPECT_GT(dead, 0);
  EXPECT_EQ(f.m.interfaces.size(), 1u);
}

TEST(Evaluate, HostOperations) {
  auto eval = [](Op op, Type t, std::vector<Constant> args, const std::string& text = "") {
    return evaluate(op, t, args, 0, text);
  };
  EXPECT_FLOAT_EQ(eval(Op::Dot, Type::Float, {{Type::Vec3, {1, 2, 3}}, {Type::Vec3, {4, 5, 6}}})->v[0], 32.0f);
  EXPECT_EQ(eval(Op::Swizzle, Type::Vec3, {{Type::Vec4, {1, 2, 3, 4}}}, "zy1")->v, (std::vector<float>{3, 2, 1}));
  auto hsv = eval(Op::RgbToHsv, Type::Vec3, {{Type::Vec3, {1, 0, 0}}});
  EXPECT_EQ(hsv->v, (std::vector<float>{0, 1, 1}));
  auto rgb = eval(Op::HsvToRgb, Type::Vec3, {{Type::Vec3, {1.0f / 3.0f, 1, 1}}});
  EXPECT_NEAR(rgb->v[1], 1.0f, 1e-5f);
  EXPECT_NEAR(rgb->v[0], 0.0f, 1e-5f);
  auto rotated = eval(Op::Rotate2D, Type::Vec2, {{Type::Vec2, {1, 0}}, {Type::Float, {90}}});
  EXPECT_NEAR(rotated->v[0], 0.0f, 1e-6f);
  EXPECT_NEAR(rotated->v[1], 1.0f, 1e-6f);
  EXPECT_FALSE(eval(Op::Ln, Type::Float, {{Type::Float, {0}}}).has_value());  // -inf is not folded
  EXPECT_FALSE(eval(Op::Noise3D, Type::Float, {{Type::Vec3, {0, 0, 0}}}).has_value());
}

}  // namespace
}  // namespace mxc::ir
