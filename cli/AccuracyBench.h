#pragma once
/// \file
/// `mxc bench accuracy`: every accuracy tier of a set of materials measured against the
/// reference tier, for its error and its cost, in one run (docs/accuracy-bench.md says what
/// each figure is and how it is measured).

#include <string>
#include <vector>

#include "cli/Harness.h"
#include "cli/Session.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct AccuracyBenchOptions {
  std::vector<std::string> files;  ///< documents (every material of each); empty: the fixed set
  bool withFixedSet = false;       ///< --fixed-set: the fixed set as well as `files`
  std::string corpus;              ///< --corpus: where the fixed set's documents are
  std::string reportDir = "generated/reports";
  /// The reference's estimates are refined (walks or frames x4) until their noise is below half
  /// the smallest error of the other tiers, up to these caps.
  int albedoWalks = 1 << 18;  ///< walks per view
  int evalWalks = 1 << 16;    ///< walks per direction pair
  int imageFrames = 1024;     ///< frames of the reference image
  int tierFrames = 1024;      ///< frames of the fast and balanced images
  int imageSize = 128;        ///< a multiple of 16 (the error is taken over 16 x 16 blocks)
  int frameSize = 512;
  LibraryOptions libraries;
  DeviceOptions device;
};

int runAccuracyBench(const AccuracyBenchOptions& options);

}  // namespace mxc::cli
