#include "runtime/Renderer.h"

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "compiler/common/Parallel.h"
#include "compiler/glsl/Contract.h"
#include "runtime/DescriptorLimits.h"
#include "runtime/Descriptors.h"

namespace mxc::rt {

/// The environment's code in MxcView.counts.y (compiler/glsl/Contract.h).
glsl::EnvironmentCode environmentCode(Environment e) {
  switch (e) {
    case Environment::None: return glsl::EnvironmentCode::None;
    case Environment::White: return glsl::EnvironmentCode::White;
    case Environment::Sky: return glsl::EnvironmentCode::Sky;
    case Environment::Map: return glsl::EnvironmentCode::Map;
  }
  return glsl::EnvironmentCode::None;
}

/// A light's kind in MxcView.lightVector[k].w (compiler/glsl/Contract.h).
glsl::LightCode lightCode(Light::Kind kind) {
  switch (kind) {
    case Light::Kind::Directional: return glsl::LightCode::Directional;
    case Light::Kind::Point: return glsl::LightCode::Point;
    case Light::Kind::Spot: return glsl::LightCode::Spot;
  }
  return glsl::LightCode::Directional;
}

namespace {

static_assert(sizeof(Vertex) == 48, "Vertex must be tightly packed for the vertex input layout");

/// The values of the fragment stage's specialization constants for a render's settings
/// (compiler/glsl/Contract.h), in the order of their ids.
struct SceneConstants {
  int32_t environment = 0;
  int32_t lightCount = 0;
  int32_t lightKinds = 0;
};
SceneConstants sceneConstants(const RenderSettings& s) {
  SceneConstants c;
  c.environment = static_cast<int32_t>(environmentCode(s.environment));
  c.lightCount = static_cast<int32_t>(std::min<size_t>(s.lights.size(), glsl::kMaxLights));
  for (int32_t k = 0; k < c.lightCount; ++k) c.lightKinds |= 1 << static_cast<int32_t>(lightCode(s.lights[k].kind));
  return c;
}

/// The radical inverse in base b (Halton 1964): well-spread sub-pixel offsets over frames.
float halton(uint32_t index, uint32_t base) {
  float f = 1.0f, r = 0.0f;
  for (; index > 0; index /= base) {
    f /= static_cast<float>(base);
    r += f * static_cast<float>(index % base);
  }
  return r;
}

/// The Vulkan objects of one draw item: its mesh's buffers, its layout and both pipelines.
struct ItemObjects {
  Buffer vertices, indices;
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline depthPipeline = VK_NULL_HANDLE;
  VkPipeline shadePipeline = VK_NULL_HANDLE;
  bool ownsDepth = false, ownsShade = false;  ///< created for this item (else another item's, shared)
  bool ownsBuffers = false;                   ///< the mesh's buffers were made for this item (else shared)
  std::vector<VkDescriptorSet> descriptorSets;
};

/// Whether two draw items build the same pipeline: the same shaders (the fragment shader only
/// when `shading`), vertex inputs and descriptor set layouts. Identically defined set layouts make
/// pipeline layouts compatible (Vulkan 1.3, s. 14.2.2), so one pipeline serves both: a document
/// or scene whose materials compile to one shader (the general shader, `--no-specialize`, of
/// every material of a shading model whose inputs are values) creates it once, and every item
/// shares one depth pipeline.
bool samePipeline(const DrawItem& a, const DrawItem& b, bool shading) {
  auto sameWords = [](const std::vector<uint32_t>* x, const std::vector<uint32_t>* y) {
    return x == y || (x && y && *x == *y);
  };
  if (!sameWords(a.vertexSpirv, b.vertexSpirv) || (shading && !sameWords(a.fragmentSpirv, b.fragmentSpirv))) return false;
  if (a.inputs.size() != b.inputs.size() || a.sets.size() != b.sets.size()) return false;
  for (size_t k = 0; k < a.inputs.size(); ++k) {
    const VertexInput &x = a.inputs[k], &y = b.inputs[k];
    if (x.location != y.location || x.format != y.format || x.offset != y.offset) return false;
  }
  for (size_t k = 0; k < a.sets.size(); ++k) {
    if (a.sets[k] != b.sets[k] && (a.sets[k]->types() != b.sets[k]->types() || a.sets[k]->stages() != b.sets[k]->stages())) {
      return false;
    }
  }
  return true;
}

/// A hash of what samePipeline compares (the shaders' words, vertex inputs and set layouts):
/// items are compared only with those of the same hash, so finding each item's pipeline owner
/// takes time linear in the items, not quadratic (10,000 objects of one material). `words`
/// remembers each SPIR-V vector's hash: the items of a scene share a few.
size_t pipelineHash(const DrawItem& item, bool shading, std::unordered_map<const std::vector<uint32_t>*, size_t>& words) {
  auto mix = [](size_t h, size_t v) { return h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)); };
  auto spirvHash = [&](const std::vector<uint32_t>* code) -> size_t {
    if (!code) return 0;
    auto [at, added] = words.try_emplace(code, 0);
    if (added) {
      at->second = std::hash<std::string_view>{}(
          std::string_view(reinterpret_cast<const char*>(code->data()), code->size() * sizeof(uint32_t)));
    }
    return at->second;
  };
  size_t h = mix(spirvHash(item.vertexSpirv), shading ? spirvHash(item.fragmentSpirv) : 0);
  for (const VertexInput& in : item.inputs) h = mix(mix(mix(h, in.location), size_t(in.format)), in.offset);
  for (const DescriptorSet* set : item.sets) {
    h = mix(h, set->stages());
    for (VkDescriptorType type : set->types()) h = mix(h, size_t(type));
  }
  return h;
}

