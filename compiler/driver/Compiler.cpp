#include "compiler/driver/Compiler.h"

#include <stdexcept>

#include <fmt/format.h>

#include "compiler/driver/ShaderGroups.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/spirv/ModuleCut.h"
#include "compiler/resolve/Resolver.h"

namespace mxc {

Workspace::Workspace() : libraries(sources, diagnostics), loader(sources, diagnostics) {}

bool Workspace::loadLibraries(bool builtin, const std::vector<std::string>& folders) {
  const size_t before = diagnostics.errorCount();
  if (builtin) {
    libraries.addBuiltin();
    libraryInfo.push_back({"builtin", libraries.top().nodeDefCount()});
  }
  for (const std::string& folder : folders) {
    if (libraries.addFolder(folder)) libraryInfo.push_back({folder, libraries.top().nodeDefCount()});
  }
  if (libraries.empty()) diagnostics.error({}, "no node library: --no-builtin needs at least one --library");
  return diagnostics.errorCount() == before;
}

Compiler::Compiler(Workspace& workspace, CompileRequest request) : workspace_(workspace), request_(std::move(request)) {}

const doc::Document* Compiler::document() {
  if (loaded_) return document_;
  loaded_ = true;
  document_ = request_.text ? workspace_.loader.loadText(request_.document.string(), *request_.text)
                            : workspace_.loader.loadFile(request_.document);
  return document_;
}

std::filesystem::path Compiler::documentFolder() const {
  return std::filesystem::absolute(request_.document).parent_path();
}

const resolve::ResolvedDocument* Compiler::resolved() {
  if (resolved_) return resolved_.get();
  const doc::Document* d = document();
  const lib::LibraryStack& libraries = request_.libraries ? *request_.libraries : workspace_.libraries;
  if (!d || libraries.empty()) return nullptr;
  // Built in place (a prvalue initialising the new object is never moved): resolved nodes
  // point at their document's `top` scope, so a ResolvedDocument must not be moved.
  resolved_.reset(new resolve::ResolvedDocument(
      resolve::resolveDocument(*d, libraries.top(), workspace_.diagnostics)));
  return resolved_.get();
}

std::vector<ir::Material>& Compiler::materials() {
  if (lowered_) return materials_;
  lowered_ = true;
  const resolve::ResolvedDocument* r = resolved();
  if (!r || (workspace_.diagnostics.hasErrors() && !request_.partial)) return materials_;
  lower::LoweringOptions lowering = request_.lowering;
  lowering.everyInputVariable = lowering.everyInputVariable || !request_.specialize;
  materials_ = lower::lowerDocument(*r, lowering, workspace_.diagnostics);
  for (const ir::Material& m : materials_) names_.push_back(m.name);
  if (!request_.material.empty()) {
    std::erase_if(materials_, [&](const ir::Material& m) { return m.name != request_.material; });
  }
  lower::checkUserInputs(materials_, lowering, workspace_.diagnostics);
  for (ir::Material& m : materials_) finishMaterial(m, request_);
  return materials_;
}

void finishMaterial(ir::Material& material, const CompileRequest& request) {
  ir::PassContext context;
  context.accuracy = request.accuracy;
  context.keptParameters = request.lowering.parameters;
  context.verify = request.verifyIr;
  ir::runPasses(material, context);
  material.features = ir::computeFeatures(material);
}

glsl::MaterialShader Compiler::shader(const ir::Material& material) const { return shader(material, request_.stage); }

glsl::MaterialShader Compiler::shader(const ir::Material& material, glsl::ShaderKind kind) const {
  return buildShader(material, kind, request_);
}

std::optional<std::vector<uint32_t>> Compiler::spirv(const glsl::MaterialShader& shader, ShaderCache::Served* served) {
  return compileShader(shader, request_, &shaderCache(), workspace_.diagnostics, served);
}

std::optional<target::Translation> Compiler::translate(const std::vector<uint32_t>& words, spirv::Stage stage,
                                                       const std::vector<target::Placement>& placements,
                                                       const std::string& what) {
  std::string error;
  std::optional<target::Translation> out = target::translate(words, stage, request_.target, placements, error);
  if (!out) workspace_.diagnostics.error({}, fmt::format("{}: {}", what, error));
  return out;
}

glsl::MaterialShader buildShader(const ir::Material& material, glsl::ShaderKind kind, const CompileRequest& request) {
  glsl::BuildOptions options;
  options.subgroups = request.target == target::Target::Spirv;
  options.separateSamplers = request.target == target::Target::Wgsl;
  options.expandLibrary = request.expandLibrary;
  options.accuracy = request.accuracy;
  options.referenceSamples = request.referenceSamples;
  options.specialize = request.specialize;
  return glsl::buildMaterialShader(material, kind, options);
}

std::optional<std::vector<uint32_t>> compileShader(const glsl::MaterialShader& shader, const CompileRequest& request,
                                                   Diagnostics& diagnostics) {
  return compileShader(shader, request, request.shaderCache, diagnostics);
}

std::optional<std::vector<uint32_t>> compileShader(const glsl::MaterialShader& shader, const CompileRequest& request,
                                                   ShaderCache* cache, Diagnostics& diagnostics,
                                                   ShaderCache::Served* served) {
  if (served) *served = ShaderCache::Served::Compiled;
  spirv::CompileOptions options;
  options.optimize = request.optimize;
  // A shader built by hand has no code key: it is compiled for itself.
  if (!cache || shader.codeKey.empty()) return spirv::compile(shader.glsl, options, diagnostics);
  // The key holds everything the module depends on: the code and the options.
  return cache->getOrCompile(shaderCacheKey(shader, request), [&]() -> std::optional<std::vector<uint32_t>> {
    std::optional<std::vector<uint32_t>> words = spirv::compile(shader.glsl, options, diagnostics);
    if (!words || options.optimize) return words;
    // In the form of a module cut from a group compile (ShaderGroups.h), so that a material
    // compiled alone and in a batch are the same bytes; a module the cut does not handle is
    // grouped with no other, and stays as glslang wrote it.
    std::string error;
    std::optional<std::vector<uint32_t>> canonical = spirv::cutModule(*words, {}, error);
    return canonical ? canonical : words;
  }, served);
}

}  // namespace mxc
