// Lowering to the slab IR: the structures the specifications describe, the effect summary,
// the media and roughness formulas, pbrlib graphs, and lowering errors.

#include "compiler/lower/Lowering.h"

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "compiler/common/LargeStack.h"
#include "compiler/ir/Evaluate.h"
#include "compiler/ir/Print.h"
#include "compiler/ir/Walk.h"
#include "compiler/ir/passes/Pass.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

using ir::Slot;

struct Lowered {
  std::unique_ptr<Context> context;
  std::vector<ir::Material> materials;

  const ir::Material& only() const { return materials.at(0); }
  std::vector<std::string> effects(size_t i = 0) const {
    std::vector<std::string> out;
    materials.at(i).features.effects.forEach([&](ir::Effect e) { out.emplace_back(ir::effectName(e)); });
    return out;
  }
  /// The origin of an effect, or null when the material does not have it.
  const ir::Origin* effect(const std::string& name, size_t i = 0) const {
    const ir::Features& f = materials.at(i).features;
    for (size_t k = 0; k < static_cast<size_t>(ir::Effect::Count); ++k) {
      const auto e = static_cast<ir::Effect>(k);
      if (f.effects.has(e) && ir::effectName(e) == name) return &f.origin(e);
    }
    return nullptr;
  }
};

Lowered lowerRequest(CompileRequest request) {
  Lowered out;
  out.context = std::make_unique<Context>();
  Compiler compiler(*out.context, std::move(request));
  out.materials = std::move(compiler.materials());
  EXPECT_FALSE(out.context->diagnostics.hasErrors()) << out.context->diagnostics.format();
  return out;
}

Lowered lower(const std::string& text) {
  CompileRequest request;
  request.document = "test.mtlx";
  request.text = text;
  return lowerRequest(std::move(request));
}

Lowered lowerFile(const std::string& relative) {
  CompileRequest request;
  request.document = sharedDir() / relative;
  return lowerRequest(std::move(request));
}

std::string in(const std::string& name, const std::string& type, const std::string& value) {
  return "    <input name=\"" + name + "\" type=\"" + type + "\" value=\"" + value + "\"/>\n";
}

std::vector<float> constant(const ir::Material& m, ir::ExprId e) {
  if (e == ir::kNoExpr) return {};  // an absent slot
  std::optional<ir::Constant> c = ir::evaluateExpr(m.exprs, e);
  return c ? c->v : std::vector<float>{};
}

/// The first medium / interface of a kind found in the material's tree.
const ir::Medium* findMedium(const ir::Material& m, ir::Medium::Extent extent) {
  for (ir::Index i : ir::reachableNodes(m)) {
    ir::Index md = m.nodes[i].medium;
    if (md != ir::kNone && m.media[md].extent == extent) return &m.media[md];
  }
  return nullptr;
}

const ir::Interface* findInterface(const ir::Material& m, ir::InterfaceKind kind) {
  for (ir::Index i : ir::reachableNodes(m)) {
    ir::Index t = m.nodes[i].top;
    if (t != ir::kNone && m.interfaces[t].kind == kind) return &m.interfaces[t];
  }
  return nullptr;
}

TEST(OpenPbrLowering, DefaultIsGlossOverDiffuseWithMinimalEffects) {
  Lowered l = lowerFile("corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx");
  ASSERT_EQ(l.materials.size(), 1u);
  EXPECT_EQ(ir::structureSignature(l.only()), "slab(dielectric:RT,-,slab(diffuse,-,-))");
  EXPECT_EQ(l.effects(), (std::vector<std::string>{"diffuse", "specular"}));
  const ir::Interface* diffuse = findInterface(l.only(), ir::InterfaceKind::Diffuse);
  ASSERT_NE(diffuse, nullptr);
  EXPECT_EQ(diffuse->diffuseModel, ir::DiffuseModel::EON);  // OpenPBR "Glossy-diffuse"
  EXPECT_EQ(constant(l.only(), diffuse->slots.value(Slot::Color)), (std::vector<float>{0.8f, 0.8f, 0.8f}));
}

TEST(Lowering, ColourValuesAreConvertedFromTheirColourSpace) {
  auto diffuseColor = [](const std::string& documentSpace, const std::string& input) {
    Lowered l = lower("<?xml version=\"1.0\"?>\n<materialx version=\"1.39\"" + documentSpace +
                      ">\n  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n" + input +
                      "  </open_pbr_surface>\n  <surfacematerial name=\"M\" type=\"material\"><input "
                      "name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n"
                      "</materialx>\n");
    const ir::Interface* diffuse = findInterface(l.only(), ir::InterfaceKind::Diffuse);
    return diffuse ? constant(l.only(), diffuse->slots.value(Slot::Color)) : std::vector<float>{};
  };
  auto expectNear = [](const std::vector<float>& got, std::vector<float> expected) {
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-5f) << i;
  };
  // The example: sRGB-encoded 0.5 is 0.214 linear (IEC 61966-2-1).
  expectNear(diffuseColor("", "    <input name=\"base_color\" type=\"color3\" value=\"0.5, 0, 0\" "
                              "colorspace=\"srgb_texture\"/>\n"),
             {0.214041f, 0.0f, 0.0f});
  // Inherited from the document: ACEScg to linear Rec.709 by MaterialX's cmlib matrix.
  expectNear(diffuseColor(" colorspace=\"acescg\"", in("base_color", "color3", "0.5, 0.4, 0.3")),
             {0.578831f, 0.388029f, 0.282302f});
  // An input's own colour space wins over the document's; data spaces are never converted.
  expectNear(diffuseColor(" colorspace=\"acescg\"", "    <input name=\"base_color\" type=\"color3\" "
                                                     "value=\"0.5, 0.4, 0.3\" colorspace=\"raw\"/>\n"),
             {0.5f, 0.4f, 0.3f});
  expectNear(diffuseColor(" colorspace=\"lin_rec709\"", in("base_color", "color3", "0.5, 0.4, 0.3")), {0.5f, 0.4f, 0.3f});
}

