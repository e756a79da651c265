#pragma once
/// \file
/// `mxc compile`: materials to GLSL and SPIR-V.

#include <string>
#include <vector>

#include "cli/MaterialPipeline.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/target/Target.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct CompileOptions {
  std::vector<std::string> files;  ///< documents, folders and scenes; several (or a folder): a batch (cli/CompileBatch.h)
  std::string file;                ///< the one document or scene of a single compile
  std::string output;
  std::string glsl;
  std::string stage = "frag";
  bool optimize = false;
  int jobs = 0;        ///< -j: documents compiled at once in a batch (0: one per core)
  std::string tables;  ///< --tables DIR: write the albedo tables the shaders sample
  std::string depfile;       ///< --depfile FILE: the outputs' dependencies, as a Makefile rule
  bool listOutputs = false;  ///< --list-outputs: print the files that would be written, write none
  std::string target;  ///< --target as given (empty: from -o's extension, else SPIR-V)
  /// The language -o is written in: --target, else the one -o's extension names, else SPIR-V
  /// (set by runCompile).
  target::Target resolvedTarget = target::Target::Spirv;
  MaterialOptions materials;
};

int runCompile(const CompileOptions& options);

/// The shader kind `--stage` names (frag, comp, furnace, sample).
glsl::ShaderKind kindOf(const std::string& stage);

}  // namespace mxc::cli
