#pragma once
/// \file
/// `mxc render`: materials on a sphere (or a plane, or an OBJ mesh) to EXR or PNG.

#include <string>
#include <vector>

#include "cli/Harness.h"
#include "cli/MaterialPipeline.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct RenderOptions {
  std::string file;
  std::vector<std::string> outputs;
  int size = 512;
  int spp = 64;
  std::vector<std::string> lights;
  std::string environment = "sky";
  float environmentIntensity = 1.0f;
  float emissionScale = 1.0f;
  float exposure = 0.0f;
  std::string background = "0.05,0.05,0.05";
  std::string mesh = "sphere";
  MaterialOptions materials;
  DeviceOptions device;
};

int runRender(const RenderOptions& options);

}  // namespace mxc::cli