TEST(Lowering, AnUnknownColourSpaceIsReportedOnceAndLeftAlone) {
  Lowered l = lower(openPbrDocument("    <input name=\"base_color\" type=\"color3\" value=\"0.5, 0.4, 0.3\" "
                               "colorspace=\"bogus_space\"/>\n    <input name=\"coat_color\" type=\"color3\" "
                               "value=\"0.5, 0.4, 0.3\" colorspace=\"bogus_space\"/>\n"));
  int warnings = 0;
  for (const Diagnostic& d : l.context->diagnostics.all()) {
    if (d.message.find("colorspace \"bogus_space\" is not one mxc knows") != std::string::npos) ++warnings;
  }
  EXPECT_EQ(warnings, 1) << l.context->diagnostics.format();
}

std::string usdDocument(const std::string& inputs) {
  return mtlx("  <UsdPreviewSurface name=\"s\" type=\"surfaceshader\">\n" + inputs +
              "  </UsdPreviewSurface>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
              "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n");
}

TEST(UsdPreviewSurfaceLowering, EachWorkflowAndModeHasItsStructure) {
  // Metalness workflow, opaque: the dielectric of `ior` over the Lambertian base.
  Lowered plastic = lower(usdDocument(in("diffuseColor", "color3", "0.2, 0.4, 0.6")));
  EXPECT_EQ(ir::structureSignature(plastic.only()), "slab(dielectric:RT,-,slab(diffuse,-,-))");
  const ir::Interface* diffuse = findInterface(plastic.only(), ir::InterfaceKind::Diffuse);
  ASSERT_NE(diffuse, nullptr);
  EXPECT_EQ(constant(plastic.only(), diffuse->slots.value(Slot::Color)), (std::vector<float>{0.2f, 0.4f, 0.6f}));
  // GGX alpha = roughness^2 (the default roughness 0.5).
  const ir::Interface* spec = findInterface(plastic.only(), ir::InterfaceKind::Dielectric);
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(constant(plastic.only(), spec->slots.value(Slot::Alpha)), (std::vector<float>{0.25f, 0.25f}));
  // metallic 1: the Schlick reflection from diffuseColor to a white edge, nothing else.
  Lowered metal = lower(usdDocument(in("metallic", "float", "1") + in("diffuseColor", "color3", "0.9, 0.6, 0.3")));
  EXPECT_EQ(ir::structureSignature(metal.only()), "slab(schlick:R,-,-)");
  const ir::Interface* schlick = findInterface(metal.only(), ir::InterfaceKind::Schlick);
  ASSERT_NE(schlick, nullptr);
  EXPECT_EQ(constant(metal.only(), schlick->slots.value(Slot::F0)), (std::vector<float>{0.9f, 0.6f, 0.3f}));
  // A white edge: F90 1, which the passes leave absent (its slotDefault).
  EXPECT_EQ(schlick->slots.value(Slot::F90), ir::kNoExpr);
  EXPECT_EQ(ir::slotDefault(Slot::F90), 1.0f);
  // Transparent mode, opacity 0: the dielectric over a body of its IOR (glass still reflects).
  Lowered glass = lower(usdDocument(in("opacity", "float", "0") + in("ior", "float", "1.52")));
  EXPECT_EQ(ir::structureSignature(glass.only()), "slab(dielectric:RT,bulk,-)");
  EXPECT_EQ(glass.only().nodes[glass.only().root].kind, ir::ScatterKind::Slab);  // refracts; nothing is cut out
  // Specular workflow: the specular colour's Schlick reflection over the diffuse base.
  Lowered specular = lower(usdDocument(in("useSpecularWorkflow", "integer", "1") +
                                      in("specularColor", "color3", "0.05, 0.05, 0.05")));
  EXPECT_EQ(ir::structureSignature(specular.only()), "slab(schlick:R,-,slab(diffuse,-,-))");
  // Presence mode: opacity is the coverage (a mix with nothing), not refraction.
  auto coverage = [](const Lowered& l) {
    // A mix with nothing weighs the surface; a coverage of 0 or 1 leaves nothing or the surface.
    const ir::ScatterNode& root = l.only().nodes[l.only().root];
    if (root.kind == ir::ScatterKind::Mix) return constant(l.only(), root.weight.value);
    return std::vector<float>{root.kind == ir::ScatterKind::Ambient ? 0.0f : 1.0f};
  };
  Lowered presence = lower(usdDocument(in("opacityMode", "integer", "1") + in("opacity", "float", "0.25")));
  EXPECT_EQ(ir::structureSignature(presence.only()), "mix(ambient,slab(dielectric:RT,-,slab(diffuse,-,-)))");
  EXPECT_EQ(coverage(presence), std::vector<float>{0.25f});
  // A threshold cuts out: opacity 0.25 below a threshold of 0.5 covers nothing, 0.75 everything.
  Lowered cutout = lower(usdDocument(in("opacity", "float", "0.25") + in("opacityThreshold", "float", "0.5")));
  EXPECT_EQ(coverage(cutout), std::vector<float>{0.0f});
  Lowered kept = lower(usdDocument(in("opacity", "float", "0.75") + in("opacityThreshold", "float", "0.5")));
  EXPECT_EQ(coverage(kept), std::vector<float>{1.0f});
  // A clear coat: a dielectric of IOR 1.5 over the rest.
  Lowered coated = lower(usdDocument(in("clearcoat", "float", "1")));
  EXPECT_EQ(ir::structureSignature(coated.only()), "slab(dielectric:RT,-,slab(dielectric:RT,-,slab(diffuse,-,-)))");
}

