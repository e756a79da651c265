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
  std::string environment = "sky";  ///< none, white, sky, or an image file
  float environmentIntensity = 1.0f;
  float environmentRotation = 0.0f;  ///< degrees about +y
  float emissionScale = 1.0f;
  float exposure = 0.0f;
  /// Linear R,G,B; empty: the environment image where there is one, else kDefaultBackground.
  std::string background;
  std::string mesh = "sphere";
  MaterialOptions materials;
  DeviceOptions device;
};

/// The background of 8-bit outputs when the environment is not an image and none is given.
inline constexpr const char* kDefaultBackground = "0.05,0.05,0.05";

int runRender(const RenderOptions& options);

}  // namespace mxc::cli
