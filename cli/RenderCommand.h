#pragma once
/// \file
/// `mxc render`: materials on a mesh (a sphere by default, MaterialX's shader ball, a glTF or
/// OBJ file) to EXR or PNG.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cli/Harness.h"
#include "cli/MaterialPipeline.h"

namespace mxc::cli {

/// The options of the command (cli/CommandLine.cpp defines them).
struct RenderOptions {
  std::string file;
  std::vector<std::string> outputs;
  std::string size = "512";  ///< N or WxH
  int spp = 64;
  std::vector<std::string> lights;
  std::string environment = "sky";  ///< none, white, sky, or an image file
  float environmentIntensity = 1.0f;
  float environmentRotation = 0.0f;  ///< degrees about +y
  float emissionScale = 1.0f;
  float exposure = 0.0f;
  std::string format;  ///< --format: the image format (an extension: png, exr, ...) of `-o -`
  std::string toneMapping = "aces";  ///< none, aces, neutral (runtime/ToneMapping.h)
  /// Linear R,G,B; empty: the environment image where there is one, else kDefaultBackground.
  std::string background;
  std::string mesh = "sphere";  ///< cli/MeshArgument.h
  /// A look of the document: one image of its assignments to the mesh's parts (or the mesh).
  std::string look;
  /// X,Y,Z; empty: framed from the mesh's bounds (runtime/Camera.h).
  std::string cameraPosition;
  std::string cameraTarget;  ///< X,Y,Z; empty: the centre of the mesh's bounds
  std::string cameraUp;      ///< X,Y,Z; empty: +y
  float fovDegrees = 45.0f;  ///< vertical
  MaterialOptions materials;
  DeviceOptions device;
  /// The long names of the options given on the command line ("--size"), so that a scene's
  /// own settings give way only to those.
  std::vector<std::string> explicitOptions;
};

/// The background of 8-bit outputs when the environment is not an image and none is given.
inline constexpr const char* kDefaultBackground = "0.05,0.05,0.05";

/// `mxc render`: a document's materials, or a scene file (cli/Scene.h) when `file` is one.
int runRender(const RenderOptions& options);

/// `mxc render SCENE.json` (cli/SceneRender.cpp).
int runSceneRender(const RenderOptions& options);

struct Scene;
struct MeshChoice;
/// Renders `scene` (read from a file, or made from the command line) to the options' outputs;
/// `meshes` holds meshes already loaded, by the scene's mesh strings.
int renderSceneData(const Scene& scene, const RenderOptions& options, std::map<std::string, MeshChoice> meshes);

/// "N" or "WxH", each from 8 to 8192; false otherwise.
bool parseRenderSize(const std::string& text, uint32_t& width, uint32_t& height);

}  // namespace mxc::cli