std::string gltfDocument(const std::string& inputs) {
  return mtlx("  <gltf_pbr name=\"s\" type=\"surfaceshader\">\n" + inputs +
              "  </gltf_pbr>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
              "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n");
}

TEST(GltfPbrLowering, EachExtensionHasItsPlaceInTheTree) {
  // The defaults (metallic 1, roughness 1): Appendix B's metal, Schlick from base_color.
  Lowered metal = lower(gltfDocument(""));
  EXPECT_EQ(ir::structureSignature(metal.only()), "slab(schlick:R,-,-)");
  // A dielectric: the interface of `ior` over the Lambertian base, alpha = roughness^2.
  Lowered plastic = lower(gltfDocument(in("metallic", "float", "0") + in("roughness", "float", "0.5")));
  EXPECT_EQ(ir::structureSignature(plastic.only()), "slab(dielectric:RT,-,slab(diffuse,-,-))");
  const ir::Interface* spec = findInterface(plastic.only(), ir::InterfaceKind::Dielectric);
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(constant(plastic.only(), spec->slots.value(Slot::Alpha)), (std::vector<float>{0.25f, 0.25f}));
  // KHR_materials_transmission without a volume (thickness 0): thin-walled.
  Lowered thin = lower(gltfDocument(in("metallic", "float", "0") + in("transmission", "float", "1")));
  EXPECT_EQ(ir::structureSignature(thin.only()), "slab(dielectric:RT,thin_wall,-)");
  // With KHR_materials_volume: a bulk absorbing mu_a = -ln(attenuation_color) / attenuation_distance.
  Lowered volume = lower(gltfDocument(in("metallic", "float", "0") + in("transmission", "float", "1") +
                                      in("thickness", "float", "1") + in("attenuation_distance", "float", "2") +
                                      in("attenuation_color", "color3", "0.5, 0.5, 0.5")));
  EXPECT_EQ(ir::structureSignature(volume.only()), "slab(dielectric:RT,bulk,-)");
  const ir::Medium* bulk = findMedium(volume.only(), ir::Medium::Extent::Bulk);
  ASSERT_NE(bulk, nullptr);
  EXPECT_NEAR(constant(volume.only(), bulk->slots.value(Slot::Absorption))[0], -std::log(0.5f) / 2.0f, 1e-6f);
  // KHR_materials_clearcoat over KHR_materials_sheen over the base.
  Lowered layered = lower(gltfDocument(in("metallic", "float", "0") + in("clearcoat", "float", "1") +
                                       in("sheen_color", "color3", "0.5, 0.5, 0.5")));
  EXPECT_EQ(ir::structureSignature(layered.only()),
            "slab(dielectric:RT,-,slab(sheen,-,slab(dielectric:RT,-,slab(diffuse,-,-))))");
  // KHR_materials_iridescence: a film on the base interface.
  Lowered film = lower(gltfDocument(in("iridescence", "float", "1") + in("iridescence_thickness", "float", "400")));
  EXPECT_NE(film.effect("thin_film"), nullptr);
  // alpha_mode MASK: alpha below the cutoff covers nothing.
  Lowered masked = lower(gltfDocument(in("alpha_mode", "integer", "1") + in("alpha", "float", "0.25")));
  EXPECT_EQ(masked.only().nodes[masked.only().root].kind, ir::ScatterKind::Ambient);
}

TEST(OpenPbrLowering, GlassIsADielectricOverAMedium) {
  Lowered l = lowerFile("corpus/materialx/examples/OpenPbr/open_pbr_glass.mtlx");
  EXPECT_EQ(ir::structureSignature(l.only()), "slab(dielectric:RT,bulk,-)");
  EXPECT_EQ(l.effects(), (std::vector<std::string>{"dispersion", "specular", "transmission"}));
  const ir::Medium* bulk = findMedium(l.only(), ir::Medium::Extent::Bulk);
  ASSERT_NE(bulk, nullptr);
  EXPECT_EQ(constant(l.only(), bulk->slots.value(Slot::Ior)), std::vector<float>{1.52f});
  EXPECT_EQ(constant(l.only(), bulk->slots.value(Slot::AbbeNumber)), std::vector<float>{64.0f});  // 64 / scale 1
}

