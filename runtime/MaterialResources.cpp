#include "runtime/MaterialResources.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "compiler/common/ColorSpace.h"
#include "compiler/common/InputFile.h"
#include "compiler/common/Quote.h"
#include "runtime/ImageIO.h"

namespace mxc::rt {

MaterialResources::MaterialResources(VulkanContext& context, const glsl::MaterialInterface& material,
                                     const std::filesystem::path& folder, Diagnostics& diagnostics,
                                     TextureCache* textures)
    : context_(context), material_(material) {
  // Without a cache of the caller's, the material's own: its textures of one file are shared.
  TextureCache own(context);
  TextureCache& cache = textures ? *textures : own;
  std::vector<uint32_t> missing(std::max<size_t>((material.textures.size() + 31) / 32, 1), 0);  // a mask per 32 textures
  for (size_t k = 0; k < material.textures.size(); ++k) {
    const glsl::TextureBinding& t = material.textures[k];
    std::filesystem::path path = t.path;
    if (path.is_relative()) path = folder / path;
    std::shared_ptr<const Texture> texture;
    if (t.path.empty()) {
      diagnostics.warning(t.origin, "an image node has no file: its default value is used");
    } else if (auto problem = inputFileProblem(path); problem && *problem != "it does not exist") {
      // A FIFO would block and /dev/zero would never end: refused before anything opens them.
      diagnostics.error(t.origin, fmt::format("cannot read image {}: {}", quotedValue(path.string()), *problem));
    } else {
      // An sRGB-encoded colour space (srgb_texture, srgb_displayp3): the device decodes the
      // texels; the shader converts the primaries (compiler/lower/StdlibRules.cpp).
      texture = cache.get(path, deviceDecodes(t.colorspace));
      for (const std::string& w : texture->warnings()) diagnostics.warning(t.origin, w);
      if (!texture->error().empty()) {
        diagnostics.warning(t.origin, texture->error() + ": the image node's default value is used");
      }
    }
    if (!texture || !texture->error().empty()) {
      missing[k / 32] |= 1u << (k % 32);
      if (!texture) texture = cache.placeholder();
    }
    textures_.push_back(std::move(texture));
  }
  for (glsl::UniformField& f : material_.parameters) {
    for (size_t word = 0; word < missing.size(); ++word) {
      if (f.name == glsl::missingTexturesMember(word * 32)) f.bits = missing[word];
    }
  }
  parameters_ = context.createBuffer(material_.parameterBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  std::vector<uint8_t> bytes = glsl::packParameters(material_.parameters, material_.parameterBytes);
  std::memcpy(parameters_.mapped, bytes.data(), bytes.size());
}

MaterialResources::~MaterialResources() { context_.destroy(parameters_); }

std::vector<VkDescriptorType> MaterialResources::layout(const glsl::MaterialInterface& material) {
  // The parameters are a read-only storage buffer, not a uniform block: lavapipe (Mesa 22.3)
  // compiles a shader again at every draw for the values of uniform-block members that decide a
  // branch ("inlinable uniforms"), and a parameter (`--param`, every input of a shader compiled
  // with --no-specialize) decides many. A storage buffer is never inlined (compiler/glsl/Bindings.h).
  std::vector<VkDescriptorType> types{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                      VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
  types.resize(glsl::kFirstTextureBinding + material.textures.size(), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  return types;
}

bool MaterialResources::setParameter(const std::string& name, const std::vector<float>& value) {
  if (glsl::isMissingTexturesMember(name)) return false;  // packParameters writes their bits, never `value`
  for (glsl::UniformField& f : material_.parameters) {
    if (f.name != name || f.value.size() != value.size()) continue;
    f.value = value;
    std::vector<uint8_t> bytes = glsl::packParameters(material_.parameters, material_.parameterBytes);
    std::memcpy(parameters_.mapped, bytes.data(), bytes.size());
    return true;
  }
  return false;
}

void MaterialResources::bind(DescriptorSet& set, const AlbedoTables& tables) const {
  set.bind(glsl::kTablesBinding, tables.image());
  set.bind(glsl::kParameterBinding, parameters_);
  for (size_t k = 0; k < textures_.size(); ++k) set.bind(material_.textures[k].binding, textures_[k]->image());
}

}  // namespace mxc::rt
