#include "cli/MaterialPipeline.h"

#include <chrono>
#include <cstdio>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/ExitCode.h"
#include "cli/SearchPaths.h"
#include "cli/Verbosity.h"

namespace mxc::cli {


bool requestInputs(const MaterialOptions& options, CompileRequest& request) {
  for (const std::string& s : options.set) {
    const size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "error: --set %s: expected INPUT=VALUE\n", s.c_str());
      return false;
    }
    request.lowering.overrides.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  request.lowering.parameters = options.parameters;
  // --param-all: every input with a value a uniform, as a general-purpose generator makes them;
  // the code is still only what the material's structure needs (unlike --no-specialize, which
  // also compiles in every effect of the shading model).
  request.lowering.everyInputVariable = options.parameterAll;
  request.lowering.imageSearchPaths = searchPaths(options.searchPaths);
  request.lowering.workingSpace = options.workingSpace;
  request.material = options.material;
  request.accuracy = options.accuracy;
  request.specialize = !options.noSpecialize;
  if (options.referenceSamples > 0) request.referenceSamples = options.referenceSamples;
  return true;
}


int MaterialPipeline::run(CompileRequest request, const MaterialOptions& options, bool nothingIsAnError) {
  if (!requestInputs(options, request)) return kUsage;
  const std::string file = request.document.string();
  // Libraries loaded once for many documents (a batch) are used as they are.
  const bool libraries = request.libraries != nullptr || session_.loadLibraries(options.libraries);
  compiler_ = std::make_unique<Compiler>(session_.workspace, std::move(request));
  auto start = std::chrono::steady_clock::now();
  if (libraries && compiler_->document()) detail("{} read in {:.1f} ms", file, millisecondsSince(start));
  if (!libraries || !compiler_->document()) {
    session_.printDiagnostics();
    return kInvalidDocument;
  }
  start = std::chrono::steady_clock::now();
  compiler_->materials();
  if (verbose()) {
    std::vector<std::string> names;
    for (const ir::Material& m : compiler_->materials()) names.push_back(fmt::format("{} (<{}>)", m.name, m.shader));
    detail("resolved and lowered in {:.1f} ms: {}", millisecondsSince(start),
           names.empty() ? std::string("no material") : fmt::format("{}", fmt::join(names, ", ")));
  }
  session_.printDiagnostics();
  if (session_.workspace.diagnostics.hasErrors()) {
    session_.printLine(fmt::format("{}: {} error(s)", file, session_.workspace.diagnostics.errorCount()));
    return kInvalidDocument;
  }
  if (!options.material.empty() && compiler_->materials().empty() && !compiler_->materialNames().empty()) {
    session_.printLine(fmt::format("error: {} has no material '{}' (it has: {})", file, options.material,
                                   fmt::join(compiler_->materialNames(), ", ")));
    return kUsage;
  }
  if (compiler_->materials().empty() && nothingIsAnError) {
    session_.printLine(fmt::format("error: {} has no material and no surface shader to compile", file));
    return kInvalidDocument;
  }
  return kOk;
}

std::vector<std::filesystem::path> MaterialPipeline::imagePaths() const {
  std::vector<std::filesystem::path> out;
  for (const ir::Material& m : compiler_->materials()) {
    for (const ir::ImageFile& image : m.images) {
      std::filesystem::path path = image.path;
      if (path.is_relative()) path = compiler_->documentFolder() / path;
      out.push_back(std::move(path));
    }
  }
  return out;
}

std::optional<std::string> MaterialPipeline::checkOutputsAreNotInputs(const OutputSet& outputs) const {
  if (auto error = session_.checkOutputsAreNotSources(outputs)) return error;
  for (const std::filesystem::path& path : imagePaths()) {
    if (auto error = outputs.checkNotInput(path, "an image file this command reads")) return error;
  }
  return std::nullopt;
}

std::vector<std::filesystem::path> MaterialPipeline::inputFiles() const {
  std::vector<std::filesystem::path> out;
  std::error_code error;
  // The built-in library's texts are not files: only paths that exist are kept.
  for (const auto& file : session_.workspace.sources.files()) {
    if (std::filesystem::is_regular_file(file->path(), error)) out.emplace_back(file->path());
  }
  for (const std::filesystem::path& path : imagePaths()) {
    if (std::filesystem::is_regular_file(path, error)) out.push_back(path.lexically_normal());
  }
  return out;
}

std::optional<std::string> checkStandardOutput(const std::vector<std::string>& outputs, size_t materials) {
  size_t toStdout = 0;
  for (const std::string& o : outputs) toStdout += o == "-" ? 1 : 0;
  if (toStdout > 1) return "-o -: standard output can take one output";
  if (toStdout == 1 && materials > 1) {
    return fmt::format("-o -: standard output takes one material's output, and there are {}: choose one with --material",
                       materials);
  }
  return std::nullopt;
}

std::string fileSafeName(const std::string& material) {
  std::string safe;
  for (char c : material) safe += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return safe;
}

std::filesystem::path perMaterialPath(const std::filesystem::path& path, const std::string& material, bool several) {
  // A folder (`-o dir/`) is no file name to derive names from: kept, so that it is refused as
  // it is for one material ("it is a directory"), not turned into dir/_A.
  std::error_code ec;
  if (!several || path == "-" || !path.has_filename() || std::filesystem::is_directory(path, ec)) return path;
  std::filesystem::path out = path;
  out.replace_filename(fmt::format("{}_{}{}", path.stem().string(), fileSafeName(material), path.extension().string()));
  return out;
}

}  // namespace mxc::cli
