#include "cli/MaterialXShader.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compiler/document/Value.h"
#include "runtime/ImageIO.h"

namespace mxc::cli {

namespace {

using spirv::Reflection;

/// The float components of a MaterialX value string of the given type, from the document
/// model's parser; empty for non-numeric types and malformed strings.
std::vector<float> numericValue(const MaterialXUniform& u) {
  auto parsed = doc::parseValue(doc::valueTypeOf(u.type), u.value);
  const doc::Value* v = std::get_if<doc::Value>(&parsed);
  if (!v) return {};
  if (v->type() == doc::ValueType::Boolean) return {v->as<bool>() ? 1.0f : 0.0f};
  if (v->type() == doc::ValueType::Integer) return {static_cast<float>(v->as<int32_t>())};
  return v->components();
}

/// Writes `values` into a std140 block member: scalars and vectors packed, matrix columns 16
/// bytes apart (values given row by row, as MaterialX writes matrices), ints and bools as
/// 32-bit integers.
void write(std::vector<uint8_t>& bytes, const Reflection::Member& m, size_t element, const std::vector<float>& values) {
  const size_t base = static_cast<size_t>(m.offset) + element * static_cast<size_t>(m.arrayStride);
  for (size_t i = 0; i < values.size() && i < static_cast<size_t>(m.components); ++i) {
    const size_t r = m.columns > 1 ? i / static_cast<size_t>(m.columns) : i;
    const size_t c = m.columns > 1 ? i % static_cast<size_t>(m.columns) : 0;
    const size_t at = base + c * 16 + r * 4;
    if (at + 4 > bytes.size()) return;  // reflection and block size disagree: leave the rest
    if (m.scalar == Reflection::Scalar::Float) {
      std::memcpy(bytes.data() + at, &values[i], 4);
    } else {
      const auto v = static_cast<int32_t>(values[i]);
      std::memcpy(bytes.data() + at, &v, 4);
    }
  }
}

std::vector<float> flatten(const glm::mat4& m) {  // row by row
  std::vector<float> out;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out.push_back(m[c][r]);
  }
  return out;
}

/// One uniform block of either stage, with the buffer behind it.
struct BlockBuffer {
  const Reflection* interface = nullptr;
  int index = -1;  ///< into interface->blocks
  std::vector<uint8_t> bytes;
  rt::Buffer buffer;
};

}  // namespace

std::vector<MaterialXUniform> parseMaterialXUniforms(const std::string& json) {
  std::vector<MaterialXUniform> out;
  const nlohmann::json blocks = nlohmann::json::parse(json);
  for (const auto& [block, entries] : blocks.items()) {
    for (const nlohmann::json& e : entries) {
      if (e.at("value").is_null()) continue;
      out.push_back({e.at("name"), e.at("type"), e.at("value")});
    }
  }
  return out;
}

std::variant<MaterialXShader, std::string> MaterialXShader::load(const std::string& vertexGlsl,
                                                                  const std::string& pixelGlsl,
                                                                  std::vector<MaterialXUniform> uniforms,
                                                                  const std::filesystem::path& folder) {
  MaterialXShader s;
  Diagnostics diagnostics;
  auto vertex = spirv::compile({vertexGlsl, spirv::Stage::Vertex, "MaterialX vertex stage", {}},
                               {.reflection = &s.vertexInterface_, .specialization = {}}, diagnostics);
  auto pixel = spirv::compile({pixelGlsl, spirv::Stage::Fragment, "MaterialX pixel stage", {}},
                              {.reflection = &s.pixelInterface_, .specialization = {}}, diagnostics);
  if (!vertex || !pixel) return diagnostics.format();
  s.vertex_ = std::move(*vertex);
  s.pixel_ = std::move(*pixel);
  for (MaterialXUniform& u : uniforms) {
    std::vector<float> numeric = numericValue(u);
    if (!numeric.empty()) s.values_[u.name] = std::move(numeric);
    std::string name = u.name;
    s.uniforms_[name] = std::move(u);
  }
  s.folder_ = folder;
  return s;
}

const std::string* MaterialXShader::valueOf(const std::string& name) const {
  auto it = uniforms_.find(name);
  return it == uniforms_.end() ? nullptr : &it->second.value;
}

