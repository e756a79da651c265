#pragma once
/// \file
/// What a material's shader simulates under a scene, and why: each effect of the material
/// (coat, fuzz, transmission, ...) and each piece of code the scene decides (environment
/// sampling, the lights, refraction, absorption, the albedo tables) kept or dropped, with the
/// input value or the scene fact behind the choice (`mxc inspect --effects`, docs/specialization.md).
///
/// It reads the decisions the stages made (the IR's features after the passes, the shader's
/// interface from the back end) and the scene; it decides nothing itself, so the report cannot
/// disagree with the shader.

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compiler/common/Accuracy.h"
#include "compiler/common/SourceFile.h"
#include "compiler/glsl/Contract.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/ir/Material.h"

namespace mxc {

/// What a scene puts around a material, as far as its shader depends on it.
struct SceneFacts {
  /// Says which scene: "the default of `mxc render`", "scene examples/scenes/still_life.json".
  std::string description;
  glsl::EnvironmentCode environment = glsl::EnvironmentCode::Sky;
  std::string environmentImage;  ///< the image of EnvironmentCode::Map
  /// Lights of each kind, indexed by glsl::LightCode.
  std::array<int, 3> lights{};
  /// Whether pipelines fix the scene (false: `--no-specialize`, read at run time).
  bool specialize = true;

  int lightCount() const { return lights[0] + lights[1] + lights[2]; }
  /// The scene `mxc render DOC` uses without options: the analytic sky and one directional light.
  static SceneFacts renderDefault();
};

/// One effect, kept or dropped.
struct EffectChoice {
  std::string name;     ///< "coat", "environment sampling", ...
  bool kept = false;
  /// How the choice is made: "material" (the IR's passes), "compile time" (a library guard),
  /// "specialization constant" (fixed when the pipeline is created).
  std::string how;
  std::string reason;   ///< the input and its value, or the scene fact
  SourceLocation at;    ///< the input's element, when the reason is one
};

/// The effects of `material`, whose shader of the raster stage has interface `shader`, under
/// `scene`, at tier `accuracy`.
std::vector<EffectChoice> materialEffects(const ir::Material& material, const glsl::MaterialInterface& shader,
                                          const SceneFacts& scene, Accuracy accuracy);

/// The report of `inspect --effects`: per material its effects, as text or JSON (schema
/// mxc-effects-1, docs/specialization.md). Locations in the material's own document are "line N",
/// others (a nodedef's default) "file:line".
struct MaterialEffects {
  const ir::Material* material = nullptr;
  std::vector<EffectChoice> effects;
};
std::string effectsText(const std::vector<MaterialEffects>& materials, const SceneFacts& scene);
nlohmann::json effectsJson(const std::vector<MaterialEffects>& materials, const SceneFacts& scene);

}  // namespace mxc
