#pragma once
/// \file
/// `mxc compile`: materials to GLSL and SPIR-V.

#include <string>
#include <vector>

#include "cli/MaterialPipeline.h"
#include "compiler/glsl/ShaderBuilder.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct CompileOptions {
  std::vector<std::string> files;  ///< documents, folders and scenes; several (or a folder): a batch (cli/CompileBatch.h)
  std::string file;                ///< the one document or scene of a single compile
  std::string output;
  std::string glsl;
  std::string stage = "frag";
  bool optimize = false;
  int jobs = 0;
  std::string tables;  ///< --tables DIR: write the albedo tables the shaders sample  ///< -j: documents compiled at once in a batch (0: one per core)
  MaterialOptions materials;
};

int runCompile(const CompileOptions& options);

/// The shader kind `--stage` names (frag, comp, furnace, sample).
glsl::ShaderKind kindOf(const std::string& stage);

}  // namespace mxc::cli
