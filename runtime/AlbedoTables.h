#pragma once
/// \file
/// The albedo tables the generated lobes read (binding kTablesBinding): computed once per device
/// by the tables compute shader (compiler/glsl/stages/mxc_tables.comp) and kept as a sampled
/// RGBA32F image.

#include <vector>

#include "runtime/VulkanContext.h"

namespace mxc::rt {

class AlbedoTables {
 public:
  explicit AlbedoTables(VulkanContext& context);
  ~AlbedoTables();
  AlbedoTables(const AlbedoTables&) = delete;
  AlbedoTables& operator=(const AlbedoTables&) = delete;

  const Image& image() const { return image_; }
  /// The texels, kTableSize x kTableHeight RGBA, row by row (layout: stages/mxc_tables.comp).
  const std::vector<float>& values() const { return values_; }

 private:
  VulkanContext& context_;
  Image image_;
  std::vector<float> values_;
};

}  // namespace mxc::rt
