#pragma once
/// \file
/// What the commands that compile materials share: load, resolve, lower (with `--set` and
/// `--param`), run the passes, and pick the materials a user asked for.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/OutputSet.h"
#include "cli/Session.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/ir/Material.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/ResolvedGraph.h"

namespace mxc::cli {

struct MaterialOptions {
  std::vector<std::string> set;         ///< --set INPUT=VALUE (repeatable)
  std::vector<std::string> parameters;  ///< --param INPUT (repeatable)
  std::string material;                 ///< --material NAME: only this one
  LibraryOptions libraries;
};

void addMaterialOptions(CLI::App& command, MaterialOptions& options);
/// Only --set and --param (for commands that have no --material).
void addInputOptions(CLI::App& command, MaterialOptions& options);

/// --set and --param as lowering options; false (with the error printed) for a malformed --set.
bool inputOptions(const MaterialOptions& options, lower::LoweringOptions& lowering);

/// A document lowered to IR materials after the passes. Keeps the document alive (the IR's
/// origins point into it).
class MaterialPipeline {
 public:
  explicit MaterialPipeline(Session& session) : session_(session) {}
  /// Runs the front end. Returns kOk, or the exit code to stop with (the diagnostics are printed).
  int run(const std::string& file, const MaterialOptions& options);
  /// A usage error when an output is a file the command reads: the document, an included
  /// document, a library file, or an image file of a material.
  std::optional<std::string> checkOutputsAreNotInputs(const OutputSet& outputs) const;

  std::vector<ir::Material> materials;
  /// The folder relative image paths are resolved from (the document's).
  std::filesystem::path documentFolder;
  const doc::Document* document = nullptr;

 private:
  Session& session_;
  std::unique_ptr<doc::DocumentLoader> loader_;
  std::unique_ptr<resolve::ResolvedDocument> resolved_;
};

/// `path` with `_<material>` inserted before its extension, for one output file per material.
std::filesystem::path perMaterialPath(const std::filesystem::path& path, const std::string& material, bool several);

}  // namespace mxc::cli
