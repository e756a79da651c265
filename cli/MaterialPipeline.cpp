#include "cli/MaterialPipeline.h"

#include <cstdio>

#include <fmt/format.h>

#include "cli/ExitCode.h"
#include "compiler/ir/Effects.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/Resolver.h"

namespace mxc::cli {

void addInputOptions(CLI::App& command, MaterialOptions& options) {
  // One value per occurrence: `--set a=1 FILE` must not take FILE as a second override.
  command.add_option("--set", options.set,
                     "Override an input of the shading node: INPUT=VALUE, the value written as in a document "
                     "(--set base_color=0.8,0.2,0.1); repeatable")
      ->type_name("INPUT=VALUE")
      ->allow_extra_args(false);
  command.add_option("--param", options.parameters,
                     "Keep an input of the shading node variable: a uniform of the shader, with the document's (or "
                     "--set's) value as its default; repeatable")
      ->type_name("INPUT")
      ->allow_extra_args(false);
}

bool inputOptions(const MaterialOptions& options, lower::LoweringOptions& lowering) {
  for (const std::string& s : options.set) {
    const size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "error: --set %s: expected INPUT=VALUE\n", s.c_str());
      return false;
    }
    lowering.overrides.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  lowering.parameters = options.parameters;
  return true;
}

void addMaterialOptions(CLI::App& command, MaterialOptions& options) {
  addInputOptions(command, options);
  command.add_option("--material", options.material, "Only the material of this name (default: every material)");
  addLibraryOptions(command, options.libraries);
}

int MaterialPipeline::run(const std::string& file, const MaterialOptions& options) {
  lower::LoweringOptions lowering;
  if (!inputOptions(options, lowering)) return kUsage;
  session_.loadLibraries(options.libraries);
  loader_ = std::make_unique<doc::DocumentLoader>(session_.sources, session_.diagnostics);
  document = session_.diagnostics.hasErrors() ? nullptr : loader_->loadFile(file);
  if (!document) {
    session_.printDiagnostics();
    return kInvalidDocument;
  }
  documentFolder = std::filesystem::absolute(file).parent_path();
  // Built in place (a prvalue initialising the new object is never moved): resolved nodes
  // point at their document's `top` scope, so a ResolvedDocument must not be moved.
  resolved_.reset(new resolve::ResolvedDocument(
      resolve::resolveDocument(*document, session_.libraries.top(), session_.diagnostics)));
  if (!session_.diagnostics.hasErrors()) {
    materials = lower::lowerDocument(*resolved_, lowering, session_.diagnostics);
  }
  session_.printDiagnostics();
  if (session_.diagnostics.hasErrors()) {
    std::fprintf(stderr, "%s: %zu error(s)\n", file.c_str(), session_.diagnostics.errorCount());
    return kInvalidDocument;
  }
  if (!options.material.empty()) {
    std::vector<ir::Material> chosen;
    std::vector<std::string> names;
    for (ir::Material& m : materials) {
      names.push_back(m.name);
      if (m.name == options.material) chosen.push_back(std::move(m));
    }
    if (chosen.empty()) {
      std::fprintf(stderr, "error: %s has no material '%s' (it has: %s)\n", file.c_str(), options.material.c_str(),
                   fmt::format("{}", fmt::join(names, ", ")).c_str());
      return kUsage;
    }
    materials = std::move(chosen);
  }
  if (materials.empty()) {
    std::fprintf(stderr, "error: %s has no material and no surface shader to compile\n", file.c_str());
    return kInvalidDocument;
  }
  for (ir::Material& m : materials) {
    ir::runPasses(m);
    ir::summarizeEffects(m);
  }
  return kOk;
}

std::optional<std::string> MaterialPipeline::checkOutputsAreNotInputs(const OutputSet& outputs) const {
  if (auto error = session_.checkOutputsAreNotSources(outputs)) return error;
  for (const ir::Material& m : materials) {
    for (const ir::ImageFile& image : m.images) {
      std::filesystem::path path = image.path;
      if (path.is_relative()) path = documentFolder / path;
      if (auto error = outputs.checkNotInput(path, "an image file this command reads")) return error;
    }
  }
  return std::nullopt;
}

std::filesystem::path perMaterialPath(const std::filesystem::path& path, const std::string& material, bool several) {
  if (!several) return path;
  std::string safe;
  for (char c : material) safe += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  std::filesystem::path out = path;
  out.replace_filename(fmt::format("{}_{}{}", path.stem().string(), safe, path.extension().string()));
  return out;
}

}  // namespace mxc::cli
