#pragma once
/// \file
/// The raster renderer: a mesh (sphere, plane, OBJ) with a material's fragment shader, a
/// camera, directional and point lights, and an environment (white furnace, analytic sky or an
/// HDR image) integrated by Monte Carlo over frames. Frames are drawn depth first, then shaded with an
/// EQUAL depth test and added into an RGBA32F image; the result is their average.

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "compiler/glsl/Contract.h"
#include "runtime/Camera.h"
#include "runtime/Descriptors.h"
#include "runtime/EnvironmentMap.h"
#include "runtime/ImageIO.h"
#include "runtime/MaterialResources.h"
#include "runtime/Mesh.h"

namespace mxc::rt {

struct Light {
  enum class Kind : uint8_t { Directional, Point, Spot };
  Kind kind = Kind::Directional;
  glm::vec3 vector{0.0f, 1.0f, 0.0f};  ///< towards a directional light; a point or spot light's position
  glm::vec3 color{1.0f};               ///< times intensity: irradiance (directional) or W/sr (point, spot)
  float intensity = 1.0f;
  /// A spot light's cone: its axis (unit, from the light outwards); full intensity within
  /// cosInner of it, none beyond cosOuter, a smooth fade between (cosInner > cosOuter).
  glm::vec3 axis{0.0f, -1.0f, 0.0f};
  float cosOuter = 0.866f;
  float cosInner = 0.906f;
};

/// Map: RenderSettings::environmentMap, importance-sampled and combined with the closure's
/// samples by multiple importance sampling.
enum class Environment : uint8_t { None, White, Sky, Map };

/// The codes the shaders know these by (compiler/glsl/Contract.h): MxcView.counts.y and the
/// MXC_ENVIRONMENT constant; MxcView.lightVector[k].w and the bits of MXC_LIGHT_KINDS.
glsl::EnvironmentCode environmentCode(Environment environment);
glsl::LightCode lightCode(Light::Kind kind);

struct RenderSettings {
  uint32_t width = 512;
  uint32_t height = 512;
  uint32_t frames = 64;           ///< accumulated frames, each with its own sub-pixel jitter
  /// The index of the first frame: frames firstFrame .. firstFrame + frames - 1 are drawn, each
  /// with that index's jitter and random numbers, so renders of disjoint ranges are independent.
  uint32_t firstFrame = 0;
  uint32_t samplesPerFrame = 1;   ///< environment samples per pixel and frame
  Environment environment = Environment::Sky;
  float environmentIntensity = 1.0f;
  /// The image of Environment::Map (not owned; required for it, ignored otherwise).
  const EnvironmentMap* environmentMap = nullptr;
  /// The environment image's turn about +y, in degrees (counter-clockwise seen from above).
  float environmentRotation = 0.0f;
  float emissionScale = 1.0f;     ///< radiance per unit of the material's emission
  std::vector<Light> lights;
  /// Fix the environment, the number of lights and their kinds in each pipeline (the fragment
  /// stage's specialization constants, compiler/glsl/Contract.h); false: the shader reads them
  /// from its view block at run time, as a general shader does (`--no-specialize`).
  bool specialize = true;
  Camera camera;
  glm::mat4 objectToWorld{1.0f};
};

/// The fragment stage's specialization constants (SpecId, value) that a pipeline of `settings`
/// gets when `settings.specialize` (compiler/glsl/Contract.h): for a tool that folds them into a
/// module as the pipeline does (spirv::CompileOptions::specialization).
std::vector<std::pair<uint32_t, int32_t>> sceneSpecialization(const RenderSettings& settings);

struct RenderResult {
  RgbaImage image;      ///< average of the frames; alpha is the coverage
  double msPerFrame = 0.0;  ///< wall time per frame (draw, submit and wait), after the first
  /// Wall time of creating the render's pipelines (the device compiling its shaders), several
  /// at a time: with one material, its shading pipeline's compile time.
  double pipelineMs = 0.0;
};

/// One vertex attribute read from the mesh's Vertex (binding 0).
struct VertexInput {
  uint32_t location = 0;
  VkFormat format = VK_FORMAT_R32G32B32_SFLOAT;
  uint32_t offset = 0;  ///< into Vertex
};

/// What a frame's shaders need from the camera: the matrices, and this frame's sub-pixel
/// jitter, both alone (in normalised device units) and folded into worldToClip.
struct FrameView {
  glm::mat4 objectToWorld{1.0f};
  glm::mat4 normalToWorld{1.0f};
  glm::mat4 worldToView{1.0f};
  glm::mat4 viewToClip{1.0f};  ///< Vulkan clip space: depth 0..1, y down
  glm::mat4 worldToClip{1.0f};  ///< jitter * viewToClip * worldToView
  glm::vec2 jitter{0.0f};
  glm::vec3 eye{0.0f};
  uint32_t frame = 0;
};

/// The environment image of `settings` as the camera sees it behind the mesh: per pixel the
/// mean radiance over 2 x 2 sub-pixel rays (times the environment's intensity), alpha 1; the
/// pixels under what a render does not cover. Black unless the environment is an image.
RgbaImage renderBackground(const RenderSettings& settings);

/// One object of a scene: a mesh under a transform, shaded by a compiled material (not owned).
struct SceneObject {
  const Mesh* mesh = nullptr;
  glm::mat4 objectToWorld{1.0f};
  const MaterialResources* resources = nullptr;
  const glsl::MaterialInterface* material = nullptr;
  const std::vector<uint32_t>* fragmentSpirv = nullptr;  ///< glsl::ShaderKind::Raster
  /// The triangles drawn: indexCount indices from firstIndex (0: all of the mesh's).
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
};

/// One draw of a render: a mesh with a vertex and fragment shader pair and its descriptor sets
/// (bound as sets 0, 1, ...); `beforeFrame` updates the caller's uniforms for each frame.
struct DrawItem {
  const Mesh* mesh = nullptr;
  const std::vector<uint32_t>* vertexSpirv = nullptr;
  const std::vector<uint32_t>* fragmentSpirv = nullptr;
  std::vector<VertexInput> inputs;
  std::vector<const DescriptorSet*> sets;
  glm::mat4 objectToWorld{1.0f};
  std::function<void(const FrameView&)> beforeFrame;
  uint32_t firstIndex = 0;  ///< as SceneObject's
  uint32_t indexCount = 0;
};

class Renderer {
 public:
  Renderer(VulkanContext& context, const AlbedoTables& tables);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Renders `mesh` with a material's fragment shader (glsl::ShaderKind::Raster). `progress`,
  /// when given, is called after each frame with the number done; `beforeFrames` once the
  /// pipelines exist, before the first frame: a caller's last check (it may throw to stop the
  /// render), which runs after the pipelines' compilation rather than before it.
  RenderResult render(const Mesh& mesh, const MaterialResources& resources, const glsl::MaterialInterface& material,
                      const std::vector<uint32_t>& fragmentSpirv, const RenderSettings& settings,
                      const std::function<void(uint32_t)>& progress = {},
                      const std::function<void()>& beforeFrames = {});

