#pragma once
/// \file
/// `mxc inspect`: what a document holds, resolved against the node libraries.

#include <string>

#include "cli/MaterialPipeline.h"
#include "cli/Session.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct InspectOptions {
  std::string file;
  bool json = false;
  bool dot = false;
  std::string output;
  bool partial = false;
  bool ir = false;
  bool shadingModelGraphs = false;
  bool effects = false;  ///< --effects: what each material's shader simulates and why (cli/InspectEffects.cpp)
  MaterialOptions inputs;  ///< --set and --param, for --ir
  LibraryOptions libraries;
};

int runInspect(const InspectOptions& options);
/// `inspect --effects DOC|SCENE`.
int runInspectEffects(const InspectOptions& options);

}  // namespace mxc::cli
