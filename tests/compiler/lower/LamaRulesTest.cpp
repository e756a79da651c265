// Pixar's Lama nodes lowered natively (compiler/lower/LamaRules.cpp): the structure each node
// becomes and the numbers of its mapping, read from the folded IR.

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "compiler/ir/Evaluate.h"
#include "compiler/ir/Print.h"
#include "compiler/ir/Walk.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

using ir::Slot;

struct Lowered {
  std::unique_ptr<Context> context;
  std::vector<ir::Material> materials;
  const ir::Material& only() const { return materials.at(0); }
  std::string signature() const { return ir::structureSignature(only()); }
  std::vector<float> value(ir::ExprId e) const {
    if (e == ir::kNoExpr) return {};
    std::optional<ir::Constant> c = ir::evaluateExpr(only().exprs, e);
    return c ? c->v : std::vector<float>{};
  }
  const ir::Interface* interface(ir::InterfaceKind kind) const {
    for (ir::Index i : ir::reachableNodes(only())) {
      const ir::Index t = only().nodes[i].top;
      if (t != ir::kNone && only().interfaces[t].kind == kind) return &only().interfaces[t];
    }
    return nullptr;
  }
  const ir::Medium* medium() const {
    for (ir::Index i : ir::reachableNodes(only())) {
      if (only().nodes[i].medium != ir::kNone) return &only().media[only().nodes[i].medium];
    }
    return nullptr;
  }
  bool noted(const std::string& text) const {
    for (const ir::Note& n : only().notes) {
      if (n.message.find(text) != std::string::npos) return true;
    }
    return false;
  }
};

/// A document whose material's surface is the Lama node named "b" among `nodes`, lowered with
/// the built-in library (no MaterialX library: the native rules).
Lowered lower(const std::string& nodes, bool wrap = true) {
  Lowered out;
  out.context = std::make_unique<Context>();
  CompileRequest request;
  request.document = "lama.mtlx";
  request.text = mtlx(nodes + (wrap ? "  <surface name=\"S\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" "
                                      "nodename=\"b\"/></surface>\n  <surfacematerial name=\"M\" type=\"material\">"
                                      "<input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"S\"/>"
                                      "</surfacematerial>\n"
                                    : ""));
  Compiler compiler(*out.context, std::move(request));
  out.materials = std::move(compiler.materials());
  EXPECT_FALSE(out.context->diagnostics.hasErrors()) << out.context->diagnostics.format();
  EXPECT_EQ(out.materials.size(), 1u);
  return out;
}

std::string node(const std::string& category, const std::string& inputs, const std::string& name = "b") {
  return fmt::format("  <{0} name=\"{1}\" type=\"BSDF\">{2}</{0}>\n", category, name, inputs);
}
std::string in(const std::string& name, const std::string& type, const std::string& value) {
  return fmt::format("<input name=\"{}\" type=\"{}\" value=\"{}\"/>", name, type, value);
}
std::string from(const std::string& name, const std::string& upstream) {
  return fmt::format("<input name=\"{}\" type=\"BSDF\" nodename=\"{}\"/>", name, upstream);
}

void expectNear(const std::vector<float>& got, const std::vector<float>& expected, float tolerance = 1e-5f) {
  ASSERT_EQ(got.size(), expected.size());
  for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], tolerance) << "component " << i;
}