rt::RenderResult MaterialXShader::render(rt::VulkanContext& context, rt::Renderer& renderer, const rt::Mesh& mesh,
                                         const rt::RenderSettings& settings, std::vector<std::string>& warnings) const {
  // Vertex inputs by MaterialX's names.
  std::vector<rt::VertexInput> inputs;
  for (const Reflection::Input& in : vertexInterface_.inputs) {
    const auto location = static_cast<uint32_t>(in.location);
    if (in.name == "i_position") {
      inputs.push_back({location, VK_FORMAT_R32G32B32_SFLOAT, offsetof(rt::Vertex, position)});
    } else if (in.name == "i_normal") {
      inputs.push_back({location, VK_FORMAT_R32G32B32_SFLOAT, offsetof(rt::Vertex, normal)});
    } else if (in.name == "i_tangent") {
      inputs.push_back({location, VK_FORMAT_R32G32B32_SFLOAT, offsetof(rt::Vertex, tangent)});
    } else if (in.name.rfind("i_texcoord_", 0) == 0) {
      inputs.push_back({location, VK_FORMAT_R32G32_SFLOAT, offsetof(rt::Vertex, uv)});
    } else {
      throw std::runtime_error(fmt::format("MaterialX's vertex stage reads '{}', which the mesh does not have", in.name));
    }
  }

  // Bindings: every block and sampler of both stages; gaps get an unused uniform buffer.
  std::vector<BlockBuffer> blocks;
  int highest = -1;
  for (const Reflection* r : {&vertexInterface_, &pixelInterface_}) {
    for (size_t b = 0; b < r->blocks.size(); ++b) {
      blocks.push_back({r, static_cast<int>(b), std::vector<uint8_t>(std::max(16, r->blocks[b].size), 0), {}});
      highest = std::max(highest, r->blocks[b].binding);
    }
    for (const Reflection::Sampler& sampler : r->samplers) highest = std::max(highest, sampler.binding);
  }
  std::vector<VkDescriptorType> types(static_cast<size_t>(highest + 1), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  std::map<int, std::string> samplers;  // binding -> name
  for (const Reflection* r : {&vertexInterface_, &pixelInterface_}) {
    for (const Reflection::Sampler& sampler : r->samplers) {
      types[static_cast<size_t>(sampler.binding)] = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      samplers[sampler.binding] = sampler.name;
    }
  }
  rt::DescriptorSet set(context, types, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
  std::vector<rt::Image> images;
  std::vector<rt::Buffer> spare;
  struct Release {
    rt::VulkanContext& context;
    std::vector<BlockBuffer>& blocks;
    std::vector<rt::Image>& images;
    std::vector<rt::Buffer>& spare;
    ~Release() {
      vkDeviceWaitIdle(context.device());
      for (BlockBuffer& b : blocks) context.destroy(b.buffer);
      for (rt::Image& i : images) context.destroy(i);
      for (rt::Buffer& b : spare) context.destroy(b);
    }
  } release{context, blocks, images, spare};
  std::vector<bool> bound(types.size(), false);
  for (BlockBuffer& b : blocks) {
    b.buffer = context.createBuffer(b.bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    const int binding = b.interface->blocks[static_cast<size_t>(b.index)].binding;
    set.bind(static_cast<uint32_t>(binding), b.buffer);
    bound[static_cast<size_t>(binding)] = true;
  }
  for (const auto& [binding, name] : samplers) {
    // The texture named by the public uniform of the same name; MaterialX's shader converts
    // colour spaces itself, so texels go up as stored, bottom row first (MaterialX's v is up
    // and its GLSL samples without flipping).
    rt::RgbaImage pixels{1, 1, {0.0f, 0.0f, 0.0f, 1.0f}};
    const std::string* file = valueOf(name);
    if (!file || file->empty()) {
      warnings.push_back(fmt::format("sampler '{}' has no file: black", name));
    } else {
      std::filesystem::path path = *file;
      if (path.is_relative()) path = folder_ / path;
      auto read = rt::readImage(path);
      if (auto* error = std::get_if<std::string>(&read)) {
        warnings.push_back(*error + ": black");
      } else {
        pixels = std::move(std::get<rt::RgbaImage>(read));
        const size_t row = static_cast<size_t>(pixels.width) * 4;
        for (uint32_t y = 0; y < pixels.height / 2; ++y) {
          std::swap_ranges(pixels.pixels.begin() + static_cast<std::ptrdiff_t>(y * row),
                           pixels.pixels.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                           pixels.pixels.begin() + static_cast<std::ptrdiff_t>((pixels.height - 1 - y) * row));
        }
      }
    }
    // MaterialX's GLSL leaves addressing to the sampler: <node>_uaddressmode / _vaddressmode
    // when the node has them (0 constant, 1 clamp, 2 periodic, 3 mirror), else periodic, as
    // its viewer does for tiledimage.
    auto address = [&](const char* axis) {
      const std::string base = name.size() > 5 && name.compare(name.size() - 5, 5, "_file") == 0
                                   ? name.substr(0, name.size() - 5)
                                   : name;
      const std::string* mode = valueOf(base + "_" + axis + "addressmode");
      const int m = mode ? std::atoi(mode->c_str()) : 2;
      return m == 0 ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER
             : m == 1 ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
             : m == 3 ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                      : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    };
    rt::Image image = context.createImage(pixels.width, pixels.height, VK_FORMAT_R32G32B32A32_SFLOAT,
                                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, address("u"),
                                          address("v"));
    context.upload(image, pixels.pixels.data());
    images.push_back(image);
    set.bind(static_cast<uint32_t>(binding), images.back());
    bound[static_cast<size_t>(binding)] = true;
  }
  for (size_t binding = 0; binding < bound.size(); ++binding) {
    if (bound[binding]) continue;
    spare.push_back(context.createBuffer(16, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
    set.bind(static_cast<uint32_t>(binding), spare.back());
  }

  // Every block, each frame: the camera from `view` (identity before the first frame),
  // material inputs from their parsed values, lights, environment off.
  const size_t lights = settings.lights.size();
  auto fill = [&](const rt::FrameView* view) {
    for (BlockBuffer& b : blocks) {
      for (const Reflection::Member& m : b.interface->members) {
        if (m.block != b.index) continue;
        const std::string& n = m.name;
        std::vector<float> v;
        if (n == "u_worldMatrix") v = flatten(view ? view->objectToWorld : glm::mat4(1.0f));
        else if (n == "u_worldInverseTransposeMatrix") v = flatten(view ? view->normalToWorld : glm::mat4(1.0f));
        else if (n == "u_viewProjectionMatrix") v = flatten(view ? view->worldToClip : glm::mat4(1.0f));
        else if (n == "u_viewMatrix") v = flatten(view ? view->worldToView : glm::mat4(1.0f));
        else if (n == "u_projectionMatrix") v = flatten(view ? view->viewToClip : glm::mat4(1.0f));
        else if (n == "u_viewPosition") v = view ? std::vector<float>{view->eye.x, view->eye.y, view->eye.z} : v;
        else if (n == "u_numActiveLightSources") v = {float(lights)};
        else if (n == "u_envLightIntensity") v = {0.0f};  // environment lighting off on both sides
        else if (n == "u_frame") v = {view ? float(view->frame) : 0.0f};
        else if (n.rfind("u_lightData", 0) == 0 && n.find('.') != std::string::npos) {
          // "u_lightData[k].field", or "u_lightData.field" when the array has one element.
          const size_t k = n[11] == '[' ? std::strtoul(n.c_str() + 12, nullptr, 10) : 0;
          const std::string field = n.substr(n.find('.') + 1);
          if (k < lights) {
            const rt::Light& l = settings.lights[k];
            // MaterialX's directional light: `direction` is the way the light travels, its
            // radiance color * intensity; mxc's Light points towards the light.
            if (field == "type") v = {1.0f};  // the id the script bound ND_directional_light to
            else if (field == "direction") v = {-l.vector.x, -l.vector.y, -l.vector.z};
            else if (field == "color") v = {l.color.x, l.color.y, l.color.z};
            else if (field == "intensity") v = {l.intensity};
          }
        } else {
          if (auto it = values_.find(n); it != values_.end()) {
            v = it->second;
          } else if (uniforms_.count(n)) {
            // A value MaterialX gave that is not numeric (a string): nothing to write.
          } else if (!view && n.rfind("u_", 0) == 0) {  // shader-typed inputs' members stay zero, unused
            warnings.push_back(fmt::format("MaterialX uniform '{}' has no value here: zero", n));
          }
        }
        if (!v.empty()) write(b.bytes, m, 0, v);
      }
      std::memcpy(b.buffer.mapped, b.bytes.data(), b.bytes.size());
    }
  };
  fill(nullptr);
  return renderer.draw(mesh, vertex_, pixel_, inputs, {&set}, settings, [&](const rt::FrameView& v) { fill(&v); });
}

}  // namespace mxc::cli