/// Vulkan objects of one render, destroyed together.
struct Frame {
  VulkanContext& context;
  Image color, depth;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  std::vector<ItemObjects> items;
  explicit Frame(VulkanContext& c) : context(c) {}
  ~Frame() {
    VkDevice d = context.device();
    vkDeviceWaitIdle(d);
    for (ItemObjects& item : items) {
      if (item.shadePipeline && item.ownsShade) vkDestroyPipeline(d, item.shadePipeline, nullptr);
      if (item.depthPipeline && item.ownsDepth) vkDestroyPipeline(d, item.depthPipeline, nullptr);
      if (item.layout) vkDestroyPipelineLayout(d, item.layout, nullptr);
      if (item.ownsBuffers) {
        for (Buffer* b : {&item.vertices, &item.indices}) context.destroy(*b);
      }
    }
    if (framebuffer) vkDestroyFramebuffer(d, framebuffer, nullptr);
    if (renderPass) vkDestroyRenderPass(d, renderPass, nullptr);
    context.destroy(color);
    context.destroy(depth);
  }
};

VkRenderPass createRenderPass(VkDevice device) {
  VkAttachmentDescription attachments[2]{};
  attachments[0].format = VK_FORMAT_R32G32B32A32_SFLOAT;
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // frames accumulate
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[0].initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachments[1].format = VK_FORMAT_D32_SFLOAT;
  attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colorRef;
  subpass.pDepthStencilAttachment = &depthRef;
  // The previous frame's blending and depth writes complete before this frame's.
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
  dependency.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                             VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 2;
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &dependency;
  VkRenderPass pass = VK_NULL_HANDLE;
  check(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
  return pass;
}

/// The depth pre-pass (no fragment shader, no colour writes) or the shading pass (EQUAL depth,
/// additive blending).
VkPipeline createPipeline(VkDevice device, VkRenderPass pass, VkPipelineLayout layout, VkShaderModule vertex,
                          VkShaderModule fragment, const VkSpecializationInfo* specialization,
                          const std::vector<VertexInput>& inputs, uint32_t width, uint32_t height) {
  const bool shading = fragment != VK_NULL_HANDLE;
  VkPipelineShaderStageCreateInfo stages[2]{};
  stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex;
  stages[0].pName = "main";
  stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment;
  stages[1].pName = "main";
  stages[1].pSpecializationInfo = specialization;
  VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const VertexInput& in : inputs) attributes.push_back({in.location, 0, in.format, in.offset});
  VkPipelineVertexInputStateCreateInfo input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  input.vertexBindingDescriptionCount = 1;
  input.pVertexBindingDescriptions = &binding;
  input.vertexAttributeDescriptionCount = static_cast<uint32_t>(attributes.size());
  input.pVertexAttributeDescriptions = attributes.data();
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {width, height}};
  VkPipelineViewportStateCreateInfo viewportState{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewportState.viewportCount = 1;
  viewportState.pViewports = &viewport;
  viewportState.scissorCount = 1;
  viewportState.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;  // open meshes and planes are seen from both sides
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = shading ? VK_FALSE : VK_TRUE;
  depth.depthCompareOp = shading ? VK_COMPARE_OP_EQUAL : VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blend{};
  if (shading) {
    blend.blendEnable = VK_TRUE;
    blend.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.colorBlendOp = VK_BLEND_OP_ADD;
    blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend.alphaBlendOp = VK_BLEND_OP_ADD;
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                           VK_COLOR_COMPONENT_A_BIT;
  }
  VkPipelineColorBlendStateCreateInfo blendState{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blendState.attachmentCount = 1;
  blendState.pAttachments = &blend;
  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = shading ? 2 : 1;
  info.pStages = stages;
  info.pVertexInputState = &input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewportState;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blendState;
  info.layout = layout;
  info.renderPass = pass;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline), "vkCreateGraphicsPipelines");
  return pipeline;
}