TEST(LamaRules, DielectricIsOneInterfaceOverItsInterior) {
  // Artistic: reflectivity 0.04 is an IOR of 1.5 ((1 + 0.2) / (1 - 0.2)).
  Lowered l = lower(node("LamaDielectric", in("absorptionColor", "color3", "0.5, 0.25, 1") +
                                               in("absorptionRadius", "float", "2") +
                                               in("scatterColor", "color3", "0.5, 0, 0")));
  EXPECT_EQ(l.signature(), "slab(dielectric:RT,bulk,-)");
  const ir::Interface* top = l.interface(ir::InterfaceKind::Dielectric);
  ASSERT_NE(top, nullptr);
  expectNear(l.value(top->slots.value(Slot::Ior)), {1.5f});
  // The interior reaches absorptionColor at absorptionRadius: mu_t = -ln(C) / R, mu_s = S mu_t.
  const ir::Medium* m = l.medium();
  ASSERT_NE(m, nullptr);
  const float t0 = -std::log(0.5f) / 2.0f, t1 = -std::log(0.25f) / 2.0f;
  expectNear(l.value(m->slots.value(Slot::Scattering)), {0.5f * t0, 0.0f, 0.0f});
  expectNear(l.value(m->slots.value(Slot::Absorption)), {0.5f * t0, t1, 0.0f});
  // Scientific: the IOR as given.
  Lowered s = lower(node("LamaDielectric", in("fresnelMode", "integer", "1") + in("IOR", "float", "1.33")));
  expectNear(s.value(s.interface(ir::InterfaceKind::Dielectric)->slots.value(Slot::Ior)), {1.33f});
}

TEST(LamaRules, AnisotropyMovesTheCoTangentRoughnessTowardOneOrZero) {
  auto alpha = [](const std::string& anisotropy) {
    Lowered l = lower(node("LamaConductor", in("roughness", "float", "0.2") + in("anisotropy", "float", anisotropy)));
    return l.value(l.interface(ir::InterfaceKind::Conductor)->slots.value(Slot::Alpha));
  };
  expectNear(alpha("0"), {0.04f, 0.04f});
  expectNear(alpha("0.5"), {0.04f, 0.36f});   // 0.2 + 0.5 (1 - 0.2) = 0.6
  expectNear(alpha("-0.5"), {0.04f, 0.01f});  // 0.2 - 0.5 0.2 = 0.1
  expectNear(alpha("1"), {0.04f, 1.0f});
  expectNear(alpha("-1"), {0.04f, 0.0f});
}

TEST(LamaRules, ConductorFresnelModes) {
  // Scientific: the complex IOR as given.
  Lowered s = lower(node("LamaConductor", in("fresnelMode", "integer", "1") + in("IOR", "vector3", "0.2, 0.9, 1.1") +
                                              in("extinction", "vector3", "3, 2.5, 2")));
  const ir::Interface* f = s.interface(ir::InterfaceKind::Conductor);
  expectNear(s.value(f->slots.value(Slot::ComplexIor)), {0.2f, 0.9f, 1.1f});
  expectNear(s.value(f->slots.value(Slot::Extinction)), {3.0f, 2.5f, 2.0f});
  // Artistic, Gulbrandsen 2014 eq. 8: an edge colour of 1 gives n = nMin = (1 - r) / (1 + r);
  // above 1 it is clamped (n stays positive) rather than extrapolated below nMin.
  for (const char* edge : {"1, 1, 1", "1.5, 1.5, 1.5"}) {
    Lowered a = lower(node("LamaConductor", in("reflectivity", "color3", "0.5, 0.5, 0.5") +
                                                in("edgeColor", "color3", edge)));
    expectNear(a.value(a.interface(ir::InterfaceKind::Conductor)->slots.value(Slot::ComplexIor)),
               {1.0f / 3.0f, 1.0f / 3.0f, 1.0f / 3.0f});
  }
  // A tint is a clamped multiplier; white is none.
  EXPECT_EQ(lower(node("LamaConductor", "")).signature(), "slab(conductor,-,-)");
  Lowered tinted = lower(node("LamaConductor", in("tint", "color3", "2, 0.5, 1")));
  EXPECT_EQ(tinted.signature(), "tint(slab(conductor,-,-))");
  expectNear(tinted.value(tinted.only().nodes[tinted.only().root].weight.value), {1.0f, 0.5f, 1.0f});
}