TEST(OpenPbrLowering, CoatWeightZeroHasNoCoat) {
  Lowered without = lower(openPbrDocument(in("coat_weight", "float", "0") + in("coat_color", "color3", "0.5, 0.2, 0.1")));
  EXPECT_EQ(ir::structureSignature(without.only()), "slab(dielectric:RT,-,slab(diffuse,-,-))");
  EXPECT_EQ(without.effect("coat"), nullptr);
  Lowered with = lower(openPbrDocument(in("coat_weight", "float", "1") + in("coat_color", "color3", "0.25, 0.25, 0.25")));
  EXPECT_EQ(ir::structureSignature(with.only()), "slab(dielectric:RT,-,slab(dielectric:RT,-,slab(diffuse,-,-)))");
  ASSERT_NE(with.effect("coat"), nullptr);
  EXPECT_EQ(with.effect("coat")->input, "coat_weight");
  // The coat medium: unit thickness, mu_a = -ln(coat_color) / 2 (coat_color = T^2, OpenPBR "Coat").
  const ir::Medium* coat = findMedium(with.only(), ir::Medium::Extent::Finite);
  ASSERT_NE(coat, nullptr);
  EXPECT_NEAR(constant(with.only(), coat->slots.value(Slot::Absorption))[0], -std::log(0.25f) / 2, 1e-6);
}

TEST(OpenPbrLowering, EachFeatureIsAnEffectKeptByItsInput) {
  struct Case {
    std::string inputs;
    std::string effect;
    std::string input;
  };
  const Case cases[] = {
      {in("fuzz_weight", "float", "0.5"), "fuzz", "fuzz_weight"},
      {in("thin_film_weight", "float", "1") + in("thin_film_thickness", "float", "0.4"), "thin_film", "thin_film_weight"},
      {in("transmission_weight", "float", "1"), "transmission", "transmission_weight"},
      {in("subsurface_weight", "float", "1"), "subsurface", "subsurface_weight"},
      {in("emission_luminance", "float", "100"), "emission", "emission_luminance"},
      {in("specular_roughness_anisotropy", "float", "0.5"), "anisotropy", "specular_roughness_anisotropy"},
      {in("geometry_opacity", "float", "0.5"), "opacity", "geometry_opacity"},
      {in("geometry_thin_walled", "boolean", "true"), "thin_walled", "geometry_thin_walled"},
      {in("base_metalness", "float", "1"), "metal", "base_metalness"},
      {in("transmission_weight", "float", "1") + in("transmission_dispersion_scale", "float", "0.5"), "dispersion",
       "transmission_dispersion_scale"},
      {in("transmission_weight", "float", "1") + in("transmission_depth", "float", "1") +
           in("transmission_color", "color3", "0.5, 0.7, 0.9"),
       "volume", "transmission_color"},
  };
  for (const Case& c : cases) {
    const std::string text = openPbrDocument(c.inputs);
    Lowered l = lower(text);
    const ir::Origin* e = l.effect(c.effect);
    ASSERT_NE(e, nullptr) << c.effect << " in " << fmt::format("{}", fmt::join(l.effects(), ","));
    EXPECT_EQ(e->input, c.input) << c.effect;
    // The origin is the line of that input in the document.
    const size_t at = text.find("name=\"" + c.input + "\"");
    const auto line = static_cast<uint32_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n') + 1);
    EXPECT_EQ(e->location.line(), line) << c.effect;
  }
}

TEST(OpenPbrLowering, FullTreeWhenEveryWeightIsATexture) {
  // With weights that are not constants nothing is pruned: the OpenPBR model tree in full,
  // distributed into slab stacks (OpenPBR "Model").
  std::string inputs;
  for (const char* w : {"base_metalness", "transmission_weight", "subsurface_weight", "coat_weight", "fuzz_weight",
                        "geometry_opacity"}) {
    inputs += std::string("    <input name=\"") + w + "\" type=\"float\" nodename=\"w\"/>\n";
  }
  inputs += "    <input name=\"emission_luminance\" type=\"float\" value=\"1\"/>\n";
  Lowered l = lower(mtlx("  <texcoord name=\"uv\" type=\"vector2\"/>\n  <extract name=\"w\" type=\"float\">\n"
                         "    <input name=\"in\" type=\"vector2\" nodename=\"uv\"/>\n  </extract>\n"
                         "  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n" +
                         inputs + "  </open_pbr_surface>\n  <surfacematerial name=\"m\" type=\"material\">\n"
                         "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/>\n  </surfacematerial>\n"));
  std::string sig = ir::structureSignature(l.only());
  EXPECT_EQ(sig,
            "mix(ambient,"
            "mix(mix(mix("
            "slab(sheen,-,slab(dielectric:RT,-,emissive(slab(dielectric:RT,-,slab(diffuse,-,-))),cov),cov),"
            "slab(sheen,-,slab(dielectric:RT,-,emissive(slab(dielectric:RT,bulk,-)),cov),cov)),"
            "slab(sheen,-,slab(dielectric:RT,-,emissive(slab(dielectric:RT,bulk,-)),cov),cov)),"
            "slab(sheen,-,slab(dielectric:RT,-,emissive(slab(schlick:R,-,-)),cov),cov)))")
      << sig;
}

