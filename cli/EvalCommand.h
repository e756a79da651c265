#pragma once
/// \file
/// `mxc eval` (f cos for direction pairs) and `mxc furnace` (directional albedo), on the device.

#include <string>

#include "cli/Harness.h"
#include "cli/MaterialPipeline.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct EvalOptions {
  std::string file;
  std::string dirs;
  std::string output;
  MaterialOptions materials;
  DeviceOptions device;
};
/// The options of the command (cli/CommandLine.cpp defines them).
struct FurnaceOptions {
  std::string file;
  int angles = 8;
  int samples = 65536;
  int seed = 1;
  std::string output;
  MaterialOptions materials;
  DeviceOptions device;
};

int runEval(const EvalOptions& options);
int runFurnace(const FurnaceOptions& options);

}  // namespace mxc::cli
