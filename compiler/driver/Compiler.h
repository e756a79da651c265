#pragma once
/// \file
/// The compiler's one entry point: a CompileRequest in, each stage's result out. Every caller
/// (the mxc commands, the tests, the fuzz targets, the benchmarks) goes through it, so the
/// sequence load -> resolve -> lower -> passes -> features -> GLSL -> SPIR-V is written once
/// and an option is added in one place: a field of CompileRequest, read by its stage.
///
///   Workspace workspace;                      // sources, diagnostics, libraries
///   workspace.loadLibraries();
///   Compiler compiler(workspace, {.document = "shader.mtlx"});
///   for (const ir::Material& m : compiler.materials())
///     auto words = compiler.spirv(compiler.shader(m));
///
/// Each stage is also callable alone (`inspect` stops at resolved(), `inspect --ir` at
/// materials()) and runs the stages before it once.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compiler/common/Accuracy.h"
#include "compiler/common/Diagnostic.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/driver/ShaderCache.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/ir/Material.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/ResolvedGraph.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "compiler/target/Translate.h"

namespace mxc {

/// What compilations share and what outlives them: the source texts (every location points
/// into them), the diagnostics, the loaded documents, and the node libraries, loaded once for a
/// command, a test program or a benchmark. The IR of a material refers to texts held here, so
/// materials stay valid as long as their workspace.
class Workspace {
 public:
  Workspace();
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  /// Loads mxc's built-in library (unless `builtin` is false), then each folder or file over it.
  /// False when a library has errors, or when no library is left.
  bool loadLibraries(bool builtin = true, const std::vector<std::string>& folders = {});

  SourceManager sources;
  Diagnostics diagnostics;
  lib::LibraryStack libraries;
  doc::DocumentLoader loader;
  std::vector<lib::LibraryInfo> libraryInfo;  ///< the layers loaded, for reports
  /// The shaders its compilers have compiled (Compiler::spirv): the materials of a document or
  /// a scene whose shaders have the same code compile once.
  ShaderCache shaderCache;
};

/// Everything a caller chooses about one compilation.
struct CompileRequest {
  /// The document: a file, or, when `text` is set, a text held in memory under this name
  /// (includes resolve relative to its folder).
  std::filesystem::path document;
  std::optional<std::string> text;
  /// Libraries loaded beforehand and shared by many workspaces (a fuzzer's inputs, a
  /// benchmark's iterations); when set, the workspace's own libraries are not used. They must
  /// outlive the materials.
  const lib::LibraryStack* libraries = nullptr;
  /// `--set`, `--param` and `--shading-model-graphs`.
  lower::LoweringOptions lowering;
  /// Only the material of this name (empty: every material). Materials() is then empty when
  /// none has the name; materialNames() lists the document's.
  std::string material;
  /// Lower even when the document has errors (`inspect --ir --partial`); otherwise a document
  /// with errors has no materials.
  bool partial = false;
  /// The accuracy tier: read by the back end, visible to the passes.
  Accuracy accuracy = Accuracy::Balanced;
  /// The reference tier's random walks per evaluation of f cos (its sampling is one walk).
  int referenceSamples = 1;
  /// The shader stage shader() builds unless told another.
  glsl::ShaderKind stage = glsl::ShaderKind::Raster;
  /// Paste the shader library in (false: `#include` lines, for the golden files).
  bool expandLibrary = true;
  /// SPIRV-Tools' performance passes (`-O`).
  bool optimize = false;
  /// Shaders already compiled by other workspaces of this process (a batch's workers): a shader
  /// whose code one of them compiled is not compiled again. Must outlive the compiles. When
  /// null, Compiler::spirv uses its workspace's.
  ShaderCache* shaderCache = nullptr;
  /// The language the shader is written in (`--target`). Other than SPIR-V, the shader is built
  /// for hosts without mxc's renderer: no subgroup operations, and for WGSL separate textures and
  /// samplers (glsl::BuildOptions); translate() then writes it from the SPIR-V.
  target::Target target = target::Target::Spirv;
  /// Compile only what the material and the scene use (the default). False (`--no-specialize`):
  /// the general shader, for comparison: every input of the shading node a uniform (so no effect
  /// of the shading model is folded away; LoweringOptions::everyInputVariable) and the library's
  /// refraction and absorption code compiled in whatever the lobes (BuildOptions::specialize).
  /// The renderer then also reads the environment and the lights at run time
  /// (rt::RenderSettings::specialize).
  bool specialize = true;
  /// Verify the IR after lowering and after every pass (compiler/ir/Verify.h): on in debug
  /// builds and in the tests; a broken rule throws ir::VerifyFailure.
#ifdef NDEBUG
  bool verifyIr = false;
#else
  bool verifyIr = true;
#endif
};

/// One compilation of one document, in a workspace.
class Compiler {
 public:
  Compiler(Workspace& workspace, CompileRequest request);