TEST(OpenPbrLowering, AnisotropicAlphaFollowsTheSpecFormula) {
  // alpha_t = r^2 sqrt(2 / (1 + (1 - a)^2)), alpha_b = (1 - a) alpha_t (OpenPBR "Microfacet model").
  Lowered l = lower(openPbrDocument(in("specular_roughness", "float", "0.5") + in("specular_roughness_anisotropy", "float", "0.5")));
  const ir::Interface* d = findInterface(l.only(), ir::InterfaceKind::Dielectric);
  std::vector<float> alpha = constant(l.only(), d->slots.value(Slot::Alpha));
  ASSERT_EQ(alpha.size(), 2u);
  EXPECT_NEAR(alpha[0], 0.25f * std::sqrt(2.0f / 1.25f), 1e-6);
  EXPECT_NEAR(alpha[1], 0.5f * alpha[0], 1e-6);
  EXPECT_NEAR(alpha[0] * alpha[0] + alpha[1] * alpha[1], 2 * std::pow(0.5f, 4.0f), 1e-6);
}

TEST(OpenPbrLowering, SubsurfaceMediumFromColourAndRadius) {
  Lowered l = lower(openPbrDocument(in("subsurface_weight", "float", "1") + in("subsurface_color", "color3", "0.8, 0.5, 0.2") +
                            in("subsurface_radius", "float", "2") + in("subsurface_radius_scale", "color3", "1, 1, 1")));
  const ir::Medium* sss = findMedium(l.only(), ir::Medium::Extent::Bulk);
  ASSERT_NE(sss, nullptr);
  std::vector<float> absorption = constant(l.only(), sss->slots.value(Slot::Absorption));
  std::vector<float> scattering = constant(l.only(), sss->slots.value(Slot::Scattering));
  for (int c = 0; c < 3; ++c) {
    // mu_t = 1 / r, and van de Hulst's single-scattering albedo for C (OpenPBR "Subsurface").
    const float C = std::vector<float>{0.8f, 0.5f, 0.2f}[c];
    const float s = 4.09712f + 4.20863f * C - std::sqrt(9.59217f + 41.6808f * C + 17.7126f * C * C);
    const float albedo = 1 - s * s;
    EXPECT_NEAR(absorption[c] + scattering[c], 0.5f, 1e-5) << c;
    EXPECT_NEAR(scattering[c] / 0.5f, albedo, 1e-5) << c;
  }
}

TEST(OpenPbrLowering, TransmissionMediumFromColourAndDepth) {
  Lowered l = lower(openPbrDocument(in("transmission_weight", "float", "1") + in("transmission_color", "color3", "0.5, 0.5, 0.5") +
                            in("transmission_depth", "float", "2") + in("transmission_scatter", "color3", "0.1, 0.2, 0.4")));
  const ir::Medium* bulk = findMedium(l.only(), ir::Medium::Extent::Bulk);
  ASSERT_NE(bulk, nullptr);
  std::vector<float> mua = constant(l.only(), bulk->slots.value(Slot::Absorption));
  std::vector<float> mus = constant(l.only(), bulk->slots.value(Slot::Scattering));
  // mu_t = -ln(0.5)/2 = 0.3466, mu_s = S/2; mu_a = mu_t - mu_s is positive here, so no grey shift.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mua[c] + mus[c], -std::log(0.5f) / 2, 1e-6) << c;
  EXPECT_NEAR(mus[2], 0.2f, 1e-6);
  // With scattering above the extinction, mu_a is shifted by grey so that it stays >= 0.
  Lowered shifted = lower(openPbrDocument(in("transmission_weight", "float", "1") + in("transmission_color", "color3", "0.9, 0.9, 0.9") +
                                  in("transmission_depth", "float", "1") + in("transmission_scatter", "color3", "1, 0, 0")));
  std::vector<float> mua2 = constant(shifted.only(), findMedium(shifted.only(), ir::Medium::Extent::Bulk)->slots.value(Slot::Absorption));
  EXPECT_NEAR(*std::min_element(mua2.begin(), mua2.end()), 0.0f, 1e-6);
}

TEST(OpenPbrLowering, TexturedCoverageStaysAParameter) {
  Lowered l = lower(mtlx("  <texcoord name=\"uv\" type=\"vector2\"/>\n  <extract name=\"w\" type=\"float\">\n"
                         "    <input name=\"in\" type=\"vector2\" nodename=\"uv\"/>\n  </extract>\n"
                         "  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
                         "    <input name=\"coat_weight\" type=\"float\" nodename=\"w\"/>\n  </open_pbr_surface>\n"
                         "  <surfacematerial name=\"m\" type=\"material\">\n"
                         "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/>\n  </surfacematerial>\n"));
  EXPECT_EQ(ir::structureSignature(l.only()), "slab(dielectric:RT,-,slab(dielectric:RT,-,slab(diffuse,-,-)),cov)");
  const ir::ScatterNode& coat = l.only().nodes[l.only().root];
  EXPECT_EQ(coat.coverage.origin.input, "coat_weight");
  EXPECT_EQ(l.only().exprs[coat.coverage.value].op, ir::Op::Clamp);
}

