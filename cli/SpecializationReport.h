#pragma once
/// \file
/// The figures of `mxc bench specialize` (cli/SpecializationBench.cpp measures them) and the two
/// files written from them: a Markdown report with the medians and the targets, and a
/// CSV table of every figure.

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace mxc::cli {

/// One shader of a material: its size and its compile time.
struct ShaderFigures {
  size_t instructions = 0;  ///< SPIR-V instructions of the fragment shader, as compiled
  /// After SPIRV-Tools' performance passes (`-O`), per scene of the report: with that scene's
  /// specialization constants fixed first for a specialized shader, as its pipeline has them.
  std::vector<size_t> optimized;
  double toSpirvMs = NAN;  ///< from the document (mxc) or the GLSL (MaterialX) to validated SPIR-V
};

/// One shader rendering one scene.
struct SceneFigures {
  double msPerFrame = NAN;
  double pipelineMs = NAN;  ///< the device's compilation of the pipeline
};

struct VariantFigures {
  ShaderFigures shader;
  std::vector<SceneFigures> scenes;  ///< per scene of the report (NaN where not rendered)
};

struct SpecializationRow {
  std::string name;    ///< the material
  std::string source;  ///< the document's file name
  std::string model;   ///< the shading node's category
  VariantFigures general;      ///< `--no-specialize`: every input a uniform, scene read at run time
  VariantFigures specialized;  ///< mxc's default
  /// Per scene: the mean over covered pixels of the largest channel difference between the
  /// two images, relative to max(general's value, 0.05).
  std::vector<double> imageDifference;
  /// MaterialX's generated shader of the same document (`--materialx`), rendered in the first
  /// scene only: its generator was asked for one directional light and no environment.
  std::optional<VariantFigures> materialx;
};

struct SpecializationReport {
  std::string device;
  std::string command;  ///< the command line that reproduces the report
  std::string date;
  std::string materialxManifest;  ///< empty: no MaterialX figures
  uint32_t size = 0;
  uint32_t frames = 0;
  int repeat = 0;
  /// A scene of the report: its name in the tables, and what is in it.
  struct Scene {
    std::string name;
    std::string definition;
  };
  std::vector<Scene> scenes;  ///< the first is MaterialX's
  std::vector<SpecializationRow> materials;
};

/// The median of the finite values (NaN when there is none).
double medianOf(std::vector<double> values);

/// The report's headline medians, specialized / general: SPIR-V instructions as compiled, and
/// frame time in scene `scene` (NaN where nothing was measured).
double medianInstructionRatio(const SpecializationReport& r);
double medianFrameRatio(const SpecializationReport& r, size_t scene);

/// The targets, checked by the report (docs/specialization.md).
constexpr double kTargetInstructionRatio = 0.5;  ///< median specialized / general instructions
constexpr double kTargetDiffuseRatio = 0.3;      ///< a plain diffuse material, specialized / general
constexpr double kTargetMaterialXFrameRatio = 0.5;  ///< open_pbr_default, key light, mxc / MaterialX
/// The materials the targets name.
inline constexpr const char* kDiffuseMaterials[] = {"open_pbr_gray_card.mtlx", "open_pbr_sand.mtlx"};
inline constexpr const char* kMaterialXFrameTarget = "open_pbr_default.mtlx";

std::string specializationMarkdown(const SpecializationReport& report);
std::string specializationCsv(const SpecializationReport& report);

}  // namespace mxc::cli
