// The hard-case suite (mission demand 2): named extreme configurations of both shading models
// and of single pbrlib BSDFs, each run through the compute harness on every accuracy tier
// (kAccuracies; the tier is the second part of a test's name). For every case, over many
// direction pairs (grazing, back-facing, below the surface) f cos and the pdf must be finite
// and non-negative, and the directional albedo at views from normal incidence to 89.9 degrees
// must be finite, non-negative and bounded by 1 (exactly 1 for the lossless configurations of
// physics-notes.md section 2.1). Each case names its expectation and the spec section behind it.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

#include <fmt/format.h>

#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

enum class Energy : uint8_t {
  Bounded,   ///< E(wo) <= 1 at every view (physics notes 2.1: anything physically bounded)
  Lossless,  ///< E(wo) = 1 at every view (physics notes 2.1: white furnace configurations)
  /// E(wo) = 1 on the tiers with multiple-scattering compensation (balanced), bounded by 1 on
  /// the fast tier, whose single-scattering microfacet lobes lose energy (physics notes 2.2)
  Compensated,
  /// E(wo) = 1 with light entering a non-absorbing scattering half-space. The reference tier's
  /// walk there is a random walk whose length has no finite mean (its tail falls as n^-1/2):
  /// the walks its budget of events cuts (mxc_walk.glsl, MXC_WALK_BUDGET) are lost, under
  /// kHalfSpaceLoss of the energy; the other tiers see an opaque diffuse and keep 1.
  LosslessHalfSpace,
};

/// The reference tier's loss where a walk in a conservative half-space is cut (measured 0.018
/// with the subsurface_radius_0 case at a budget of 65000 events).
constexpr float kHalfSpaceLoss = 0.03f;

/// Whether a case's albedo must be 1 on a tier.
bool lossless(Energy energy, Accuracy accuracy) {
  return energy == Energy::Lossless || (energy == Energy::LosslessHalfSpace && accuracy != Accuracy::Reference) ||
         (energy == Energy::Compensated && accuracy != Accuracy::Fast);
}

struct HardCase {
  const char* name;
  const char* model;   ///< "openpbr", "standard", "usd", "gltf", "disney" (shading node with `inputs`), "hair" (a chiang_hair_bsdf with `inputs`), "bsdf" (BSDF nodes, the surface's named "b") or "document" (`inputs` is the body)
  const char* inputs;  ///< <input> elements, or a document body
  Energy energy;
  const char* why;     ///< the expectation and the section of the spec or paper behind it
};