  /// Renders several objects in one image: each frame draws every object's depth, then shades
  /// each where it is the nearest. The settings' objectToWorld is not used (each object has its
  /// own). Where two objects have exactly the same depth, both are shaded and added.
  RenderResult renderScene(const std::vector<SceneObject>& objects, const RenderSettings& settings,
                           const std::function<void(uint32_t)>& progress = {},
                           const std::function<void()>& beforeFrames = {});

  /// Renders each object alone, each in an image of its own, in order: render() of each, except
  /// that every pipeline is compiled before the first frame, several at a time (a document's
  /// materials, one image each). Each image goes to `finished` (with the object's index) as soon
  /// as it is done, so that only one is held at a time; `progress` is called after each frame
  /// with the object's index and the number of its frames done.
  void renderEach(const std::vector<SceneObject>& objects, const RenderSettings& settings,
                  const std::function<void(size_t, RenderResult&&)>& finished,
                  const std::function<void(size_t, uint32_t)>& progress = {},
                  const std::function<void()>& beforeFrames = {});

  /// Renders `mesh` with any vertex and fragment shader pair (for instance another generator's,
  /// whose resource interface the caller found by reflection): the same passes, accumulation
  /// and timing as render(). `sets` are bound as sets 0, 1, ...; `beforeFrame` updates the
  /// caller's uniforms for each frame.
  RenderResult draw(const Mesh& mesh, const std::vector<uint32_t>& vertexSpirv,
                    const std::vector<uint32_t>& fragmentSpirv, const std::vector<VertexInput>& inputs,
                    const std::vector<const DescriptorSet*>& sets, const RenderSettings& settings,
                    const std::function<void(const FrameView&)>& beforeFrame,
                    const std::function<void(uint32_t)>& progress = {});

 private:
  /// The passes, accumulation and timing of every render: one image per group of items (each
  /// group drawn alone, in order, and handed to `finished` when done), after every item's
  /// pipelines are created. `progress` gets the group's index and its frames done.
  void drawItems(const std::vector<DrawItem>& items, const std::vector<std::vector<size_t>>& groups,
                 const RenderSettings& settings, const std::function<void(size_t, RenderResult&&)>& finished,
                 const std::function<void(size_t, uint32_t)>& progress, const std::function<void()>& beforeFrames = {});
  /// The view blocks and sets of `objects`, then drawItems.
  void renderObjects(const std::vector<SceneObject>& objects, const std::vector<std::vector<size_t>>& groups,
                     const RenderSettings& settings, const std::function<void(size_t, RenderResult&&)>& finished,
                     const std::function<void(size_t, uint32_t)>& progress, const std::function<void()>& beforeFrames);

  VulkanContext& context_;
  const AlbedoTables& tables_;
  std::vector<uint32_t> vertexSpirv_;
  /// Bound as the environment set when the environment is not an image.
  std::unique_ptr<EnvironmentMap> black_;
};

}  // namespace mxc::rt