TEST(StandardSurfaceLowering, SheenAndMetalAndCoat) {
  Lowered l = lowerFile("corpus/materialx/examples/StandardSurface/standard_surface_velvet.mtlx");
  EXPECT_NE(l.effect("sheen"), nullptr);
  const ir::Interface* sheen = findInterface(l.only(), ir::InterfaceKind::Sheen);
  ASSERT_NE(sheen, nullptr);
  EXPECT_EQ(sheen->sheenModel, ir::SheenModel::ContyKulla);
  Lowered gold = lowerFile("corpus/materialx/examples/StandardSurface/standard_surface_gold.mtlx");
  const ir::Interface* metal = findInterface(gold.only(), ir::InterfaceKind::Conductor);
  ASSERT_NE(metal, nullptr);
  // The conductor's complex IOR comes from the artistic colours (Gulbrandsen 2014): n, k > 0.
  EXPECT_GT(constant(gold.only(), metal->slots.value(Slot::ComplexIor))[0], 0.0f);
  EXPECT_NE(gold.effect("metal"), nullptr);
}

TEST(StandardSurfaceLowering, SpecularIorIsNotRelativeToTheCoat) {
  // Standard Surface "Layering" weights the specular BRDF by the coat's transmission but keeps
  // specular_IOR against the ambient medium; OpenPBR (eq. specular_ior_ratio) takes it relative
  // to the coat. With equal IORs the OpenPBR base specular is index-matched; Standard
  // Surface's is not.
  Lowered ss = lowerFile("corpus/materialx/examples/StandardSurface/standard_surface_carpaint.mtlx");
  Lowered op = lowerFile("corpus/materialx/examples/OpenPbr/open_pbr_carpaint.mtlx");
  auto specular = [](const ir::Material& m) {
    const ir::Interface* found = nullptr;  // the dielectric below the coat (the last one lowered first)
    for (const ir::Interface& i : m.interfaces) {
      if (i.kind == ir::InterfaceKind::Dielectric && !found) found = &i;
    }
    return found;
  };
  ASSERT_NE(specular(ss.only()), nullptr);
  ASSERT_NE(specular(op.only()), nullptr);
  EXPECT_EQ(specular(ss.only())->iorReference, ir::IorReference::Ambient);
  EXPECT_EQ(specular(op.only())->iorReference, ir::IorReference::MediumAbove);
}

TEST(PbrlibLowering, LayerAndMixBuildStacks) {
  Lowered l = lower(mtlx(
      "  <oren_nayar_diffuse_bsdf name=\"d\" type=\"BSDF\"/>\n"
      "  <dielectric_bsdf name=\"coat\" type=\"BSDF\"><input name=\"weight\" type=\"float\" value=\"0.7\"/></dielectric_bsdf>\n"
      "  <conductor_bsdf name=\"metal\" type=\"BSDF\"/>\n"
      "  <mix name=\"base\" type=\"BSDF\">\n    <input name=\"fg\" type=\"BSDF\" nodename=\"metal\"/>\n"
      "    <input name=\"bg\" type=\"BSDF\" nodename=\"d\"/>\n    <input name=\"mix\" type=\"float\" value=\"0.25\"/>\n  </mix>\n"
      "  <layer name=\"coated\" type=\"BSDF\">\n    <input name=\"top\" type=\"BSDF\" nodename=\"coat\"/>\n"
      "    <input name=\"base\" type=\"BSDF\" nodename=\"base\"/>\n  </layer>\n"
      "  <surface name=\"surf\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" nodename=\"coated\"/></surface>\n"
      "  <surfacematerial name=\"m\" type=\"material\">\n"
      "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"surf\"/>\n  </surfacematerial>\n"));
  // layer(coat weighted 0.7, mix(d, metal, 0.25)): the weight is the coat slab's coverage, and
  // the slab distributes over the mix (mix(fg, bg, w) has bg on the weight-0 side).
  EXPECT_EQ(ir::structureSignature(l.only()),
            "mix(slab(dielectric:RT,-,slab(diffuse,-,-),cov),slab(dielectric:RT,-,slab(conductor,-,-),cov))");
  // The dielectric is a coat over the metal and the gloss of the plastic part.
  EXPECT_EQ(l.effects(), (std::vector<std::string>{"coat", "diffuse", "metal", "specular"}));
}

TEST(PbrlibLowering, AScaledTopLetsTheBaseShowWhereItIsAbsent) {
  // layer(0.4 top, base) = 0.4 top + (1 - 0.4 E_top) base (MaterialX "layer"): where the top
  // is absent the base shows, so the scaled top is a coverage, not a black surface.
  Lowered l = lower(mtlx(
      "  <oren_nayar_diffuse_bsdf name=\"d\" type=\"BSDF\"/>\n  <dielectric_bsdf name=\"coat\" type=\"BSDF\"/>\n"
      "  <multiply name=\"scaled\" type=\"BSDF\">\n    <input name=\"in1\" type=\"BSDF\" nodename=\"coat\"/>\n"
      "    <input name=\"in2\" type=\"float\" value=\"0.4\"/>\n  </multiply>\n"
      "  <layer name=\"coated\" type=\"BSDF\">\n    <input name=\"top\" type=\"BSDF\" nodename=\"scaled\"/>\n"
      "    <input name=\"base\" type=\"BSDF\" nodename=\"d\"/>\n  </layer>\n"
      "  <surface name=\"surf\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" nodename=\"coated\"/></surface>\n"));
  EXPECT_EQ(ir::structureSignature(l.only()), "mix(slab(diffuse,-,-),slab(dielectric:RT,-,slab(diffuse,-,-)))");
}

