#pragma once
/// \file
/// The albedo tables the generated lobes read (binding kTablesBinding), as a sampled RGBA32F
/// image. The harness loads the committed tables (generated/tables, embedded in the binary:
/// compiler/glsl/AlbedoTableFile.h); `compute` runs the tables compute shader
/// (compiler/glsl/stages/mxc_tables.comp) that produced them, for scripts/generate-tables and
/// for the test that the committed tables are still what that shader computes.

#include <vector>

#include "runtime/VulkanContext.h"

namespace mxc::rt {

class AlbedoTables {
 public:
  /// The committed tables, uploaded. Throws when the embedded file does not hold tables of the
  /// contract's size (a build from a tree whose tables were not regenerated).
  explicit AlbedoTables(VulkanContext& context);
  /// Given tables (kTableSize x kTableHeight RGBA; throws std::invalid_argument otherwise): for
  /// the generator of the walk's tables, which measures with the computed tables and no walk
  /// rows (tools/GenerateWalkFits.cpp), so that a change of their layout needs no committed file.
  AlbedoTables(VulkanContext& context, std::vector<float> texels);
  ~AlbedoTables();
  AlbedoTables(const AlbedoTables&) = delete;
  AlbedoTables& operator=(const AlbedoTables&) = delete;

  const Image& image() const { return image_; }
  /// The texels, kTableSize x kTableHeight RGBA, row by row (layout: stages/mxc_tables.comp).
  const std::vector<float>& values() const { return values_; }

  /// The computed tables (kComputedTableHeight rows) as the tables compute shader computes them
  /// on `context`'s device (seconds).
  static std::vector<float> compute(VulkanContext& context);

 private:
  VulkanContext& context_;
  Image image_;
  std::vector<float> values_;
};

}  // namespace mxc::rt
