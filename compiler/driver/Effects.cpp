#include "compiler/driver/Effects.h"

#include <algorithm>

#include <fmt/format.h>

namespace mxc {

namespace {

using ir::Effect;

/// The inputs of a shading model that switch an effect on: when the effect is dropped, their
/// values say why. The models' own specifications name them (OpenPBR 1.1 "Parameters";
/// Autodesk Standard Surface 1.0 "Parameters"; UsdPreviewSurface 2.6 "Preview Surface"; glTF 2.0
/// and its KHR material extensions).
struct EffectInputs {
  std::string_view shader;
  Effect effect;
  std::array<std::string_view, 3> inputs;
};

constexpr EffectInputs kEffectInputs[] = {
    {"open_pbr_surface", Effect::Diffuse, {"base_weight", "base_metalness", "transmission_weight"}},
    {"open_pbr_surface", Effect::Metal, {"base_metalness"}},
    {"open_pbr_surface", Effect::Specular, {"specular_weight", "base_metalness"}},
    {"open_pbr_surface", Effect::Anisotropy, {"specular_roughness_anisotropy", "coat_roughness_anisotropy"}},
    {"open_pbr_surface", Effect::Transmission, {"transmission_weight"}},
    {"open_pbr_surface", Effect::Volume, {"transmission_depth", "transmission_color", "transmission_scatter"}},
    {"open_pbr_surface", Effect::Dispersion, {"transmission_dispersion_scale", "transmission_dispersion_abbe_number"}},
    {"open_pbr_surface", Effect::Subsurface, {"subsurface_weight"}},
    {"open_pbr_surface", Effect::Coat, {"coat_weight"}},
    {"open_pbr_surface", Effect::Fuzz, {"fuzz_weight"}},
    {"open_pbr_surface", Effect::ThinFilm, {"thin_film_weight", "thin_film_thickness"}},
    {"open_pbr_surface", Effect::Emission, {"emission_luminance", "emission_color"}},
    {"open_pbr_surface", Effect::Opacity, {"geometry_opacity"}},
    {"open_pbr_surface", Effect::ThinWalled, {"geometry_thin_walled"}},
    {"standard_surface", Effect::Diffuse, {"base", "metalness", "transmission"}},
    {"standard_surface", Effect::Metal, {"metalness"}},
    {"standard_surface", Effect::Specular, {"specular", "metalness"}},
    {"standard_surface", Effect::Anisotropy, {"specular_anisotropy", "coat_anisotropy"}},
    {"standard_surface", Effect::Transmission, {"transmission"}},
    {"standard_surface", Effect::Volume, {"transmission_depth", "transmission_color", "transmission_scatter"}},
    {"standard_surface", Effect::Dispersion, {"transmission_dispersion"}},
    {"standard_surface", Effect::Subsurface, {"subsurface"}},
    {"standard_surface", Effect::Coat, {"coat"}},
    {"standard_surface", Effect::Sheen, {"sheen"}},
    {"standard_surface", Effect::ThinFilm, {"thin_film_thickness"}},
    {"standard_surface", Effect::Emission, {"emission", "emission_color"}},
    {"standard_surface", Effect::Opacity, {"opacity"}},
    {"standard_surface", Effect::ThinWalled, {"thin_walled"}},
    {"UsdPreviewSurface", Effect::Diffuse, {"metallic", "useSpecularWorkflow", "opacity"}},
    {"UsdPreviewSurface", Effect::Metal, {"metallic", "useSpecularWorkflow"}},
    {"UsdPreviewSurface", Effect::Specular, {"metallic", "useSpecularWorkflow"}},
    {"UsdPreviewSurface", Effect::Transmission, {"opacity", "opacityMode", "opacityThreshold"}},
    {"UsdPreviewSurface", Effect::Coat, {"clearcoat"}},
    {"UsdPreviewSurface", Effect::Emission, {"emissiveColor"}},
    {"UsdPreviewSurface", Effect::Opacity, {"opacity", "opacityMode", "opacityThreshold"}},
    {"gltf_pbr", Effect::Diffuse, {"metallic", "transmission"}},
    {"gltf_pbr", Effect::Metal, {"metallic"}},
    {"gltf_pbr", Effect::Specular, {"specular", "metallic"}},
    {"gltf_pbr", Effect::Anisotropy, {"anisotropy_strength"}},
    {"gltf_pbr", Effect::Transmission, {"transmission"}},
    {"gltf_pbr", Effect::Volume, {"thickness", "attenuation_distance", "attenuation_color"}},
    {"gltf_pbr", Effect::Dispersion, {"dispersion"}},
    {"gltf_pbr", Effect::Coat, {"clearcoat"}},
    {"gltf_pbr", Effect::Sheen, {"sheen_color"}},
    {"gltf_pbr", Effect::ThinFilm, {"iridescence"}},
    {"disney_principled", Effect::Diffuse, {"metallic", "specTrans"}},
    {"disney_principled", Effect::Metal, {"metallic"}},
    {"disney_principled", Effect::Specular, {"specular", "metallic"}},
    {"disney_principled", Effect::Anisotropy, {"anisotropic"}},
    {"disney_principled", Effect::Transmission, {"specTrans"}},
    {"disney_principled", Effect::Subsurface, {"subsurface"}},
    {"disney_principled", Effect::Sheen, {"sheen"}},
    {"disney_principled", Effect::Coat, {"clearcoat"}},
    {"gltf_pbr", Effect::Emission, {"emissive", "emissive_strength"}},
    {"gltf_pbr", Effect::Opacity, {"alpha_mode", "alpha"}},
    {"gltf_pbr", Effect::ThinWalled, {"thickness"}},
};

const EffectInputs* effectInputs(std::string_view shader, Effect effect) {
  for (const EffectInputs& e : kEffectInputs) {
    if (e.shader == shader && e.effect == effect) return &e;
  }
  return nullptr;
}

/// "line 12" in the material's document, else "file:12" (a nodedef's default).
std::string where(SourceLocation at, const SourceFile* document) {
  if (!at.valid()) return {};
  if (at.file == document) return fmt::format("line {}", at.line());
  return fmt::format("{}:{}", at.file->path(), at.line());
}

/// An input with its value and whence: "coat_weight = 0 (default)", "base_color is a parameter
/// (0 to 1)".
std::string describe(const ir::ShaderInput& in) {
  using Source = ir::ShaderInput::Source;
  switch (in.source) {
    case Source::Document: return fmt::format("{} = {}", in.name, in.value);
    case Source::Default: return fmt::format("{} = {} (its default)", in.name, in.value);
    case Source::Override: return fmt::format("{} = {} (--set)", in.name, in.value);
    case Source::Parameter:
      return in.range.empty() ? fmt::format("{} is a parameter", in.name)
                              : fmt::format("{} is a parameter (UI range {})", in.name, in.range);
    case Source::Connected: return fmt::format("{} is connected", in.name);
  }
  return std::string(in.name);
}

/// Why an effect the IR keeps is kept: the input its features name.
EffectChoice kept(const ir::Material& m, Effect effect, std::string how) {
  EffectChoice c{std::string(ir::effectName(effect)), true, std::move(how), {}, {}};
  const ir::Origin& origin = m.features.origin(effect);
  const ir::ShaderInput* in = origin.input.empty() ? nullptr : m.shaderInput(origin.input);
  c.reason = in ? describe(*in) : origin.input.empty() ? "the graph has it" : fmt::format("{}", origin.input);
  c.at = in ? in->location : origin.location;
  return c;
}

/// Why an effect is not there: the model's inputs that would switch it on, with their values;
/// `otherwise` when the model names none.
EffectChoice dropped(const ir::Material& m, Effect effect, std::string how,
                     std::string otherwise = "no node of the material produces it") {
  EffectChoice c{std::string(ir::effectName(effect)), false, std::move(how), {}, {}};
  if (const EffectInputs* inputs = effectInputs(m.shader, effect)) {
    for (std::string_view name : inputs->inputs) {
      if (name.empty()) continue;
      const ir::ShaderInput* in = m.shaderInput(name);
      if (!in) continue;
      c.reason += (c.reason.empty() ? "" : ", ") + describe(*in);
      if (!c.at.valid()) c.at = in->location;
    }
  }
  if (c.reason.empty()) c.reason = std::move(otherwise);
  return c;
}

std::string lightList(const SceneFacts& scene) {
  static constexpr std::array<std::string_view, 3> kNames = {"directional", "point", "spot"};
  std::string out;
  for (size_t k = 0; k < kNames.size(); ++k) {
    if (scene.lights[k] == 0) continue;
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", scene.lights[k], kNames[k]);
  }
  return out;
}

std::string environmentName(const SceneFacts& scene) {
  switch (scene.environment) {
    case glsl::EnvironmentCode::None: return "no environment";
    case glsl::EnvironmentCode::White: return "the white furnace";
    case glsl::EnvironmentCode::Sky: return "the analytic sky";
    case glsl::EnvironmentCode::Map: return fmt::format("the image {}", scene.environmentImage);
  }
  return "?";
}

}  // namespace

SceneFacts SceneFacts::renderDefault() {
  SceneFacts s;
  s.description = "the default of `mxc render`: the analytic sky and one directional light";
  s.environment = glsl::EnvironmentCode::Sky;
  s.lights[static_cast<size_t>(glsl::LightCode::Directional)] = 1;
  return s;
}

std::vector<EffectChoice> materialEffects(const ir::Material& m, const glsl::MaterialInterface& shader,
                                          const SceneFacts& scene, Accuracy accuracy) {
  std::vector<EffectChoice> out;
  // The material's effects, as the passes left them: a dropped one has no lobe, medium or code.
  const bool model = effectInputs(m.shader, Effect::Coat) != nullptr;
  for (size_t e = 0; e < static_cast<size_t>(Effect::Count); ++e) {
    const Effect effect = static_cast<Effect>(e);
    if (m.features.effects.has(effect)) {
      out.push_back(kept(m, effect, "material"));
    } else if (model && effectInputs(m.shader, effect)) {
      out.push_back(dropped(m, effect, "material"));
    }
  }

  // What the scene decides: fixed in the pipeline (specialization constants), or read at run time.
  const std::string constant = scene.specialize ? "specialization constant" : "run time (--no-specialize)";
  const bool environment = scene.environment != glsl::EnvironmentCode::None;
  out.push_back({"environment lighting", environment, constant,
                 environment ? fmt::format("scene: {}; the closure's sampling compiled", environmentName(scene))
                             : "scene: no environment; no closure sampling, no environment lookups",
                 {}});
  const bool image = scene.environment == glsl::EnvironmentCode::Map;
  out.push_back({"environment image sampling", image, constant,
                 image ? fmt::format("scene: {} (importance-sampled, with multiple importance sampling)",
                                     environmentName(scene))
                       : fmt::format("scene: {}", environmentName(scene)),
                 {}});
  const int lights = scene.lightCount();
  out.push_back({"analytic lights", lights > 0, constant,
                 lights > 0 ? fmt::format("scene: {} light(s): {} (the count is compiled in)", lights, lightList(scene))
                            : "scene: no lights",
                 {}});
  const int positioned = scene.lights[static_cast<size_t>(glsl::LightCode::Point)] +
                         scene.lights[static_cast<size_t>(glsl::LightCode::Spot)];
  out.push_back({"point and spot light code", positioned > 0, constant,
                 positioned > 0 ? fmt::format("scene: {}", lightList(scene))
                                : lights > 0 ? "scene: directional lights only" : "scene: no lights",
                 {}});

  // What the material's closure decides in the shader library (compile time): the effect that
  // needs the code names its input; the general shader and the reference tier always compile it.
  auto libraryCode = [&](std::string name, std::string_view guard, bool compiled, Effect effect, std::string otherwise,
                         std::string_view reference) {
    EffectChoice c =
        m.features.effects.has(effect) ? kept(m, effect, "") : dropped(m, effect, "", std::move(otherwise));
    c.name = std::move(name);
    c.how = fmt::format("compile time ({})", guard);
    c.kept = compiled;
    if (!scene.specialize) c.reason = "the general shader (--no-specialize) compiles it";
    if (accuracy == Accuracy::Reference) c.reason = std::string(reference);
    return c;
  };
  const bool always = !scene.specialize || accuracy == Accuracy::Reference;
  EffectChoice refraction = libraryCode("refraction code", "MXC_TRANSMISSION", shader.transmission, Effect::Transmission,
                                        "no lobe transmits", "the reference tier's walk refracts through every interface");
  if (refraction.kept && !always && !m.features.effects.has(Effect::Transmission)) refraction.reason = "a lobe transmits";
  out.push_back(std::move(refraction));
  EffectChoice absorption = libraryCode("absorption above lobes", "MXC_ABSORPTION", shader.absorption, Effect::Coat,
                                        "no lobe lies under an absorbing medium",
                                        "the reference tier's walk crosses every medium");
  if (!absorption.kept && m.features.effects.has(Effect::Coat)) {
    absorption.reason = "the coat does not absorb (coat colour white)";
  }
  out.push_back(std::move(absorption));
  out.push_back({"albedo tables", accuracy != Accuracy::Fast, "compile time (the tier)",
                 accuracy == Accuracy::Fast ? "the fast tier uses fitted albedos: no table is read"
                                            : fmt::format("the {} tier reads tabulated albedos", accuracyName(accuracy)),
                 {}});
  return out;
}

std::string effectsText(const std::vector<MaterialEffects>& materials, const SceneFacts& scene) {
  std::string out = fmt::format("scene: {}\n", scene.description);
  for (const MaterialEffects& me : materials) {
    const ir::Material& m = *me.material;
    const SourceFile* document = m.origin.location.file;
    out += fmt::format("\nmaterial {} ({}, {})\n", m.name, m.shader, where(m.origin.location, document));
    size_t width = 0;
    for (const EffectChoice& c : me.effects) width = std::max(width, c.name.size());
    for (const EffectChoice& c : me.effects) {
      const std::string at = where(c.at, document);
      out += fmt::format("  {:<7} {:<{}}  {}{}  [{}]\n", c.kept ? "kept" : "dropped", c.name, width, c.reason,
                         at.empty() ? "" : fmt::format(" ({})", at), c.how);
    }
  }
  return out;
}

nlohmann::json effectsJson(const std::vector<MaterialEffects>& materials, const SceneFacts& scene) {
  nlohmann::json j{{"schema", "mxc-effects-1"}, {"scene", scene.description}, {"materials", nlohmann::json::array()}};
  for (const MaterialEffects& me : materials) {
    const ir::Material& m = *me.material;
    nlohmann::json effects = nlohmann::json::array();
    for (const EffectChoice& c : me.effects) {
      nlohmann::json e{{"effect", c.name}, {"kept", c.kept}, {"how", c.how}, {"reason", c.reason}};
      if (c.at.valid()) e["location"] = {{"file", c.at.file->path()}, {"line", c.at.line()}};
      effects.push_back(std::move(e));
    }
    j["materials"].push_back({{"name", m.name}, {"shader", m.shader}, {"effects", std::move(effects)}});
  }
  return j;
}

}  // namespace mxc