// clang-format off
const HardCase kCases[] = {
  {"roughness_0", "openpbr", R"(<input name="specular_roughness" type="float" value="0" />)", Energy::Bounded,
   "a perfect mirror is a delta lobe: no NaN from alpha = 0 in D (OpenPBR 'Specular': roughness 0 is allowed)"},
  {"roughness_1e-6", "openpbr", R"(<input name="specular_roughness" type="float" value="1e-6" />)", Energy::Bounded,
   "alpha = 1e-12: below the delta threshold, same as 0 (continuity)"},
  {"roughness_1_anisotropy_1", "openpbr", R"(<input name="specular_roughness" type="float" value="1" /><input name="specular_roughness_anisotropy" type="float" value="1" />)", Energy::Bounded,
   "alpha_t = sqrt(2), alpha_b = 0 (OpenPBR eq. anisotropic_roughness): one axis a mirror, the other beyond 1"},
  {"anisotropy_1_roughness_0", "openpbr", R"(<input name="specular_roughness" type="float" value="0" /><input name="specular_roughness_anisotropy" type="float" value="1" />)", Energy::Bounded,
   "both alphas 0: the delta lobe (OpenPBR 'Specular' anisotropy)"},
  {"ior_1_white_base", "openpbr", R"(<input name="specular_ior" type="float" value="1" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Lossless,
   "index-matched interface: F = 0 at every angle, the white EON base alone gives 1 (physics notes 2.3, case 11)"},
  {"ior_1.0001", "openpbr", R"(<input name="specular_ior" type="float" value="1.0001" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Lossless,
   "just above index matching: F ~ 1e-9, still lossless over a white base"},
  {"ior_0.9999", "openpbr", R"(<input name="specular_ior" type="float" value="0.9999" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "just below 1: total internal reflection near grazing; F(1/n) is used for the albedo table"},
  {"coat_ior_below_specular_ior", "openpbr", R"(<input name="coat_weight" type="float" value="1" /><input name="coat_ior" type="float" value="1.2" /><input name="specular_ior" type="float" value="1.8" />)", Energy::Bounded,
   "the base is denser than the coat: OpenPBR eq. specular_ior_ratio_with_tir_fix"},
  {"coat_ior_above_specular_ior_white", "openpbr", R"(<input name="coat_weight" type="float" value="1" /><input name="coat_ior" type="float" value="2.0" /><input name="specular_ior" type="float" value="1.3" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "eta < 1 at the base interface (TIR inside the stack); a clear coat over white may lose nothing but never gains"},
  {"coat_darkening_coat_ior_1", "openpbr", R"(<input name="coat_weight" type="float" value="1" /><input name="coat_ior" type="float" value="1" /><input name="coat_darkening" type="float" value="1" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Lossless,
   "an index-matched coat reflects nothing and darkens nothing: K = 0, Delta = 1 (OpenPBR 'Coat', physics notes 2.5)"},
  {"clear_coat_white_base", "openpbr", R"(<input name="coat_weight" type="float" value="1" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "a clear coat over a lossless base (physics notes 2.1: 1 for the ground truth; albedo scaling may lose energy, never gain)"},
  {"backfacing_shading_normal", "openpbr", R"(<input name="geometry_normal" type="vector3" value="0, 0, -1" />)", Energy::Bounded,
   "N.V < 0 for every view: the lobes see wo below their hemisphere and return 0"},
  {"tilted_shading_normal", "openpbr", R"(<input name="geometry_normal" type="vector3" value="0.9, 0, 0.1" />)", Energy::Bounded,
   "a shading normal far from the geometric one: grazing and below-horizon configurations"},
  {"zero_tangent", "openpbr", R"(<input name="geometry_tangent" type="vector3" value="0, 0, 0" /><input name="specular_roughness_anisotropy" type="float" value="0.8" />)", Energy::Bounded,
   "a zero tangent is replaced by one built from N (Duff et al. 2017)"},
  {"tangent_parallel_to_normal", "openpbr", R"(<input name="geometry_tangent" type="vector3" value="0, 0, 1" /><input name="specular_roughness_anisotropy" type="float" value="0.8" />)", Energy::Bounded,
   "a tangent with nothing left after projection into the tangent plane: same fallback"},
  {"nan_tangent", "document", R"(
  <divide name="zero_by_zero" type="vector3">
    <input name="in1" type="vector3" value="0, 0, 0" />
    <input name="in2" type="vector3" value="0, 0, 0" />
  </divide>
  <open_pbr_surface name="s" type="surfaceshader">
    <input name="specular_roughness_anisotropy" type="float" value="0.8" />
    <input name="geometry_tangent" type="vector3" nodename="zero_by_zero" />
  </open_pbr_surface>
  <surfacematerial name="M" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s" /></surfacematerial>
)", Energy::Bounded, "a NaN tangent computed at run time (0 / 0) falls back like a zero one"},
  {"flake_normal_extremes", "document", R"(
  <flake3d name="f" type="multioutput">
    <input name="size" type="float" value="0" />
    <input name="coverage" type="float" value="5" />
    <input name="roughness" type="float" value="3" />
    <input name="tangent" type="vector3" value="0, 0, 0" />
  </flake3d>
  <open_pbr_surface name="s" type="surfaceshader">
    <input name="base_metalness" type="float" value="1" />
    <input name="base_color" type="color3" value="1, 1, 1" />
    <input name="geometry_normal" type="vector3" nodename="f" output="flakenormal" />
  </open_pbr_surface>
  <surfacematerial name="M" type="material"><input name="surfaceshader" type="surfaceshader" nodename="s" /></surfacematerial>
)", Energy::Bounded, "flakes of size 0 and coverage above 1, normals of roughness 3 in a frame without tangent: a unit normal, no division by zero"},
  {"thin_film_thickness_0", "openpbr", R"(<input name="thin_film_weight" type="float" value="1" /><input name="thin_film_thickness" type="float" value="0" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Lossless,
   "no film: the interface's own Fresnel (OpenPBR 'Thin-film iridescence'); removed by the passes"},
  {"thin_film_thick", "openpbr", R"(<input name="thin_film_weight" type="float" value="1" /><input name="thin_film_thickness" type="float" value="1000" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "1 mm of film: the incoherent limit, grey (physics notes 2.6)"},
  {"thin_film_ior_1", "openpbr", R"(<input name="thin_film_weight" type="float" value="1" /><input name="thin_film_thickness" type="float" value="0.3" /><input name="thin_film_ior" type="float" value="1" />)", Energy::Bounded,
   "an index-matched film changes nothing (physics notes 2.6)"},
  {"thin_film_on_metal", "openpbr", R"(<input name="thin_film_weight" type="float" value="1" /><input name="thin_film_thickness" type="float" value="0.5" /><input name="base_metalness" type="float" value="1" />)", Energy::Bounded,
   "film over an F82 metal: the base IOR is derived from F0 (OpenPBR 'Thin-film iridescence')"},
  {"transmission_depth_0_smooth", "openpbr", R"(<input name="transmission_weight" type="float" value="1" /><input name="transmission_depth" type="float" value="0" /><input name="specular_roughness" type="float" value="0" />)", Energy::Lossless,
   "white transmission at depth 0, smooth: R + T = 1 exactly (physics notes 2.1)"},
  {"transmission_depth_0_rough", "openpbr", R"(<input name="transmission_weight" type="float" value="1" /><input name="transmission_depth" type="float" value="0" />)", Energy::Compensated,
   "1 for the ground truth (physics notes 2.1); single-scattering rough refraction loses energy (2.2), compensated on balanced"},
  {"transmission_rough", "openpbr", R"(<input name="transmission_weight" type="float" value="1" /><input name="specular_roughness" type="float" value="0.7" />)", Energy::Compensated,
   "rough refraction: single scattering loses energy (physics notes 2.2), compensated on balanced"},
  {"transmission_dark_thin", "openpbr", R"(<input name="transmission_weight" type="float" value="1" /><input name="transmission_color" type="color3" value="0.01, 0.5, 0" /><input name="transmission_depth" type="float" value="1e-6" />)", Energy::Bounded,
   "a tiny depth makes the absorption coefficient huge (-ln c / d); a zero colour makes it infinite"},
  {"thin_walled_transmission", "openpbr", R"(<input name="geometry_thin_walled" type="boolean" value="true" /><input name="transmission_weight" type="float" value="1" /><input name="specular_roughness" type="float" value="0" />)", Energy::Lossless,
   "a thin dielectric sheet: reflected plus passed straight through is 1 (OpenPBR 'Thin-walled mode')"},
  {"subsurface_radius_0", "openpbr", R"(<input name="subsurface_weight" type="float" value="1" /><input name="subsurface_radius" type="float" value="0" /><input name="subsurface_color" type="color3" value="1, 1, 1" />)", Energy::LosslessHalfSpace,
   "zero mean free path: an opaque diffuse of the subsurface colour (OpenPBR 'Subsurface'); white is lossless"},
  {"fuzz_on_black", "openpbr", R"(<input name="fuzz_weight" type="float" value="1" /><input name="base_color" type="color3" value="0, 0, 0" />)", Energy::Bounded,
   "only the fuzz and the specular lobe reflect"},
  {"fuzz_white_on_white", "openpbr", R"(<input name="fuzz_weight" type="float" value="1" /><input name="fuzz_color" type="color3" value="1, 1, 1" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "fuzz over a lossless base (physics notes 2.1: 1 for the ground truth; albedo scaling never gains)"},
  {"base_color_above_1", "openpbr", R"(<input name="base_color" type="color3" value="2, 2, 2" />)", Energy::Bounded,
   "albedos are clamped to [0, 1] (OpenPBR 'Parameter reference')"},
  {"negative_inputs", "openpbr", R"(<input name="base_color" type="color3" value="-1, -1, -1" /><input name="specular_roughness" type="float" value="-1" /><input name="coat_weight" type="float" value="-1" /><input name="specular_weight" type="float" value="-1" />)", Energy::Bounded,
   "every input is clamped to its range (OpenPBR 'Parameter reference')"},
  {"huge_emission", "openpbr", R"(<input name="emission_luminance" type="float" value="1e30" /><input name="emission_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "emission is not part of the BSDF: the albedo is unaffected, nothing overflows"},
  {"white_metal", "openpbr", R"(<input name="base_metalness" type="float" value="1" /><input name="base_color" type="color3" value="1, 1, 1" /><input name="specular_color" type="color3" value="1, 1, 1" /><input name="specular_roughness" type="float" value="0.6" />)", Energy::Compensated,
   "1 for the ground truth (physics notes 2.1); single-scattering GGX loses energy (2.2), compensated on balanced"},
  {"geometry_opacity_0", "openpbr", R"(<input name="geometry_opacity" type="float" value="0" />)", Energy::Lossless,
   "fully transparent: all light passes straight through (OpenPBR 'Opacity / Transparency')"},
  {"geometry_opacity_half_white", "openpbr", R"(<input name="geometry_opacity" type="float" value="0.5" /><input name="base_color" type="color3" value="1, 1, 1" /><input name="specular_weight" type="float" value="0" />)", Energy::Lossless,
   "a mix of a lossless surface and of nothing (physics notes 2.1: unchanged by geometry_opacity)"},
  {"ss_default_white", "standard", R"(<input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "Standard Surface's weighted layering ('Layering'): bounded"},
  {"ss_ior_1", "standard", R"(<input name="specular_IOR" type="float" value="1" /><input name="base_color" type="color3" value="1, 1, 1" /><input name="base" type="float" value="1" />)", Energy::Lossless,
   "no specular reflection over a white Oren-Nayar of roughness 0"},
  {"ss_thin_walled_transmission", "standard", R"(<input name="thin_walled" type="boolean" value="true" /><input name="transmission" type="float" value="1" />)", Energy::Bounded,
   "Standard Surface thin-walled transmission"},
  {"ss_coat_ior_1", "standard", R"(<input name="coat" type="float" value="1" /><input name="coat_IOR" type="float" value="1" />)", Energy::Bounded,
   "an index-matched coat"},
  {"fuzz_roughness_0", "openpbr", R"(<input name="fuzz_weight" type="float" value="1" /><input name="fuzz_roughness" type="float" value="0" />)", Energy::Bounded,
   "the fuzz LTC at its clamp r = 0.01: M^-1 has a = 8e-5 at grazing, a density peaking near 0.1 / a at the horizon (Zeltner et al. 2022)"},
  {"ss_sheen_roughness_0", "standard", R"(<input name="sheen" type="float" value="1" /><input name="sheen_roughness" type="float" value="0" />)", Energy::Bounded,
   "the sheen distribution's 1/r exponent at r = 0 (Estevez & Kulla 2017; r clamped to 0.01)"},
  {"ss_diffuse_roughness_1", "standard", R"(<input name="diffuse_roughness" type="float" value="1" /><input name="base_color" type="color3" value="1, 1, 1" /><input name="specular" type="float" value="0" />)", Energy::Bounded,
   "Oren-Nayar at full roughness loses energy without compensation (physics notes 2.1)"},
  {"usd_roughness_0_white", "usd", R"(<input name="roughness" type="float" value="0" /><input name="diffuseColor" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "UsdPreviewSurface: a mirror dielectric over a white Lambertian base (alpha = roughness^2 = 0: the delta lobe)"},
  {"usd_ior_1_glass", "usd", R"(<input name="ior" type="float" value="1" /><input name="opacity" type="float" value="0" />)", Energy::Bounded,
   "UsdPreviewSurface transparent mode at IOR 1: the interface vanishes, light passes straight through"},
  {"usd_metal_white_edge", "usd", R"(<input name="metallic" type="float" value="1" /><input name="diffuseColor" type="color3" value="1, 1, 1" /><input name="roughness" type="float" value="1" />)", Energy::Bounded,
   "UsdPreviewSurface metal of F0 = 1: Schlick is 1 at every angle, a rough GGX lobe loses energy but never gains"},
  {"usd_specular_workflow_coat", "usd", R"(<input name="useSpecularWorkflow" type="integer" value="1" /><input name="specularColor" type="color3" value="1, 1, 1" /><input name="clearcoat" type="float" value="1" /><input name="clearcoatRoughness" type="float" value="0" />)", Energy::Bounded,
   "UsdPreviewSurface specular workflow of F0 = 1 under a mirror coat of IOR 1.5"},
  {"gltf_metal_roughness_0_white", "gltf", R"(<input name="roughness" type="float" value="0" />)", Energy::Bounded,
   "glTF's default metal of F0 = 1 as a mirror (alpha = roughness^2 = 0): a delta lobe, no NaN"},
  {"gltf_everything", "gltf", R"(<input name="metallic" type="float" value="0" /><input name="transmission" type="float" value="1" /><input name="thickness" type="float" value="1" /><input name="clearcoat" type="float" value="1" /><input name="sheen_color" type="color3" value="1, 1, 1" /><input name="iridescence" type="float" value="1" /><input name="anisotropy_strength" type="float" value="1" /><input name="dispersion" type="float" value="1" />)", Energy::Bounded,
   "glTF with every extension at full strength: transmission through a dispersive volume, iridescence, sheen, coat, alpha_t = 1"},
  {"gltf_ior_1_specular_0", "gltf", R"(<input name="metallic" type="float" value="0" /><input name="ior" type="float" value="1" /><input name="specular" type="float" value="0" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "KHR_materials_ior at 1 and KHR_materials_specular at 0: no specular reflection over a white base"},
  {"disney_white", "disney", R"(<input name="baseColor" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "the default Disney material over a white base (Burley 2012): the specular layer over the diffuse gains nothing"},
  {"disney_saturated_tints", "disney", R"(<input name="baseColor" type="color3" value="0, 0, 1" /><input name="specular" type="float" value="1" /><input name="specularTint" type="float" value="1" /><input name="sheen" type="float" value="1" /><input name="sheenTint" type="float" value="1" />)", Energy::Bounded,
   "the hue of pure blue is (0, 0, 13.8) (baseColor / luminance): the tinted F0 and sheen colour are clamped to 1"},
  {"disney_everything_rough", "disney", R"(<input name="baseColor" type="color3" value="1, 1, 1" /><input name="metallic" type="float" value="0.5" /><input name="roughness" type="float" value="1" /><input name="anisotropic" type="float" value="1" /><input name="clearcoat" type="float" value="1" /><input name="clearcoatGloss" type="float" value="0" /><input name="subsurface" type="float" value="1" /><input name="specTrans" type="float" value="0.5" /><input name="sheen" type="float" value="1" />)", Energy::Bounded,
   "every lobe at once, the most stretched alpha (aspect sqrt(0.1)) and the roughest coat"},
  {"disney_glass_ior_1_smooth", "disney", R"(<input name="specTrans" type="float" value="1" /><input name="ior" type="float" value="1" /><input name="roughness" type="float" value="0" /><input name="baseColor" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "an index-matched smooth transmission: the interface passes everything straight through"},
  {"hair_white", "hair", "", Energy::Lossless,
   "no absorption, white tints: sum_p Ap = 1 and Mp, Np are normalised (Chiang 2016 eq. 3; d'Eon 2011 eq. 7)"},
  {"hair_roughness_0", "hair", R"(<input name="roughness_R" type="vector2" value="0, 0" /><input name="roughness_TT" type="vector2" value="0, 0" /><input name="roughness_TRT" type="vector2" value="0, 0" />)", Energy::Lossless,
   "the narrowest lobes (v = 1e-3: 1/v = 1000) stay finite: Mp is evaluated by its logarithm"},
  {"hair_ior_1", "hair", R"(<input name="ior" type="float" value="1" />)", Energy::Lossless,
   "an index-matched fibre reflects nothing: everything is TT (Fresnel 0; Chiang 2016 eq. 3)"},
  {"hair_extreme_tilt_absorbing", "hair", R"(<input name="cuticle_angle" type="float" value="0" /><input name="absorption_coefficient" type="vector3" value="0, 5, 1000" /><input name="ior" type="float" value="0.5" />)", Energy::Bounded,
   "a tilt of -90 degrees, an IOR below 1 (the modified IOR eta' floored) and an opaque blue channel"},
  {"hair_tint_above_1_along_normal", "hair", R"(<input name="tint_R" type="color3" value="4, 4, 4" /><input name="tint_TT" type="color3" value="2, 2, 2" /><input name="curve_direction" type="vector3" value="0, 0, 1" />)", Energy::Bounded,
   "tints are clamped to 1 (no gain); a fibre along the normal falls back to another tangent frame"},
  {"metal_specular_weight_2_white", "openpbr", R"(<input name="base_metalness" type="float" value="1" /><input name="base_color" type="color3" value="1, 1, 1" /><input name="specular_weight" type="float" value="2" /><input name="specular_roughness" type="float" value="0.3" />)", Energy::Bounded,
   "OpenPBR 'Metal': F = specular_weight F82; a weight of 2 on a white metal would reflect twice what arrives (the dielectric's weight above 1 modulates F0 instead)"},
  {"standard_base_color_3_coat_negative", "standard", R"(<input name="base_color" type="color3" value="3, 3, 3" /><input name="subsurface_color" type="color3" value="3, 3, 3" /><input name="coat" type="float" value="-1" /><input name="coat_affect_color" type="float" value="2" /><input name="thin_walled" type="boolean" value="true" /><input name="subsurface" type="float" value="0.5" />)", Energy::Bounded,
   "albedos above 1 (clamped: Standard Surface's base_color is a reflectivity) and a coat power 1 + 2 (-1) < 0, which would give pow(0, -1) = Inf"},
  {"gltf_specular_color_above_1", "gltf", R"(<input name="specular_color" type="color3" value="4, 2, 0" /><input name="metallic" type="float" value="0" /><input name="base_color" type="color3" value="1, 1, 1" />)", Energy::Bounded,
   "KHR_materials_specular: F0 = min(F0(ior) specular_color, 1); the colour's largest channel goes into the Fresnel scale, its hue into a tint <= 1"},
  {"dielectric_ior_1_rough_anisotropic_transmission", "bsdf", R"(<dielectric_bsdf name="t" type="BSDF"><input name="ior" type="float" value="1" /><input name="roughness" type="vector2" value="0.25, 1" /><input name="scatter_mode" type="string" value="RT" /></dielectric_bsdf><anisotropic_vdf name="v" type="VDF" /><layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="t" /><input name="base" type="VDF" nodename="v" /></layer>)", Energy::Lossless,
   "an index-matched interface refracts every microfacet's light straight on: the transmission is a delta at any roughness, R + T = 1 (Walter et al. 2007 eq. 16: the refraction half vector vanishes)"},
  {"thin_film_on_index_matched_rough_over_white", "bsdf", R"(<dielectric_bsdf name="t" type="BSDF"><input name="ior" type="float" value="1.02" /><input name="roughness" type="vector2" value="0.09, 0.09" /><input name="thinfilm_thickness" type="float" value="600" /><input name="thinfilm_ior" type="float" value="1.3" /></dielectric_bsdf><oren_nayar_diffuse_bsdf name="d" type="BSDF"><input name="color" type="color3" value="1, 1, 1" /></oren_nayar_diffuse_bsdf><layer name="b" type="BSDF"><input name="top" type="BSDF" nodename="t" /><input name="base" type="BSDF" nodename="d" /></layer>)", Energy::Bounded,
   "a film reflects where the nearly index-matched interface under it does not (F0 = 1e-4): the layer under it gets what the film does not reflect, no more"},
  {"lama_diffuse_white_rough", "bsdf", R"(<LamaDiffuse name="b" type="BSDF"><input name="color" type="color3" value="1, 1, 1" /><input name="roughness" type="float" value="1" /></LamaDiffuse>)", Energy::Lossless,
   "energyCompensation 1 is EON, lossless for a white albedo at any roughness (Portsmouth et al. 2025)"},
  {"lama_diffuse_half_compensated", "bsdf", R"(<LamaDiffuse name="b" type="BSDF"><input name="color" type="color3" value="1, 1, 1" /><input name="roughness" type="float" value="1" /><input name="energyCompensation" type="float" value="0.5" /></LamaDiffuse>)", Energy::Bounded,
   "a mix of Oren-Nayar (which loses energy when rough) and EON"},
  {"lama_iridescence_over_white", "bsdf", R"(<LamaIridescence name="i" type="BSDF"><input name="roughness" type="float" value="0.3" /></LamaIridescence><LamaDiffuse name="d" type="BSDF"><input name="color" type="color3" value="1, 1, 1" /></LamaDiffuse><LamaLayer name="b" type="BSDF"><input name="materialTop" type="BSDF" nodename="i" /><input name="materialBase" type="BSDF" nodename="d" /></LamaLayer>)", Energy::Bounded,
   "a film on an index-matched interface reflects (Airy) while the bare interface does not: the base gets what the film does not reflect, no more"},
  {"lama_iridescence_film_0_smooth", "bsdf", R"(<LamaIridescence name="b" type="BSDF"><input name="roughness" type="float" value="0" /><input name="minFilmThickness" type="float" value="0" /><input name="maxFilmThickness" type="float" value="0" /></LamaIridescence>)", Energy::Bounded,
   "no film on an index-matched smooth interface: everything passes straight through (IOR 1, roughness 0)"},
  {"lama_dielectric_reflectivity_extremes", "bsdf", R"(<LamaDielectric name="b" type="BSDF"><input name="reflectivity" type="float" value="1" /><input name="roughness" type="float" value="0" /><input name="anisotropy" type="float" value="-1" /><input name="absorptionColor" type="color3" value="0, 0, 0" /><input name="absorptionRadius" type="float" value="0" /><input name="scatterColor" type="color3" value="2, 2, 2" /></LamaDielectric>)", Energy::Bounded,
   "F0 = 1 (clamped to 0.99: n = 399), a mirror, an opaque interior of radius 0 and a scatter albedo above 1 (clamped)"},
  {"lama_dielectric_reflectivity_0", "bsdf", R"(<LamaDielectric name="b" type="BSDF"><input name="reflectivity" type="float" value="0" /><input name="roughness" type="float" value="0.5" /><input name="anisotropy" type="float" value="1" /></LamaDielectric>)", Energy::Bounded,
   "F0 = 0 is an IOR of 1 (index-matched) with the co-tangent roughness at 1"},
  {"lama_conductor_everything_above_1", "bsdf", R"(<LamaConductor name="b" type="BSDF"><input name="tint" type="color3" value="4, 4, 4" /><input name="reflectivity" type="color3" value="1.2, 1.2, 1.2" /><input name="edgeColor" type="color3" value="1.5, 1.5, 1.5" /><input name="roughness" type="float" value="0" /><input name="anisotropy" type="float" value="1" /></LamaConductor>)", Energy::Bounded,
   "tint clamped to 1, reflectivity to 0.99 and the edge colour to 1 (Gulbrandsen's n stays in its bounds), alpha (0, 1)"},
  {"lama_schlick_profile_0", "bsdf", R"(<LamaGeneralizedSchlick name="b" type="BSDF"><input name="reflectivityProfile" type="float" value="0" /><input name="reflectivity" type="color3" value="1, 0, 0.5" /><input name="reflectivity90" type="color3" value="2, 2, 2" /><input name="anisotropy" type="float" value="1" /><input name="roughness" type="float" value="0" /></LamaGeneralizedSchlick>)", Energy::Bounded,
   "exponent 1 / 0 (floored: 1000), F90 above 1 (clamped), an F0 of 1 in red"},
  {"lama_coated_white_thick_scattering_coat", "bsdf", R"(<LamaDielectric name="c" type="BSDF"><input name="absorptionColor" type="color3" value="0.5, 0.8, 1" /><input name="scatterColor" type="color3" value="0.9, 0.9, 0.9" /><input name="scatterAnisotropy" type="float" value="-1" /></LamaDielectric><LamaDiffuse name="d" type="BSDF"><input name="color" type="color3" value="1, 1, 1" /></LamaDiffuse><LamaLayer name="b" type="BSDF"><input name="materialTop" type="BSDF" nodename="c" /><input name="materialBase" type="BSDF" nodename="d" /><input name="topThickness" type="float" value="5" /><input name="topMix" type="float" value="0.7" /></LamaLayer>)", Energy::Bounded,
   "a scattering coating 5 units thick (g = -1 clamped to -0.99) over a white base, covering 70%"},
  {"lama_sss_radius_0_white", "bsdf", R"(<LamaSSS name="b" type="BSDF"><input name="color" type="color3" value="1, 1, 1" /></LamaSSS>)", Energy::Lossless,
   "radius 0 is a Lambertian reflection (the Lama definition): white is lossless"},
};
// clang-format on

std::string document(const HardCase& c) {
  if (std::string(c.model) == "document") return mtlx(c.inputs);
  if (std::string(c.model) == "hair") {
    return bsdfDocument(fmt::format("  <chiang_hair_bsdf name=\"bsdf\" type=\"BSDF\">{}</chiang_hair_bsdf>\n", c.inputs));
  }
  if (std::string(c.model) == "bsdf") return bsdfDocument(c.inputs, "b");
  const std::string model = c.model;
  const std::string node = model == "openpbr" ? "open_pbr_surface"
                           : model == "usd"   ? "UsdPreviewSurface"
                           : model == "gltf"  ? "gltf_pbr"
                           : model == "disney" ? "disney_principled"
                                              : "standard_surface";
  return mtlx(fmt::format("  <{0} name=\"s\" type=\"surfaceshader\">\n    {1}\n  </{0}>\n"
                          "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                          "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n",
                          node, c.inputs));
}

/// Direction pairs covering the sphere, with grazing and exactly tangent directions added.
std::vector<rt::DirectionPair> directionPairs(size_t count) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  auto direction = [&]() {
    for (;;) {
      glm::vec3 d(u(random), u(random), u(random));
      const float l = glm::length(d);
      if (l > 0.05f && l <= 1.0f) return d / l;
    }
  };
  std::vector<rt::DirectionPair> pairs;
  for (size_t i = 0; i < count; ++i) pairs.push_back({direction(), direction()});
  const glm::vec3 special[] = {{0, 0, 1}, {1, 0, 0}, {0, 0, -1}, {0.9999f, 0, 0.01414f}, {0.70710677f, 0.70710677f, 0}};
  for (glm::vec3 a : special) {
    for (glm::vec3 b : special) pairs.push_back({glm::normalize(a), glm::normalize(b)});
  }
  return pairs;
}

class HardCases : public ::testing::TestWithParam<std::tuple<HardCase, Accuracy>> {};

TEST_P(HardCases, StayFiniteAndBounded) {
  const HardCase& c = std::get<0>(GetParam());
  const Accuracy accuracy = std::get<1>(GetParam());
  SCOPED_TRACE(fmt::format("{} on {}: {}", c.name, accuracyName(accuracy), c.why));
  Context context;
  std::vector<ir::Material> materials = lowerText(context, document(c));
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  ASSERT_EQ(materials.size(), 1u);

  // The reference tier's estimate is one walk per pair: fewer pairs keep its run short. Walks
  // from below a smooth thin wall can be trapped by total internal reflection at both of its
  // faces, a lossless waveguide that only the walk's budget of events ends (mxc_walk.glsl).
  const std::vector<rt::DirectionPair> pairs = directionPairs(accuracy == Accuracy::Reference ? 1024 : 4096);
  std::vector<glm::vec4> values = evaluate(materials[0], pairs, accuracy);
  ASSERT_EQ(values.size(), pairs.size());
  size_t bad = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      if (!std::isfinite(values[i][k]) || values[i][k] < 0.0f) {
        if (++bad <= 5) {
          ADD_FAILURE() << "f cos or pdf = " << values[i][k] << " at wo (" << pairs[i].wo.x << ", " << pairs[i].wo.y << ", "
                        << pairs[i].wo.z << "), wi (" << pairs[i].wi.x << ", " << pairs[i].wi.y << ", " << pairs[i].wi.z
                        << ")";
        }
      }
    }
  }
  EXPECT_EQ(bad, 0u);

  const double degrees[] = {0, 30, 60, 80, 89, 89.9};
  std::vector<glm::vec3> views;
  for (double d : degrees) views.push_back(viewAt(d));
  // The reference tier draws one walk per invocation and dispatch (runtime/Evaluator.h): fewer
  // samples keep its run short; the bounds below allow for its larger standard errors.
  std::vector<rt::Albedo> albedo = furnace(materials[0], views, accuracy == Accuracy::Reference ? 2048 : 32768, {}, accuracy);
  ASSERT_EQ(albedo.size(), views.size());
  for (size_t k = 0; k < albedo.size(); ++k) {
    const glm::vec3 e = albedo[k].total();
    const glm::vec3 error = albedo[k].reflectedError + albedo[k].transmittedError;
    for (int ch = 0; ch < 3; ++ch) {
      ASSERT_TRUE(std::isfinite(e[ch])) << "albedo at " << degrees[k] << " degrees";
      EXPECT_GE(e[ch], 0.0f) << "albedo at " << degrees[k] << " degrees";
      // Energy: no gain beyond Monte Carlo error (4 standard errors) and the tables' accuracy.
      const float slack = 4.0f * error[ch] + 3e-3f;
      EXPECT_LE(e[ch], 1.0f + slack) << "energy gain at " << degrees[k] << " degrees";
      // Lossless cases are checked up to 80 degrees: beyond, the tables' first view step (mu
      // from 0 to 1/31) makes the albedo scaling approximate, and only the bound is checked.
      if (lossless(c.energy, accuracy) && degrees[k] <= 80.0) {
        EXPECT_GE(e[ch], 1.0f - slack) << "energy lost at " << degrees[k] << " degrees";
      }
      if (c.energy == Energy::LosslessHalfSpace && accuracy == Accuracy::Reference && degrees[k] <= 80.0) {
        EXPECT_GE(e[ch], 1.0f - kHalfSpaceLoss - slack) << "energy lost at " << degrees[k] << " degrees";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Stability, HardCases, ::testing::Combine(::testing::ValuesIn(kCases), ::testing::ValuesIn(kAccuracies)),
                         [](const ::testing::TestParamInfo<std::tuple<HardCase, Accuracy>>& param) {
                           std::string name = fmt::format("{}_{}", std::get<0>(param.param).name,
                                                          accuracyName(std::get<1>(param.param)));
                           for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return name;
                         });

}  // namespace
}  // namespace mxc::test

namespace mxc::test {
namespace {

/// The albedo of an OpenPBR material with `inputs` at a few views.
std::vector<rt::Albedo> openPbrAlbedo(const std::string& inputs, const std::vector<glm::vec3>& views) {
  Context context;
  HardCase c{"", "openpbr", inputs.c_str(), Energy::Bounded, ""};
  std::vector<ir::Material> materials = lowerText(context, document(c));
  EXPECT_EQ(materials.size(), 1u) << context.diagnostics.format();
  return materials.empty() ? std::vector<rt::Albedo>{} : furnace(materials[0], views, 65536);
}

// Continuity: the result at an extreme value is close to the result just inside it.
// (transmission_depth is discontinuous at 0 by the specification: 0 makes transmission_color a
// tint of the interface, any depth > 0 makes it the colour at that depth inside a medium.)
TEST(Continuity, ExtremesMatchTheirNeighbours) {
  struct Pair {
    const char* what;
    const char* extreme;
    const char* inside;
  };
  const Pair pairs[] = {
      {"specular_roughness 0 vs 1e-4", R"(<input name="specular_roughness" type="float" value="0" />)",
       R"(<input name="specular_roughness" type="float" value="1e-4" />)"},
      {"specular_ior 1 vs 1.001", R"(<input name="specular_ior" type="float" value="1" />)",
       R"(<input name="specular_ior" type="float" value="1.001" />)"},
      {"specular_roughness_anisotropy 1 vs 0.999",
       R"(<input name="specular_roughness_anisotropy" type="float" value="1" />)",
       R"(<input name="specular_roughness_anisotropy" type="float" value="0.999" />)"},
      {"coat_weight 0 vs 1e-4", R"(<input name="coat_weight" type="float" value="0" />)",
       R"(<input name="coat_weight" type="float" value="1e-4" />)"},
      {"thin_film_thickness 0 vs 1e-4",
       R"(<input name="thin_film_weight" type="float" value="1" /><input name="thin_film_thickness" type="float" value="0" />)",
       R"(<input name="thin_film_weight" type="float" value="1" /><input name="thin_film_thickness" type="float" value="1e-4" />)"},
  };
  const std::vector<glm::vec3> views{viewAt(0), viewAt(45), viewAt(80)};
  for (const Pair& p : pairs) {
    std::vector<rt::Albedo> a = openPbrAlbedo(p.extreme, views);
    std::vector<rt::Albedo> b = openPbrAlbedo(p.inside, views);
    ASSERT_EQ(a.size(), views.size());
    ASSERT_EQ(b.size(), views.size());
    for (size_t k = 0; k < views.size(); ++k) {
      const glm::vec3 error = a[k].reflectedError + a[k].transmittedError + b[k].reflectedError + b[k].transmittedError;
      for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(a[k].reflected[ch], b[k].reflected[ch], 4.0f * error[ch] + 5e-3f) << p.what << ", view " << k;
        EXPECT_NEAR(a[k].total()[ch], b[k].total()[ch], 4.0f * error[ch] + 5e-3f) << p.what << ", view " << k;
      }
    }
  }
}

// Helmholtz reciprocity (physics notes 2.4) of the single-lobe BSDFs that are reciprocal:
// f(o, i) = f(i, o), i.e. fcos(o, i) / cos_i = fcos(i, o) / cos_o.
TEST(Reciprocity, SingleLobesAreReciprocal) {
  const char* const bsdfs[] = {
      R"(<conductor_bsdf name="bsdf" type="BSDF"><input name="roughness" type="vector2" value="0.4, 0.05" /></conductor_bsdf>)",
      R"(<dielectric_bsdf name="bsdf" type="BSDF"><input name="roughness" type="vector2" value="0.2, 0.2" /></dielectric_bsdf>)",
      R"(<generalized_schlick_bsdf name="bsdf" type="BSDF"><input name="roughness" type="vector2" value="0.6, 0.6" /></generalized_schlick_bsdf>)",
      R"(<oren_nayar_diffuse_bsdf name="bsdf" type="BSDF"><input name="roughness" type="float" value="0.8" /></oren_nayar_diffuse_bsdf>)",
      R"(<oren_nayar_diffuse_bsdf name="bsdf" type="BSDF"><input name="roughness" type="float" value="0.8" /><input name="energy_compensation" type="boolean" value="true" /></oren_nayar_diffuse_bsdf>)",
      // Roughness 0.2: Burley's albedo stays under 1 (0.988 at most) from 3 to 90 degrees, where
      // the lobe is not rescaled by it (mxc_burley_albedo; rougher, the rescaling by E(wo) is
      // not reciprocal).
      R"(<burley_diffuse_bsdf name="bsdf" type="BSDF"><input name="roughness" type="float" value="0.2" /></burley_diffuse_bsdf>)",
  };
  std::mt19937 random(99);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  auto above = [&]() {
    const float z = 0.05f + 0.95f * u(random), phi = 6.2831853f * u(random), r = std::sqrt(1.0f - z * z);
    return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
  };
  std::vector<rt::DirectionPair> pairs;
  for (int k = 0; k < 256; ++k) {
    glm::vec3 o = above(), i = above();
    pairs.push_back({o, i});
    pairs.push_back({i, o});
  }
  for (const char* bsdf : bsdfs) {
    Context context;
    std::vector<ir::Material> materials = lowerText(context, bsdfDocument(std::string("  ") + bsdf + "\n"));
    ASSERT_EQ(materials.size(), 1u) << context.diagnostics.format();
    // The single-scattering lobes of the fast tier; balanced's multiple-scattering compensation
    // depends on wo alone and is not reciprocal (physics notes 2.4), its bound is checked above.
    std::vector<glm::vec4> f = evaluate(materials[0], pairs, Accuracy::Fast);
    ASSERT_EQ(f.size(), pairs.size());
    for (size_t k = 0; k < pairs.size(); k += 2) {
      for (int ch = 0; ch < 3; ++ch) {
        const float forward = f[k][ch] / pairs[k].wi.z;          // wi.z >= 0.05
        const float backward = f[k + 1][ch] / pairs[k + 1].wi.z;
        ASSERT_NEAR(forward, backward, 2e-4f * std::max(1.0f, forward)) << bsdf << ", pair " << k / 2;
      }
    }
  }
}

// A sample's weight f cos / pdf is what a renderer multiplies radiance by: at views near the
// horizon and just below it (a silhouette, where the interpolated normal turns away from the
// eye) it must stay bounded, on the tiers whose sampling is a closure's (the reference's is a
// walk, tested by reference_walk_test). Written after `mxc bench accuracy` found the car paint
// preset (coat roughness 0.02) rendering 4 silhouette pixels of about 2e12 in 1024 frames at
// 128x128, with wo.N about -0.1 to -0.2 and sample pdfs about 1e-6: the compute sampler does not
// reproduce it at those views (4M samples each), so the cause is in the raster stage's
// geometry, which is still open; this keeps the closure itself bounded there.
TEST(SampleWeights, StayBoundedAtTheHorizon) {
  const char* cases[] = {
      R"(<input name="base_color" type="color3" value="0.1, 0.6, 0.9" /><input name="specular_ior" type="float" value="1.6" /><input name="specular_roughness" type="float" value="0.3" /><input name="coat_weight" type="float" value="1" /><input name="coat_roughness" type="float" value="0.02" /><input name="coat_ior" type="float" value="1.6" />)",
  };
  std::vector<glm::vec3> views;
  for (float z : {0.2f, 0.05f, 1e-2f, 1e-3f, 1e-4f, 0.0f, -1e-4f, -1e-2f, -0.08f, -0.21f}) {
    views.push_back(glm::vec3(std::sqrt(1.0f - z * z), 0.0f, z));
  }
  for (const char* inputs : cases) {
    Context context;
    std::vector<ir::Material> materials = lowerText(context, openPbrDocument(inputs));
    ASSERT_EQ(materials.size(), 1u) << context.diagnostics.format();
    for (Accuracy tier : {Accuracy::Fast, Accuracy::Balanced}) {
      // 2^19 samples per view: the sampler's one output buffer (16 bytes a sample) must stay within
      // the device's maxStorageBufferRange (lavapipe: 128 MiB).
      // 2^19 samples per view: the sampler's one output buffer (16 bytes a sample, every view)
      // must stay within the device's maxStorageBufferRange (lavapipe: 128 MiB).
      std::vector<std::vector<rt::SampledDirection>> drawn = sampleDirections(materials[0], views, 1u << 19, 7, tier);
      ASSERT_EQ(drawn.size(), views.size());
      for (size_t v = 0; v < views.size(); ++v) {
        std::vector<rt::DirectionPair> pairs;
        for (const rt::SampledDirection& s : drawn[v]) {
          if (s.kind == rt::SampledDirection::Kind::Continuous) pairs.push_back({views[v], s.wi});
        }
        if (pairs.empty()) continue;  // a view exactly at the horizon draws nothing
        std::vector<glm::vec4> f = evaluate(materials[0], pairs, tier);
        float worst = 0.0f;
        size_t at = 0;
        for (size_t k = 0; k < f.size(); ++k) {
          const float w = f[k].w > 0.0f ? std::max({f[k].x, f[k].y, f[k].z}) / f[k].w : 0.0f;
          if (!(w <= worst)) worst = w, at = k;
        }
        // Luminance-weighted lobe choice lets one channel's weight pass 1 (blue base 0.9 under
        // the coat: 2.4 at the horizon); a weight far above it is a sample that gains energy.
        EXPECT_LE(worst, 4.0f) << accuracyName(tier) << ", wo.z " << views[v].z << ", wi (" << pairs[at].wi.x << ", "
                               << pairs[at].wi.y << ", " << pairs[at].wi.z << ")";
      }
    }
  }
}

}  // namespace
}  // namespace mxc::test
