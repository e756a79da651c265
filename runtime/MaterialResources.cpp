#include "runtime/MaterialResources.h"

#include <cstring>

#include <fmt/format.h>

#include "compiler/common/InputFile.h"
#include "runtime/ImageIO.h"

namespace mxc::rt {

MaterialResources::MaterialResources(VulkanContext& context, const glsl::MaterialInterface& material,
                                     const std::filesystem::path& folder, Diagnostics& diagnostics)
    : context_(context), material_(material) {
  uint32_t missing = 0;
  for (size_t k = 0; k < material.textures.size(); ++k) {
    const glsl::TextureBinding& t = material.textures[k];
    std::filesystem::path path = t.path;
    if (path.is_relative()) path = folder / path;
    RgbaImage pixels;
    if (t.path.empty()) {
      diagnostics.warning(t.origin, "an image node has no file: its default value is used");
    } else if (auto problem = inputFileProblem(path); problem && *problem != "it does not exist") {
      // A FIFO would block and /dev/zero would never end: refused before anything opens them.
      diagnostics.error(t.origin, fmt::format("cannot read image '{}': {}", path.string(), *problem));
    } else {
      ImageReadOptions options;
      options.maxDimension = context.maxImageDimension2D();
      // MaterialX colour space "srgb_texture": sRGB-encoded values, decoded to linear on reading.
      options.srgbDecode = t.colorspace == "srgb_texture";
      std::vector<std::string> warnings;
      auto read = readImage(path, options, &warnings);
      for (const std::string& w : warnings) diagnostics.warning(t.origin, w);
      if (auto* error = std::get_if<std::string>(&read)) {
        diagnostics.warning(t.origin, *error + ": the image node's default value is used");
      } else {
        pixels = std::move(std::get<RgbaImage>(read));
      }
    }
    if (pixels.pixels.empty()) {
      missing |= 1u << (k % 32);
      pixels = RgbaImage{1, 1, {0.0f, 0.0f, 0.0f, 1.0f}};
    }
    Image image = context.createImage(pixels.width, pixels.height, VK_FORMAT_R32G32B32A32_SFLOAT,
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    context.upload(image, pixels.pixels.data());
    textures_.push_back(image);
  }
  for (glsl::UniformField& f : material_.parameters) {
    if (f.name == "missing_textures") f.value = {static_cast<float>(missing)};
  }
  parameters_ = context.createBuffer(material_.parameterBytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::vector<uint8_t> bytes = glsl::packParameters(material_.parameters, material_.parameterBytes);
  std::memcpy(parameters_.mapped, bytes.data(), bytes.size());
}

MaterialResources::~MaterialResources() {
  for (Image& image : textures_) context_.destroy(image);
  context_.destroy(parameters_);
}

std::vector<VkDescriptorType> MaterialResources::layout(const glsl::MaterialInterface& material) {
  std::vector<VkDescriptorType> types{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                      VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                      VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
  types.resize(glsl::kFirstTextureBinding + material.textures.size(), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  return types;
}

bool MaterialResources::setParameter(const std::string& name, const std::vector<float>& value) {
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
  for (size_t k = 0; k < textures_.size(); ++k) set.bind(material_.textures[k].binding, textures_[k]);
}

}  // namespace mxc::rt