TEST(PbrlibLowering, AddIsFlaggedAsNotEnergyBounded) {
  Lowered l = lower(mtlx(
      "  <oren_nayar_diffuse_bsdf name=\"a\" type=\"BSDF\"/>\n  <sheen_bsdf name=\"b\" type=\"BSDF\"/>\n"
      "  <add name=\"sum\" type=\"BSDF\">\n    <input name=\"in1\" type=\"BSDF\" nodename=\"a\"/>\n"
      "    <input name=\"in2\" type=\"BSDF\" nodename=\"b\"/>\n  </add>\n"
      "  <surface name=\"surf\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" nodename=\"sum\"/></surface>\n"));
  EXPECT_EQ(ir::structureSignature(l.only()), "add(slab(diffuse,-,-),slab(sheen,-,-))");
  ASSERT_FALSE(l.only().notes.empty());
  EXPECT_NE(l.only().notes[0].message.find("not energy-bounded"), std::string::npos);
  EXPECT_NE(l.effect("unbounded_sum"), nullptr);
}

TEST(PbrlibLowering, ThinFilmMixAndVolumeLayer) {
  Lowered l = lowerFile("corpus/materialx/testsuite/pbrlib/bsdf/thin_film_bsdf.mtlx");
  ASSERT_GE(l.materials.size(), 1u);
  EXPECT_EQ(ir::structureSignature(l.materials[0]), "slab(dielectric:R+film,-,-)");
  EXPECT_NE(l.effect("thin_film"), nullptr);
}

TEST(Lowering, NodeGraphImplementationsAreInlined) {
  Lowered l = lower(mtlx(
      "  <nodedef name=\"ND_half\" node=\"half\">\n    <input name=\"in\" type=\"color3\" value=\"1, 1, 1\"/>\n"
      "    <output name=\"out\" type=\"color3\"/>\n  </nodedef>\n"
      "  <nodegraph name=\"NG_half\" nodedef=\"ND_half\">\n    <multiply name=\"h\" type=\"color3\">\n"
      "      <input name=\"in1\" type=\"color3\" interfacename=\"in\"/>\n      <input name=\"in2\" type=\"float\" value=\"0.5\"/>\n"
      "    </multiply>\n    <output name=\"out\" type=\"color3\" nodename=\"h\"/>\n  </nodegraph>\n"
      "  <half name=\"c\" type=\"color3\"><input name=\"in\" type=\"color3\" value=\"0.6, 0.4, 0.2\"/></half>\n" +
      std::string("  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n"
                  "    <input name=\"base_color\" type=\"color3\" nodename=\"c\"/>\n  </open_pbr_surface>\n"
                  "  <surfacematerial name=\"m\" type=\"material\">\n"
                  "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"s\"/>\n  </surfacematerial>\n")));
  const ir::Interface* diffuse = findInterface(l.only(), ir::InterfaceKind::Diffuse);
  ASSERT_NE(diffuse, nullptr);
  std::vector<float> color = constant(l.only(), diffuse->slots.value(Slot::Color));
  ASSERT_EQ(color.size(), 3u);
  EXPECT_FLOAT_EQ(color[0], 0.3f);
  EXPECT_FLOAT_EQ(color[2], 0.1f);
}

TEST(Lowering, ConicalEmissionUnderASchlickFactorKeepsItsAngles) {
  // The cone's angles had the slots Roughness and Exponent; a generalized Schlick factor over
  // the cone wrote its exponent into Exponent, so the outer angle became 3 degrees.
  Lowered l = lower(mtlx(
      "  <conical_edf name=\"cone\" type=\"EDF\">\n" + in("inner_angle", "float", "20") + in("outer_angle", "float", "40") +
      "  </conical_edf>\n"
      "  <generalized_schlick_edf name=\"fade\" type=\"EDF\">\n" + in("exponent", "float", "3") +
      "    <input name=\"base\" type=\"EDF\" nodename=\"cone\"/>\n  </generalized_schlick_edf>\n"
      "  <surface name=\"surf\" type=\"surfaceshader\"><input name=\"edf\" type=\"EDF\" nodename=\"fade\"/></surface>\n"));
  ASSERT_EQ(l.only().emissions.size(), 1u);
  const ir::Emission& e = l.only().emissions[0];
  EXPECT_EQ(e.kind, ir::Emission::Kind::Conical);
  EXPECT_EQ(constant(l.only(), e.slots.value(Slot::InnerAngle)), std::vector<float>{20.0f});
  EXPECT_EQ(constant(l.only(), e.slots.value(Slot::OuterAngle)), std::vector<float>{40.0f});
  EXPECT_EQ(constant(l.only(), e.slots.value(Slot::Exponent)), std::vector<float>{3.0f});
  const std::string glsl = buildShader(l.only(), glsl::ShaderKind::Raster).glsl.text;
  EXPECT_NE(glsl.find("mxc_cone_falloff(dot(v1, wo), 20.0, 40.0)"), std::string::npos);  // v1: the normal
  EXPECT_NE(glsl.find("mxc_fresnel_schlick(clamp(dot(g.N, wo), 0.0, 1.0), vec3(1.0), vec3(1.0), 3.0)"), std::string::npos);
}

