#pragma once
/// \file
/// What the commands that run shaders share: device options, compiling a material for a use,
/// and progress on a terminal.

#include <cstdio>
#include <filesystem>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/MaterialPipeline.h"
#include "cli/Session.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "runtime/AlbedoTables.h"
#include "runtime/MaterialResources.h"
#include "runtime/TextureCache.h"
#include "runtime/VulkanContext.h"

namespace mxc::cli {

struct DeviceOptions {
  std::string device;       ///< --device: index or part of a name
  bool validation = false;  ///< --validation: Khronos validation layer on; a message fails the run
};


/// The device and the albedo tables, created on first use. Vulkan errors become a message and
/// a non-zero exit instead of an exception escaping.
class Device {
 public:
  explicit Device(const DeviceOptions& options) : options_(options) {}
  /// Null (with the error printed) when no device can be created.
  rt::VulkanContext* context();
  rt::AlbedoTables* tables();
  /// The textures read so far, shared by the materials of a run; null (with the error printed)
  /// when there is no device.
  rt::TextureCache* textures();
  /// Prints validation messages; true when there were none.
  bool checkValidation();

 private:
  DeviceOptions options_;
  std::unique_ptr<rt::VulkanContext> context_;
  std::unique_ptr<rt::AlbedoTables> tables_;
  std::unique_ptr<rt::TextureCache> textures_;  // after context_: destroyed before it
};

/// A material ready to run: its shader of one kind, the SPIR-V, and its resources on the device.
struct MaterialProgram {
  glsl::MaterialShader shader;
  std::vector<uint32_t> spirv;
  std::unique_ptr<rt::MaterialResources> resources;
};

/// Builds and compiles the material's shader of `kind` and loads its textures (relative paths
/// from the document's folder; warnings printed). Nullopt when it does not compile or a texture path is not a
/// regular file (diagnostics printed). Textures come from `textures` when given.
std::optional<MaterialProgram> prepareMaterial(MaterialPipeline& pipeline, Session& session, rt::VulkanContext& context,
                                               const ir::Material& material, glsl::ShaderKind kind,
                                               rt::TextureCache* textures = nullptr);

/// One material of a document to prepare (prepareMaterials).
struct MaterialToPrepare {
  MaterialPipeline* pipeline;
  const ir::Material* material;
};

/// prepareMaterial for several materials, in order. Their shaders are built and compiled on up
/// to one thread per core (glslang is most of a material's compile time); then each one's
/// resources are made on this thread, in order (they upload through the device's one queue).
/// Nullopt when any fails (diagnostics printed, in the materials' order).
std::optional<std::vector<MaterialProgram>> prepareMaterials(const std::vector<MaterialToPrepare>& materials,
                                                             Session& session, rt::VulkanContext& context,
                                                             glsl::ShaderKind kind, rt::TextureCache* textures = nullptr);

/// A progress bar with the share done and an estimate of the time left, on stderr, rewritten
/// in place: only when stderr is a terminal and the work has taken more than a second, at most
/// ten times a second, cut to the terminal's width (a line that wraps cannot be rewritten), and
/// cleared when the object is destroyed, so nothing of it stays before the command's output.
class Progress {
 public:
  explicit Progress(size_t total);
  /// One more unit of the total is done; `what` says where the work is.
  void step(const std::string& what);
  /// Erases the bar, if drawn, so that a message can be printed; the next step draws it again.
  void clear();
  ~Progress();

 private:
  size_t total_;
  size_t done_ = 0;
  bool tty_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastDraw_;
};

}  // namespace mxc::cli
