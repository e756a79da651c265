#pragma once
/// \file
/// What a material shader reads besides the stage's own data: its parameter block and its
/// textures (read through OpenImageIO), bound at the bindings of compiler/glsl/Bindings.h.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "runtime/AlbedoTables.h"
#include "runtime/Descriptors.h"
#include "runtime/TextureCache.h"

namespace mxc::rt {

class MaterialResources {
 public:
  /// Reads the material's textures, relative paths from `folder`, reported at the image node's
  /// `file` input: a missing or unreadable file is a warning and the shader uses the node's
  /// default instead; a path that is not a regular file (a FIFO, a device, a directory) is an
  /// error. Images beyond the device's size limit are downsampled (a warning). Textures come
  /// from `textures` when given (shared with the other materials using it).
  MaterialResources(VulkanContext& context, const glsl::MaterialInterface& material, const std::filesystem::path& folder,
                    Diagnostics& diagnostics, TextureCache* textures = nullptr);
  ~MaterialResources();
  MaterialResources(const MaterialResources&) = delete;
  MaterialResources& operator=(const MaterialResources&) = delete;

  /// The descriptor types of set 0 for this material: tables, stage block, parameters, input,
  /// output, then one sampler per texture.
  static std::vector<VkDescriptorType> layout(const glsl::MaterialInterface& material);

  /// Sets a parameter (`--param`, frame, time) to new values; false when it does not exist, and
  /// for the missing_textures masks, which the textures' files set (their bits are not floats).
  bool setParameter(const std::string& name, const std::vector<float>& value);
  /// Binds the tables, the parameters and the textures into `set`.
  void bind(DescriptorSet& set, const AlbedoTables& tables) const;

 private:
  VulkanContext& context_;
  glsl::MaterialInterface material_;
  Buffer parameters_;
  std::vector<std::shared_ptr<const Texture>> textures_;
};

}  // namespace mxc::rt