/// The camera's projection: Vulkan's clip space (depth 0..1, y down, hence the flip), and its
/// right-handed view. draw() and renderBackground() share them.
glm::mat4 viewToClip(const Camera& camera, uint32_t width, uint32_t height) {
  glm::mat4 projection =
      glm::perspectiveRH_ZO(glm::radians(camera.fovDegrees), float(width) / float(height), camera.nearPlane, camera.farPlane);
  projection[1][1] *= -1.0f;
  return projection;
}
glm::mat4 worldToView(const Camera& camera) { return glm::lookAtRH(camera.eye, camera.target, camera.up); }

}  // namespace

std::vector<std::pair<uint32_t, int32_t>> sceneSpecialization(const RenderSettings& settings) {
  const SceneConstants c = sceneConstants(settings);
  return {{glsl::kEnvironmentConstantId, c.environment},
          {glsl::kLightCountConstantId, c.lightCount},
          {glsl::kLightKindsConstantId, c.lightKinds}};
}

RgbaImage renderBackground(const RenderSettings& s) {
  RgbaImage out{s.width, s.height, std::vector<float>(size_t{s.width} * s.height * 4, 0.0f)};
  for (size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 1.0f;
  if (s.environment != Environment::Map || !s.environmentMap) return out;
  // Each ray through the camera of draw(): a point of the far plane, back to the world.
  const glm::mat4 clipToWorld = glm::inverse(viewToClip(s.camera, s.width, s.height) * worldToView(s.camera));
  const float rotation = glm::radians(s.environmentRotation);
  const RgbaImage& radiance = s.environmentMap->radiance();
  for (uint32_t y = 0; y < s.height; ++y) {
    for (uint32_t x = 0; x < s.width; ++x) {
      glm::vec3 sum(0.0f);
      for (int k = 0; k < 4; ++k) {
        // Normalised device coordinates: -1 at the left and top edges (Vulkan's y points down).
        const float px = (float(x) + 0.25f + 0.5f * float(k % 2)) / float(s.width) * 2.0f - 1.0f;
        const float py = (float(y) + 0.25f + 0.5f * float(k / 2)) / float(s.height) * 2.0f - 1.0f;
        const glm::vec4 far = clipToWorld * glm::vec4(px, py, 1.0f, 1.0f);
        // far.w > 0 for a point in front of the camera; eye and far point differ (near < far).
        const glm::vec3 d = glm::normalize(glm::vec3(far) / far.w - s.camera.eye);
        sum += equirectLookup(radiance, environmentToMap(d, rotation));
      }
      float* p = out.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = 0.25f * sum[c] * s.environmentIntensity;
    }
  }
  return out;
}

Renderer::Renderer(VulkanContext& context, const AlbedoTables& tables) : context_(context), tables_(tables) {
  vertexSpirv_ = glsl::vertexStageSpirv();
  black_ = std::make_unique<EnvironmentMap>(context, RgbaImage{});
}

Renderer::~Renderer() = default;

RenderResult Renderer::render(const Mesh& mesh, const MaterialResources& resources,
                              const glsl::MaterialInterface& material, const std::vector<uint32_t>& fragmentSpirv,
                              const RenderSettings& s, const std::function<void(uint32_t)>& progress,
                              const std::function<void()>& beforeFrames) {
  return renderScene({SceneObject{&mesh, s.objectToWorld, &resources, &material, &fragmentSpirv}}, s, progress,
                     beforeFrames);
}

RenderResult Renderer::renderScene(const std::vector<SceneObject>& objects, const RenderSettings& s,
                                   const std::function<void(uint32_t)>& progress,
                                   const std::function<void()>& beforeFrames) {
  std::vector<size_t> all(objects.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  auto frameDone = [&](size_t, uint32_t drawn) {
    if (progress) progress(drawn);
  };
  RenderResult image;
  renderObjects(objects, {all}, s, [&](size_t, RenderResult&& done) { image = std::move(done); }, frameDone, beforeFrames);
  return image;
}

void Renderer::renderEach(const std::vector<SceneObject>& objects, const RenderSettings& s,
                          const std::function<void(size_t, RenderResult&&)>& finished,
                          const std::function<void(size_t, uint32_t)>& progress,
                          const std::function<void()>& beforeFrames) {
  std::vector<std::vector<size_t>> each;
  for (size_t i = 0; i < objects.size(); ++i) each.push_back({i});
  renderObjects(objects, each, s, finished, progress, beforeFrames);
}

void Renderer::renderObjects(const std::vector<SceneObject>& objects, const std::vector<std::vector<size_t>>& groups,
                             const RenderSettings& s, const std::function<void(size_t, RenderResult&&)>& finished,
                             const std::function<void(size_t, uint32_t)>& progress,
                             const std::function<void()>& beforeFrames) {
  if (s.environment == Environment::Map && !s.environmentMap) {
    throw std::logic_error("Renderer::renderScene: Environment::Map without an environment image");
  }
  const EnvironmentMap& environment = s.environment == Environment::Map ? *s.environmentMap : *black_;
  const uint32_t lights = std::min<uint32_t>(static_cast<uint32_t>(s.lights.size()), glsl::kMaxLights);
  // Per object: its MxcView (written member by member through the contract's table,
  // compiler/glsl/Contract.h; objects differ only in their transform) and its material's set.
  struct ObjectState {
    glsl::BlockWriter block{glsl::viewMembers()};
    Buffer view;
    std::unique_ptr<DescriptorSet> set;
  };
  std::vector<std::unique_ptr<ObjectState>> states;
  Buffer dummy = context_.createBuffer(16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  struct Release {
    VulkanContext& context;
    std::vector<std::unique_ptr<ObjectState>>& states;
    Buffer& dummy;
    ~Release() {
      vkDeviceWaitIdle(context.device());
      for (auto& state : states) context.destroy(state->view);
      context.destroy(dummy);
    }
  } release{context_, states, dummy};
  const std::vector<VertexInput> inputs = {
      {glsl::kAttributePosition, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
      {glsl::kAttributeNormal, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
      {glsl::kAttributeTangent, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(Vertex, tangent)},
      {glsl::kAttributeUv, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, uv)}};
  static_assert(glsl::kEnvironmentSet == 1, "the sets are bound in order: the material's, the environment's");
  std::vector<DrawItem> items;
  for (const SceneObject& object : objects) {
    auto state = std::make_unique<ObjectState>();
    ObjectState& st = *state;
    states.push_back(std::move(state));
    st.view = context_.createBuffer(st.block.bytes().size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    st.set = std::make_unique<DescriptorSet>(context_, MaterialResources::layout(*object.material),
                                             VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
    object.resources->bind(*st.set, tables_);
    st.set->bind(glsl::kStageBinding, st.view);
    // The storage bindings belong to the compute stages; they are written anyway so that every
    // descriptor of the set is valid.
    st.set->bind(glsl::kInputBinding, dummy);
    st.set->bind(glsl::kOutputBinding, dummy);
    for (uint32_t k = 0; k < lights; ++k) {
      const Light& l = s.lights[k];
      const float kind = static_cast<float>(lightCode(l.kind));
      st.block.set("lightVector", glm::vec4(l.vector, kind), k);
      st.block.set("lightSpot", glm::vec4(l.axis, l.cosOuter), k);
      st.block.set("lightRadiance", glm::vec4(l.color * l.intensity, l.cosInner), k);
    }
    st.block.set("environment",
                 glm::vec4(s.environmentIntensity, s.emissionScale, glm::radians(s.environmentRotation), 0.0f));
    DrawItem item;
    item.mesh = object.mesh;
    item.vertexSpirv = &vertexSpirv_;
    item.fragmentSpirv = object.fragmentSpirv;
    item.inputs = inputs;
    item.sets = {st.set.get(), &environment.set()};
    item.objectToWorld = object.objectToWorld;
    item.firstIndex = object.firstIndex;
    item.indexCount = object.indexCount;
    item.beforeFrame = [&st, &s, lights](const FrameView& v) {
      st.block.set("objectToWorld", v.objectToWorld);
      st.block.set("normalToWorld", v.normalToWorld);
      st.block.set("worldToClip", v.viewToClip * v.worldToView);
      st.block.set("eye", glm::vec4(v.eye, 1.0f));
      // xy added in clip space by mxc_raster.vert; z scales the texture footprint (frames >= 1).
      st.block.set("jitter", glm::vec4(v.jitter, 1.0f / std::sqrt(float(std::max(s.frames, 1u))), 0.0f));
      st.block.set("counts", glm::ivec4(int(lights), int(environmentCode(s.environment)), int(v.frame),
                                        int(std::max(s.samplesPerFrame, 1u))));
      std::memcpy(st.view.mapped, st.block.bytes().data(), st.block.bytes().size());
    };
    items.push_back(std::move(item));
  }
  drawItems(items, groups, s, finished, progress, beforeFrames);
}

RenderResult Renderer::draw(const Mesh& mesh, const std::vector<uint32_t>& vertexSpirv,
                            const std::vector<uint32_t>& fragmentSpirv, const std::vector<VertexInput>& inputs,
                            const std::vector<const DescriptorSet*>& sets, const RenderSettings& s,
                            const std::function<void(const FrameView&)>& beforeFrame,
                            const std::function<void(uint32_t)>& progress) {
  DrawItem item{&mesh, &vertexSpirv, &fragmentSpirv, inputs, sets, s.objectToWorld, beforeFrame};
  auto frameDone = [&](size_t, uint32_t drawn) {
    if (progress) progress(drawn);
  };
  RenderResult image;
  drawItems({item}, {{0}}, s, [&](size_t, RenderResult&& done) { image = std::move(done); }, frameDone);
  return image;
}

void Renderer::drawItems(const std::vector<DrawItem>& items, const std::vector<std::vector<size_t>>& groups,
                         const RenderSettings& s, const std::function<void(size_t, RenderResult&&)>& finished,
                         const std::function<void(size_t, uint32_t)>& progress,
                         const std::function<void()>& beforeFrames) {
  for (const std::vector<size_t>& group : groups) {
    for (size_t i : group) {
      if (i >= items.size()) throw std::logic_error("Renderer::drawItems: a group names an item that does not exist");
    }
  }
  // Before anything is made: a layout beyond the device's limits would crash lavapipe.
  for (const DrawItem& item : items) checkDescriptorLimits(context_, item.sets);
  VkDevice device = context_.device();
  Frame f(context_);
  f.color = context_.createImage(s.width, s.height, VK_FORMAT_R32G32B32A32_SFLOAT,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                     VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  f.depth = context_.createImage(s.width, s.height, VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  f.renderPass = createRenderPass(device);
  VkImageView views[2] = {f.color.view, f.depth.view};
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = f.renderPass;
  fb.attachmentCount = 2;
  fb.pAttachments = views;
  fb.width = s.width;
  fb.height = s.height;
  fb.layers = 1;
  check(vkCreateFramebuffer(device, &fb, nullptr, &f.framebuffer), "vkCreateFramebuffer");
  f.items.resize(items.size());
  // Which item's pipelines each item uses (its own, or an earlier item's that is the same):
  // the owners met so far, by hash, each compared in full before it is shared.
  std::vector<size_t> shadeOwner(items.size()), depthOwner(items.size());
  std::unordered_map<const std::vector<uint32_t>*, size_t> spirvHashes;
  std::unordered_map<size_t, std::vector<size_t>> shadeOwners, depthOwners;
  auto ownerOf = [&](size_t i, bool shading) {
    std::vector<size_t>& candidates = (shading ? shadeOwners : depthOwners)[pipelineHash(items[i], shading, spirvHashes)];
    for (size_t j : candidates) {
      if (samePipeline(items[j], items[i], shading)) return j;
    }
    candidates.push_back(i);
    return i;
  };
  // Which item's buffers each item draws from: one pair per mesh, however many objects show it.
  std::unordered_map<const Mesh*, size_t> meshOwner;
  for (size_t i = 0; i < items.size(); ++i) {
    shadeOwner[i] = ownerOf(i, true);
    depthOwner[i] = ownerOf(i, false);
    f.items[i].ownsShade = shadeOwner[i] == i;
    f.items[i].ownsDepth = depthOwner[i] == i;
    f.items[i].ownsBuffers = meshOwner.try_emplace(items[i].mesh, i).first->second == i;
  }
  // The modules are needed only while the pipelines are created (only the owners' are made).
  std::vector<std::unique_ptr<ShaderModule>> modules(2 * items.size());
  for (size_t i = 0; i < items.size(); ++i) {
    const DrawItem& item = items[i];
    ItemObjects& o = f.items[i];
    const Mesh& mesh = *item.mesh;
    if (o.ownsBuffers) {
      o.vertices = context_.createBuffer(mesh.vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
      std::memcpy(o.vertices.mapped, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex));
      o.indices = context_.createBuffer(mesh.indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
      std::memcpy(o.indices.mapped, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    } else {
      // An earlier item of the same mesh made them (items are visited in order): drawn from,
      // destroyed by that item alone.
      const ItemObjects& owner = f.items[meshOwner.at(item.mesh)];
      o.vertices = owner.vertices;
      o.indices = owner.indices;
    }
    // The item's range of the mesh's triangles, clamped to the mesh.
    o.firstIndex = std::min(item.firstIndex, static_cast<uint32_t>(mesh.indices.size()));
    const uint32_t available = static_cast<uint32_t>(mesh.indices.size()) - o.firstIndex;
    o.indexCount = item.indexCount == 0 ? available : std::min(item.indexCount, available);
    if (o.ownsShade || o.ownsDepth) modules[2 * i] = std::make_unique<ShaderModule>(context_, *item.vertexSpirv);
    if (o.ownsShade) modules[2 * i + 1] = std::make_unique<ShaderModule>(context_, *item.fragmentSpirv);
    std::vector<VkDescriptorSetLayout> setLayouts;
    for (const DescriptorSet* set : item.sets) {
      setLayouts.push_back(set->layout());
      o.descriptorSets.push_back(set->set());
    }
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = static_cast<uint32_t>(setLayouts.size());
    layoutInfo.pSetLayouts = setLayouts.data();
    check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &o.layout), "vkCreatePipelineLayout");
  }
  // The environment and the lights are fixed per pipeline (compiler/glsl/Contract.h), unless
  // the settings ask for the general shader: a shader without the constants (another
  // generator's) is not affected by the entries (Vulkan 1.3, s. 10.9).
  const SceneConstants constants = sceneConstants(s);
  const VkSpecializationMapEntry entries[] = {
      {glsl::kEnvironmentConstantId, offsetof(SceneConstants, environment), sizeof(int32_t)},
      {glsl::kLightCountConstantId, offsetof(SceneConstants, lightCount), sizeof(int32_t)},
      {glsl::kLightKindsConstantId, offsetof(SceneConstants, lightKinds), sizeof(int32_t)}};
  const VkSpecializationInfo specialization{3, entries, sizeof(SceneConstants), &constants};
  const VkSpecializationInfo* fragmentConstants = s.specialize ? &specialization : nullptr;
  // The pipelines, several at a time: lavapipe compiles a material's shader on the calling
  // thread (LLVM, up to seconds for a large material), and vkCreateGraphicsPipelines may be
  // called from several threads at once (Vulkan 1.3, s. 3.6 "Threading Behavior": only a
  // pipeline cache, none here, needs external synchronisation). One job per pipeline; the
  // first failure is rethrown once all have stopped (runOnEveryCore). The shading pipelines come
  // first, the depth pipelines (a vertex shader only, quick) after: so that one material's two
  // are created side by side, and a long shading pipeline does not start last.
  std::vector<std::pair<size_t, bool>> jobs;  // (item, shading), shading pipelines first
  for (size_t i = 0; i < items.size(); ++i) {
    if (f.items[i].ownsShade) jobs.emplace_back(i, true);
  }
  for (size_t i = 0; i < items.size(); ++i) {
    if (f.items[i].ownsDepth) jobs.emplace_back(i, false);
  }
  const auto pipelinesStart = std::chrono::steady_clock::now();
  runOnEveryCore(jobs.size(), [&](size_t j) {
    const auto [i, shading] = jobs[j];
    ItemObjects& o = f.items[i];
    VkShaderModule vertex = modules[2 * i]->get();  // an owner has its vertex module
    if (shading) {
      o.shadePipeline = createPipeline(device, f.renderPass, o.layout, vertex, modules[2 * i + 1]->get(), fragmentConstants,
                                       items[i].inputs, s.width, s.height);
    } else {
      o.depthPipeline = createPipeline(device, f.renderPass, o.layout, vertex, VK_NULL_HANDLE, nullptr, items[i].inputs,
                                       s.width, s.height);
    }
  });
  const double pipelineMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - pipelinesStart).count();
  modules.clear();
  for (size_t i = 0; i < items.size(); ++i) {
    f.items[i].shadePipeline = f.items[shadeOwner[i]].shadePipeline;
    f.items[i].depthPipeline = f.items[depthOwner[i]].depthPipeline;
  }
  if (beforeFrames) beforeFrames();

  FrameView frameView;
  frameView.viewToClip = viewToClip(s.camera, s.width, s.height);
  frameView.worldToView = worldToView(s.camera);
  frameView.eye = s.camera.eye;

  // One image per group, drawn alone: the color image is cleared for each.
  for (size_t g = 0; g < groups.size(); ++g) {
    const std::vector<size_t>& group = groups[g];
    context_.submit([&](VkCommandBuffer cmd) {
      VulkanContext::transition(cmd, f.color.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                                VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                                VK_PIPELINE_STAGE_TRANSFER_BIT);
      VkClearColorValue zero{};
      VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      vkCmdClearColorImage(cmd, f.color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
      VulkanContext::transition(cmd, f.color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                                VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                                VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    });

    RenderResult result;
    double totalMs = 0.0;
    const uint32_t frames = std::max(s.frames, 1u);
    for (uint32_t drawn = 0; drawn < frames; ++drawn) {
      const uint32_t frame = s.firstFrame + drawn;
      // Sub-pixel offset in [-0.5, 0.5) pixels, in normalised device units (2 / size per pixel);
      // frame 0 samples pixel centres.
      const float jx = frame == 0 ? 0.0f : halton(frame, 2) - 0.5f;
      const float jy = frame == 0 ? 0.0f : halton(frame, 3) - 0.5f;
      // The jitter is a translation in clip space, applied before the perspective divide
      // (x_ndc += j needs x_clip += j w): one matrix for every vertex shader.
      frameView.jitter = glm::vec2(2.0f * jx / float(s.width), 2.0f * jy / float(s.height));
      glm::mat4 jitter(1.0f);
      jitter[3][0] = frameView.jitter.x;
      jitter[3][1] = frameView.jitter.y;
      frameView.worldToClip = jitter * frameView.viewToClip * frameView.worldToView;
      frameView.frame = frame;
      for (size_t i : group) {
        const DrawItem& item = items[i];
        frameView.objectToWorld = item.objectToWorld;
        // Normals by the inverse transpose; a singular transform (a zero scale) leaves them as
        // they are rather than dividing by its zero determinant.
        const float det = glm::determinant(glm::mat3(item.objectToWorld));
        frameView.normalToWorld = std::abs(det) > 1e-30f ? glm::transpose(glm::inverse(item.objectToWorld)) : glm::mat4(1.0f);
        item.beforeFrame(frameView);
      }
      const auto start = std::chrono::steady_clock::now();
      context_.submit([&](VkCommandBuffer cmd) {
        VkClearValue clears[2]{};
        clears[1].depthStencil = {1.0f, 0};
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = f.renderPass;
        begin.framebuffer = f.framebuffer;
        begin.renderArea = {{0, 0}, {s.width, s.height}};
        begin.clearValueCount = 2;
        begin.pClearValues = clears;
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        // Every object's depth first, then every object shaded where it is the nearest (EQUAL).
        for (bool shading : {false, true}) {
          for (size_t i : group) {
            const ItemObjects& o = f.items[i];
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, o.layout, 0,
                                    static_cast<uint32_t>(o.descriptorSets.size()), o.descriptorSets.data(), 0, nullptr);
            VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(cmd, 0, 1, &o.vertices.buffer, &offset);
            vkCmdBindIndexBuffer(cmd, o.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shading ? o.shadePipeline : o.depthPipeline);
            vkCmdDrawIndexed(cmd, o.indexCount, 1, o.firstIndex, 0, 0);
          }
        }
        vkCmdEndRenderPass(cmd);
      });
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (drawn > 0 || frames == 1) totalMs += ms;  // the first frame also warms caches up
      if (progress) progress(g, drawn + 1);
    }
    result.msPerFrame = totalMs / double(frames > 1 ? frames - 1 : 1);
    result.pipelineMs = pipelineMs;
    std::vector<float> sum = context_.download(f.color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    result.image.width = s.width;
    result.image.height = s.height;
    result.image.pixels.resize(sum.size());
    const float inv = 1.0f / float(frames);  // frames >= 1
    for (size_t i = 0; i < sum.size(); ++i) result.image.pixels[i] = sum[i] * inv;
    finished(g, std::move(result));
  }
}

}  // namespace mxc::rt