TEST(Lowering, UnsupportedNodeIsAnErrorAtItsElement) {
  Context context;
  CompileRequest request;
  request.document = "test.mtlx";
  // A node the document defines without any implementation.
  request.text = mtlx(
      "  <nodedef name=\"ND_glow\" node=\"glow\"><output name=\"out\" type=\"color3\"/></nodedef>\n"
      "  <glow name=\"g\" type=\"color3\"/>\n"
      "  <surface_unlit name=\"surf\" type=\"surfaceshader\"><input name=\"emission_color\" type=\"color3\" "
      "nodename=\"g\"/></surface_unlit>\n");
  Compiler compiler(context, request);
  ASSERT_NE(compiler.resolved(), nullptr);
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  compiler.materials();
  Diagnostic e = context.firstError();
  EXPECT_NE(e.message.find("<glow> (nodedef ND_glow) is not supported"), std::string::npos) << e.message;
  EXPECT_EQ(e.location.line(), 4u);
  EXPECT_EQ(e.location.lineColumn().column, 3u);
}

// A node of a category no nodedef defines only warns while the document is read (as MaterialX
// reads it); a material that needs it, as a value or as its shader, is an error at the node, once.
TEST(Lowering, ANodeOfAnUnknownCategoryIsAnErrorWhereAMaterialNeedsIt) {
  for (const bool asShader : {false, true}) {
    Context context;
    CompileRequest request;
    request.document = "test.mtlx";
    request.text = mtlx(asShader ? "  <glow name=\"g\" type=\"surfaceshader\"/>\n"
                                   "  <surfacematerial name=\"m\" type=\"material\"><input name=\"surfaceshader\" "
                                   "type=\"surfaceshader\" nodename=\"g\"/></surfacematerial>\n"
                                 : "  <glow name=\"g\" type=\"color3\"/>\n"
                                   "  <surface_unlit name=\"surf\" type=\"surfaceshader\"><input name=\"emission_color\" "
                                   "type=\"color3\" nodename=\"g\"/><input name=\"transmission_color\" type=\"color3\" "
                                   "nodename=\"g\"/></surface_unlit>\n");
    Compiler compiler(context, request);
    ASSERT_NE(compiler.resolved(), nullptr);
    ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
    compiler.materials();
    Diagnostic e = context.firstError();
    EXPECT_NE(e.message.find("node 'g' is a <glow>, which no nodedef defines"), std::string::npos)
        << asShader << ": " << context.diagnostics.format();
    EXPECT_EQ(e.location.line(), 3u);
    size_t errors = 0;
    for (const Diagnostic& d : context.diagnostics.all()) errors += d.severity == Severity::Error;
    EXPECT_EQ(errors, 1u) << context.diagnostics.format();
  }
}

TEST(Lowering, AGraphDeeperThanTheStackIsAnErrorNotACrash) {
  // A chain of 40,000 sin nodes on a 16 MiB stack: lowering recurses once per node on the
  // path, so it must stop with an error at the node where the stack runs short (the CLI's
  // 1 GiB stack moves that point to millions of nodes; the mechanism is the same).
  std::string body = "  <texcoord name=\"uv\" type=\"vector2\"/>\n"
                     "  <extract name=\"n0\" type=\"float\"><input name=\"in\" type=\"vector2\" nodename=\"uv\"/>"
                     "<input name=\"index\" type=\"integer\" value=\"0\"/></extract>\n";
  constexpr int kNodes = 40000;
  for (int i = 1; i < kNodes; ++i) {
    body += fmt::format("  <sin name=\"n{}\" type=\"float\"><input name=\"in\" type=\"float\" nodename=\"n{}\"/></sin>\n", i,
                        i - 1);
  }
  body += fmt::format("  <open_pbr_surface name=\"s\" type=\"surfaceshader\"><input name=\"base_weight\" type=\"float\" "
                      "nodename=\"n{}\"/></open_pbr_surface>\n",
                      kNodes - 1);
  Context context;
  CompileRequest request;
  request.document = "deep.mtlx";
  request.text = mtlx(body);
  Compiler compiler(context, request);
  runWithLargeStack(
      [&] {
        ASSERT_NE(compiler.resolved(), nullptr);
        ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
        compiler.materials();
      },
      size_t{16} << 20);
  ASSERT_TRUE(context.diagnostics.hasErrors());
  Diagnostic e = context.firstError();
  EXPECT_NE(e.message.find("the graph is too deep to lower"), std::string::npos) << e.message;
  EXPECT_GT(e.location.line(), 3u);  // a sin node of the chain, named by its line
  size_t errors = 0;
  for (const Diagnostic& d : context.diagnostics.all()) errors += d.severity == Severity::Error;
  EXPECT_EQ(errors, 1u) << "reported once, not once per node beyond the limit";
}

TEST(Lowering, EveryCorpusMaterialLowers) {
  // The acceptance walk: every corpus document lowers without error, and every material has
  // a root and an effect list (at least one effect unless it is black).
  size_t materials = 0;
  for (const char* dir : {"corpus/materialx/examples/OpenPbr", "corpus/materialx/examples/StandardSurface",
                          "corpus/openpbr-presets", "corpus/materialx/testsuite/pbrlib/bsdf"}) {
    for (const auto& e : std::filesystem::directory_iterator(sharedDir() / dir)) {
      if (e.path().extension() != ".mtlx") continue;
      Lowered l = lowerFile(std::filesystem::relative(e.path(), sharedDir()).string());
      for (const ir::Material& m : l.materials) {
        EXPECT_NE(m.root, ir::kNone) << e.path();
        ++materials;
      }
    }
  }
  EXPECT_GE(materials, 90u);
}

}  // namespace
}  // namespace mxc::test
