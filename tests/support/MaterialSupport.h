#pragma once
// Helpers for tests that run materials: lower a document to IR materials (after the passes),
// and evaluate them on the shared Vulkan device (validation on).

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "compiler/driver/Compiler.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "runtime/Evaluator.h"
#include "support/TestSupport.h"

namespace mxc::test {

/// The materials of a document, compiled to the IR (passes run, features computed) by the
/// compiler. Lowered even when the context already holds errors (the request is partial), so a
/// test can look at what a document with errors lowers to.
inline std::vector<ir::Material> lowerRequest(Context& context, CompileRequest request) {
  request.partial = true;
  Compiler compiler(context, std::move(request));
  return std::move(compiler.materials());
}

inline std::vector<ir::Material> lowerText(Context& context, const std::string& text,
                                           const lower::LoweringOptions& options = {}) {
  CompileRequest request;
  request.document = "test.mtlx";
  request.text = text;
  request.lowering = options;
  return lowerRequest(context, std::move(request));
}

inline std::vector<ir::Material> lowerFile(Context& context, const std::filesystem::path& path,
                                           const lower::LoweringOptions& options = {}) {
  CompileRequest request;
  request.document = path;
  request.lowering = options;
  return lowerRequest(context, std::move(request));
}

/// `--set` overrides as lowering options.
inline lower::LoweringOptions withInputs(std::vector<std::pair<std::string, std::string>> overrides) {
  lower::LoweringOptions options;
  options.overrides = std::move(overrides);
  return options;
}

/// One Vulkan device and its albedo tables for the whole test program, validation on.
struct Device {
  static Device& get() {
    static Device device;
    created() = true;
    return device;
  }
  static bool& created() {
    static bool value = false;
    return value;
  }
  rt::VulkanContext context{rt::DeviceOptions{"", true}};
  rt::AlbedoTables tables{context};
};

/// Fails the test program when the validation layer said anything while it ran.
class ValidationEnvironment : public ::testing::Environment {
 public:
  void TearDown() override {
    if (!Device::created()) return;
    for (const std::string& m : Device::get().context.validationMessages()) ADD_FAILURE() << "validation: " << m;
  }
};
inline ::testing::Environment* const kValidationEnvironment =
    ::testing::AddGlobalTestEnvironment(new ValidationEnvironment);

/// Compiles a material's shader; fails the test when it does not compile.
inline std::vector<uint32_t> compiledWords(const glsl::MaterialShader& shader) {
  Diagnostics diagnostics;
  auto words = compileShader(shader, {}, diagnostics);
  EXPECT_TRUE(words.has_value()) << diagnostics.format();
  return words.value_or(std::vector<uint32_t>{});
}

/// A material's shader of one kind, compiled, with its resources on the shared device.
struct Prepared {
  glsl::MaterialShader shader;
  std::vector<uint32_t> words;
  std::unique_ptr<rt::MaterialResources> resources;
  bool ok() const { return !words.empty(); }
};

inline Prepared prepare(const ir::Material& material, glsl::ShaderKind kind, const std::filesystem::path& folder = {},
                        Accuracy accuracy = Accuracy::Balanced) {
  Prepared p;
  CompileRequest request;
  request.accuracy = accuracy;
  p.shader = buildShader(material, kind, request);
  p.words = compiledWords(p.shader);
  Diagnostics diagnostics;
  if (p.ok()) p.resources = std::make_unique<rt::MaterialResources>(Device::get().context, p.shader.interface, folder, diagnostics);
  EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.format();
  return p;
}

/// The directional albedo of a material at the given view directions.
inline std::vector<rt::Albedo> furnace(const ir::Material& material, const std::vector<glm::vec3>& views,
                                       uint32_t samples, const std::filesystem::path& folder = {},
                                       Accuracy accuracy = Accuracy::Balanced) {
  Prepared p = prepare(material, glsl::ShaderKind::Furnace, folder, accuracy);
  if (!p.ok()) return {};
  rt::FurnaceEstimator estimator(Device::get().context, Device::get().tables, *p.resources, p.shader.interface, p.words);
  return estimator.estimate(views, samples, 7);
}

/// Directions drawn by the material's closure sampling at each view.
inline std::vector<std::vector<rt::SampledDirection>> sampleDirections(const ir::Material& material,
                                                                      const std::vector<glm::vec3>& views,
                                                                      uint32_t samples, uint32_t seed = 7,
                                                                      Accuracy accuracy = Accuracy::Balanced) {
  Prepared p = prepare(material, glsl::ShaderKind::Sample, {}, accuracy);
  if (!p.ok()) return {};
  rt::DirectionSampler sampler(Device::get().context, Device::get().tables, *p.resources, p.shader.interface, p.words);
  return sampler.sample(views, samples, seed);
}

/// f(wo, wi) |cos| and the pdf for direction pairs.
/// `dispatches` > 1 averages that many (the reference tier's estimate is random).
inline std::vector<glm::vec4> evaluate(const ir::Material& material, const std::vector<rt::DirectionPair>& pairs,
                                       Accuracy accuracy = Accuracy::Balanced, uint32_t dispatches = 1) {
  Prepared p = prepare(material, glsl::ShaderKind::Eval, {}, accuracy);
  if (!p.ok()) return {};
  rt::MaterialEvaluator evaluator(Device::get().context, Device::get().tables, *p.resources, p.shader.interface, p.words);
  return evaluator.evaluate(pairs, dispatches);
}

/// A view direction at `degrees` from the normal, in the xz plane.
inline glm::vec3 viewAt(double degrees) {
  const double t = degrees * 3.14159265358979 / 180.0;
  return glm::vec3(static_cast<float>(std::sin(t)), 0.0f, static_cast<float>(std::cos(t)));
}

/// A document with one BSDF node (given as XML) as its material's surface.
inline std::string bsdfDocument(const std::string& bsdf, const std::string& name = "bsdf") {
  return mtlx(bsdf + "  <surface name=\"surf\" type=\"surfaceshader\"><input name=\"bsdf\" type=\"BSDF\" nodename=\"" +
              name +
              "\" /></surface>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
              "type=\"surfaceshader\" nodename=\"surf\" /></surfacematerial>\n");
}

}  // namespace mxc::test

#include "runtime/Renderer.h"

namespace mxc::test {

/// Renders a material on the default sphere with the shared device.
/// The material on `mesh` (the unit sphere when null).
inline rt::RgbaImage render(const ir::Material& material, const rt::RenderSettings& settings,
                            const std::filesystem::path& folder = {}, Accuracy accuracy = Accuracy::Balanced,
                            const rt::Mesh* mesh = nullptr) {
  Prepared p = prepare(material, glsl::ShaderKind::Raster, folder, accuracy);
  if (!p.ok()) return {};
  static std::unique_ptr<rt::Renderer> renderer;  // its vertex shader is compiled once
  if (!renderer) renderer = std::make_unique<rt::Renderer>(Device::get().context, Device::get().tables);
  static const rt::Mesh sphere = rt::makeSphere();
  return renderer->render(mesh ? *mesh : sphere, *p.resources, p.shader.interface, p.words, settings).image;
}

}  // namespace mxc::test
