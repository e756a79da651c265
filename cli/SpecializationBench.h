#pragma once
/// \file
/// `mxc bench specialize`: each material's specialized shader against the general one
/// (`--no-specialize`), and against MaterialX's own shader of the document when its GLSL is
/// given, in one run: SPIR-V size, compile time and frame time per scene
/// (generated/reports/specialization.md; docs/specialization.md says what is measured).

#include <string>
#include <vector>

#include "cli/Harness.h"
#include "cli/Session.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct SpecializationBenchOptions {
  std::vector<std::string> files;  ///< documents (every material of each); empty: the fixed set
  std::string corpus;              ///< --corpus: where the fixed set's documents are
  /// --materialx: the manifest tests/bench/materialx_compare.py writes (MaterialX's GLSL per
  /// document); empty: no MaterialX figures.
  std::string materialx;
  std::string reportDir = "generated/reports";
  int size = 256;   ///< width and height of the frame-time images
  int frames = 16;  ///< frames per image (the first is not timed)
  int repeat = 3;   ///< compilations to the SPIR-V module per shader (the median is reported)
  LibraryOptions libraries;
  DeviceOptions device;
};

int runSpecializationBench(const SpecializationBenchOptions& options);

}  // namespace mxc::cli
