#pragma once
/// \file
/// The command-line options that choose what to compile (`--set`, `--param`, `--material`,
/// `--library`), turned into a compile request for the compiler (compiler/driver/Compiler.h),
/// whose materials the commands then use.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/OutputSet.h"
#include "cli/Session.h"
#include "compiler/driver/Compiler.h"

namespace mxc::cli {

struct MaterialOptions {
  std::vector<std::string> set;         ///< --set INPUT=VALUE (repeatable)
  std::vector<std::string> parameters;  ///< --param INPUT (repeatable)
  std::string material;                 ///< --material NAME: only this one
  Accuracy accuracy = Accuracy::Balanced;  ///< --accuracy TIER
  int referenceSamples = 0;                ///< --reference-samples N (0: the command's default)
  bool noSpecialize = false;               ///< --no-specialize: the general shader (CompileRequest::specialize)
  bool parameterAll = false;               ///< --param-all: every input of the shading node a uniform
  std::vector<std::string> searchPaths;    ///< --search-path DIR (repeatable): images, meshes
  std::string workingSpace = "lin_rec709";  ///< --working-space NAME (compile): LoweringOptions::workingSpace
  LibraryOptions libraries;
};


/// --set, --param and --material into `request`; false (with the error printed) for a
/// malformed --set.
bool requestInputs(const MaterialOptions& options, CompileRequest& request);

/// A document compiled to IR materials by the compiler, for a command.
class MaterialPipeline {
 public:
  explicit MaterialPipeline(Session& session) : session_(session) {}
  /// Loads the libraries and runs the compiler to the IR stage on `request` (its document, and
  /// the inputs and materials `options` choose). Returns kOk, or the exit code to stop with
  /// (the diagnostics are printed). A document without a material or surface shader is an
  /// error, unless `nothingIsAnError` is false: then kOk with no materials().
  int run(CompileRequest request, const MaterialOptions& options, bool nothingIsAnError = true);
  /// A usage error when an output is a file the command reads: the document, an included
  /// document, a library file, or an image file of a material.
  std::optional<std::string> checkOutputsAreNotInputs(const OutputSet& outputs) const;

  /// Every file the command reads for these materials, as paths that exist: the document, its
  /// includes, library files and the materials' image files (for `compile --depfile`).
  std::vector<std::filesystem::path> inputFiles() const;

  Compiler& compiler() { return *compiler_; }
  /// The materials chosen, after the passes.
  std::vector<ir::Material>& materials() { return compiler_->materials(); }
  std::filesystem::path documentFolder() const { return compiler_->documentFolder(); }

 private:
  /// The materials' image files, relative ones resolved against the document's folder.
  std::vector<std::filesystem::path> imagePaths() const;

  Session& session_;
  std::unique_ptr<Compiler> compiler_;
};

/// A usage error when `-` (standard output) is more than one of `outputs`, or is the output of
/// more than one material (each needs its own file).
std::optional<std::string> checkStandardOutput(const std::vector<std::string>& outputs, size_t materials);

/// A material's name as part of a file name: letters, digits, '-' and '_' kept, anything else '_'.
std::string fileSafeName(const std::string& material);

/// `path` with `_<material>` inserted before its extension, for one output file per material.
std::filesystem::path perMaterialPath(const std::filesystem::path& path, const std::string& material, bool several);

}  // namespace mxc::cli
