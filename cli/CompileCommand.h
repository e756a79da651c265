#pragma once
/// \file
/// `mxc compile`: materials to GLSL and SPIR-V.

#include <string>

#include "cli/MaterialPipeline.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct CompileOptions {
  std::string file;
  std::string output;
  std::string glsl;
  std::string stage = "frag";
  bool optimize = false;
  MaterialOptions materials;
};

int runCompile(const CompileOptions& options);

}  // namespace mxc::cli