TEST(LamaRules, GeneralizedSchlickMapsReflectivityProfileAndItsOwnAnisotropy) {
  Lowered l = lower(node("LamaGeneralizedSchlick", in("reflectivity", "color3", "0.3, 0.2, 0.1") +
                                                       in("reflectivityProfile", "float", "0.25") +
                                                       in("roughness", "float", "0.5") + in("anisotropy", "float", "0.8")));
  EXPECT_EQ(l.signature(), "slab(schlick:RT,bulk,-)");
  const ir::Interface* f = l.interface(ir::InterfaceKind::Schlick);
  expectNear(l.value(f->slots.value(Slot::F0)), {0.3f, 0.2f, 0.1f});
  expectNear(l.value(f->slots.value(Slot::Exponent)), {4.0f});
  expectNear(l.value(f->slots.value(Slot::Alpha)), {0.25f, 0.64f});  // the anisotropy is r_b itself
  // Its default anisotropy (-1) is none; Scientific F0 = ((n - 1) / (n + 1))^2.
  Lowered d = lower(node("LamaGeneralizedSchlick", in("fresnelMode", "integer", "1") + in("IOR", "vector3", "1.5, 2, 3")));
  const ir::Interface* g = d.interface(ir::InterfaceKind::Schlick);
  expectNear(d.value(g->slots.value(Slot::Alpha)), {0.01f, 0.01f});
  expectNear(d.value(g->slots.value(Slot::F0)), {0.04f, 1.0f / 9.0f, 0.25f});
}

TEST(LamaRules, DiffuseSheenTranslucentAndIridescence) {
  // Oren-Nayar sigma = r^2 / 2; energyCompensation 1 is EON, 0 the plain model, between a mix.
  Lowered eon = lower(node("LamaDiffuse", in("roughness", "float", "0.6")));
  const ir::Interface* d = eon.interface(ir::InterfaceKind::Diffuse);
  EXPECT_EQ(d->diffuseModel, ir::DiffuseModel::EON);
  expectNear(eon.value(d->slots.value(Slot::Roughness)), {0.18f});
  EXPECT_EQ(lower(node("LamaDiffuse", in("energyCompensation", "float", "0"))).interface(ir::InterfaceKind::Diffuse)->diffuseModel,
            ir::DiffuseModel::OrenNayar);
  EXPECT_EQ(lower(node("LamaDiffuse", in("energyCompensation", "float", "0.5"))).signature(),
            "mix(slab(diffuse,-,-),slab(diffuse,-,-))");
  // Sheen roughness (0.1 + 0.9 r)^2.
  Lowered sheen = lower(node("LamaSheen", in("roughness", "float", "0.5")));
  expectNear(sheen.value(sheen.interface(ir::InterfaceKind::Sheen)->slots.value(Slot::Roughness)), {0.55f * 0.55f});
  EXPECT_EQ(lower(node("LamaTranslucent", "")).signature(), "slab(diffuse_transmission,-,-)");
  // Iridescence: a film (thickness lerp(min, max, relative)) on an index-matched interface.
  Lowered film = lower(node("LamaIridescence", in("relativeFilmThickness", "float", "0.25")));
  EXPECT_EQ(film.signature(), "slab(dielectric:RT+film,bulk,-)");
  const ir::Interface* f = film.interface(ir::InterfaceKind::Dielectric);
  expectNear(film.value(f->slots.value(Slot::Ior)), {1.0f});
  expectNear(film.value(f->thinFilm.thickness.value), {500.0f});
  expectNear(film.value(f->thinFilm.ior.value), {1.3f});
}

TEST(LamaRules, SubsurfaceOfRadiusZeroIsLambertian) {
  EXPECT_EQ(lower(node("LamaSSS", "")).signature(), "slab(diffuse,-,-)");
  Lowered sss = lower(node("LamaSSS", in("sssRadius", "color3", "10, 5, 2") + in("sssUnitLength", "float", "0.1")));
  EXPECT_EQ(sss.signature(), "slab(-,bulk,-)");
  // The mean free path in scene units is radius x scale x unit length: mu_t = 1 / (10 0.1).
  const ir::Medium* m = sss.medium();
  ASSERT_NE(m, nullptr);
  const std::vector<float> a = sss.value(m->slots.value(Slot::Absorption));
  const std::vector<float> s = sss.value(m->slots.value(Slot::Scattering));
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_NEAR(a[0] + s[0], 1.0f, 1e-5f);
  EXPECT_NEAR(a[2] + s[2], 1.0f / 0.2f, 1e-4f);
}