  const CompileRequest& request() const { return request_; }
  /// The cache spirv() compiles through: the request's, else the workspace's.
  ShaderCache& shaderCache() { return request_.shaderCache ? *request_.shaderCache : workspace_.shaderCache; }
  Workspace& workspace() { return workspace_; }
  Diagnostics& diagnostics() { return workspace_.diagnostics; }

  /// The document, or null when it cannot be read or is not well-formed XML.
  const doc::Document* document();
  /// The folder relative image paths are resolved from (the document's).
  std::filesystem::path documentFolder() const;
  /// The resolved graph (kept even when resolution reported errors, for `inspect --partial`),
  /// or null when there is no document or no library.
  const resolve::ResolvedDocument* resolved();
  /// Every material of the document, lowered, with the passes run to their fixed point and the
  /// features computed. Empty when the document has errors (unless the request is partial).
  std::vector<ir::Material>& materials();
  /// The names of every material of the document (before the `material` choice).
  const std::vector<std::string>& materialNames() { materials(); return names_; }

  /// The GLSL of a material's shader for the request's stage, or for `kind`.
  glsl::MaterialShader shader(const ir::Material& material) const;
  glsl::MaterialShader shader(const ir::Material& material, glsl::ShaderKind kind) const;
  /// The shader compiled to validated SPIR-V (optimised when the request says so); nullopt when
  /// glslang rejects it (reported at the document elements the failing lines came from).
  /// `served`, when given, says whether the cache had it (ShaderCache::Served).
  std::optional<std::vector<uint32_t>> spirv(const glsl::MaterialShader& shader,
                                             ShaderCache::Served* served = nullptr);
  /// A stage's SPIR-V in the request's target, each resource at its placement
  /// (target::placeResources), validated by the target's toolchain; nullopt when it fails
  /// (reported, naming `what`: "material Glass (fragment)").
  std::optional<target::Translation> translate(const std::vector<uint32_t>& words, spirv::Stage stage,
                                               const std::vector<target::Placement>& placements,
                                               const std::string& what);

 private:
  Workspace& workspace_;
  CompileRequest request_;
  bool loaded_ = false, lowered_ = false;
  const doc::Document* document_ = nullptr;
  std::unique_ptr<resolve::ResolvedDocument> resolved_;
  std::vector<ir::Material> materials_;
  std::vector<std::string> names_;
};

/// The stages after lowering, for a material built or kept outside a Compiler (tests of the
/// passes and the back end, benchmarks): the very calls Compiler makes.
///
/// Runs the passes to their fixed point and computes the features.
void finishMaterial(ir::Material& material, const CompileRequest& request = {});
/// The GLSL of the material's shader of `kind`.
glsl::MaterialShader buildShader(const ir::Material& material, glsl::ShaderKind kind, const CompileRequest& request = {});

/// The shader compiled to validated SPIR-V; nullopt (reported in `diagnostics`) when glslang
/// rejects it. Through `cache` when there is one (default: the request's).
std::optional<std::vector<uint32_t>> compileShader(const glsl::MaterialShader& shader, const CompileRequest& request,
                                                   Diagnostics& diagnostics);
std::optional<std::vector<uint32_t>> compileShader(const glsl::MaterialShader& shader, const CompileRequest& request,
                                                   ShaderCache* cache, Diagnostics& diagnostics,
                                                   ShaderCache::Served* served = nullptr);

}  // namespace mxc