TEST(LamaRules, LayerTurnsTheTopsInteriorIntoACoating) {
  const std::string nodes = node("LamaDielectric", in("absorptionColor", "color3", "0.5, 0.5, 0.5") +
                                                       in("absorptionRadius", "float", "3"), "top") +
                            node("LamaDiffuse", "", "base");
  auto layer = [&](const std::string& inputs) {
    return lower(nodes + node("LamaLayer", from("materialTop", "top") + from("materialBase", "base") + inputs));
  };
  // topThickness 0: the interior is a coating as thick as its absorptionRadius (absorptionColor
  // is the coating's colour at normal incidence); otherwise topThickness.
  for (const auto& [thickness, expected] : {std::pair{"0", 3.0f}, std::pair{"0.5", 0.5f}}) {
    Lowered l = layer(in("topThickness", "float", thickness));
    EXPECT_EQ(l.signature(), "slab(dielectric:RT,-,slab(diffuse,-,-))");
    const ir::Medium* m = l.medium();
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->extent, ir::Medium::Extent::Finite);
    expectNear(l.value(m->slots.value(Slot::Thickness)), {expected});
  }
  // topMix is the top's coverage: mix(base, layer(top, base), topMix).
  EXPECT_EQ(layer(in("topMix", "float", "0.5")).signature(),
            "mix(slab(diffuse,-,-),slab(dielectric:RT,-,slab(diffuse,-,-)))");
}

TEST(LamaRules, AddMixAndEmission) {
  const std::string two = node("LamaDiffuse", "", "d") + node("LamaConductor", "", "c");
  EXPECT_EQ(lower(two + node("LamaMix", from("material1", "d") + from("material2", "c") + in("mix", "float", "0.3")))
                .signature(),
            "mix(slab(diffuse,-,-),slab(conductor,-,-))");
  // weight1 m1 + weight2 m2; a zero weight removes its term.
  EXPECT_EQ(lower(two + node("LamaAdd", from("material1", "d") + from("material2", "c") + in("weight2", "float", "0.5")))
                .signature(),
            "add(slab(diffuse,-,-),mix(absorber,slab(conductor,-,-)))");
  Lowered emitting = lower(node("LamaDiffuse", "", "b") +
                           "  <LamaEmission name=\"e\" type=\"EDF\"><input name=\"color\" type=\"color3\" value=\"2, 1, 0\"/>"
                           "</LamaEmission>\n  <surface name=\"S\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" "
                           "nodename=\"b\"/><input name=\"edf\" type=\"EDF\" nodename=\"e\"/></surface>\n"
                           "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                           "type=\"surfaceshader\" nodename=\"S\"/></surfacematerial>\n",
                           false);
  EXPECT_EQ(emitting.signature(), "emissive(slab(diffuse,-,-))");
}

TEST(LamaRules, SurfaceIsAMaterialWithPresence) {
  Lowered l = lower(node("LamaDiffuse", "", "front") + node("LamaConductor", "", "back") +
                        "  <LamaSurface name=\"Lama\" type=\"material\">" + from("materialFront", "front") +
                        from("materialBack", "back") + in("presence", "float", "0.25") + "</LamaSurface>\n",
                    false);
  EXPECT_EQ(l.only().name, "Lama");
  EXPECT_EQ(l.only().shader, "LamaSurface");
  EXPECT_EQ(l.signature(), "mix(ambient,slab(diffuse,-,-))");
  expectNear(l.value(l.only().opacity.value), {0.25f});
  EXPECT_TRUE(l.noted("back side"));
}

}  // namespace
}  // namespace mxc::test
