#pragma once
/// \file
/// The figures of `mxc bench accuracy` (cli/AccuracyBench.cpp measures them) and the three
/// files written from them: a Markdown report, a CSV table and a plot of error against cost.

#include <cmath>
#include <string>
#include <vector>

#include "compiler/common/Accuracy.h"
#include "runtime/ImageIO.h"

namespace mxc::cli {

/// A tier of one material: its errors against the reference tier and its costs. An error is NaN
/// where it is not defined (f cos when every direction pair of the reference is 0, as for a
/// smooth material whose lobes are all delta); the reference tier's errors are its own noise.
struct TierFigures {
  Accuracy tier = Accuracy::Balanced;
  /// Relative RMS error of the directional albedo (R + T, luminance) over the view angles.
  double albedoError = NAN;
  /// Mean absolute error of the directional albedo (R + T) over the view angles and the three
  /// channels: an absolute measure, which a dark material's relative error overstates.
  double albedoMeanAbs = NAN;
  /// RMS error of f cos (luminance) over the direction pairs, over the RMS of the reference's.
  double fcosError = NAN;
  /// RMS error of the rendered image's luminance over the reference's RMS luminance.
  double imageError = NAN;
  double nsPerEval = NAN;   ///< one evaluation of f cos and pdf (reference: of one walk)
  double msPerFrame = NAN;  ///< a frame of the cost image (AccuracyReport::frameSize)
  size_t spirvInstructions = 0;  ///< of the fragment shader
};

/// The reference's own estimates: how many walks or frames it took and their noise.
struct ReferenceFigures {
  uint32_t albedoWalks = 0;  ///< walks per view
  uint32_t evalWalks = 0;    ///< walks per direction pair
  double evalSeconds = 0;    ///< time of the f cos estimate, every pair
  uint32_t imageFrames = 0;  ///< frames (one walk per pixel each)
  double albedoSeconds = 0;  ///< time of the albedo estimate, every view
  double imageSeconds = 0;   ///< time of the reference image
};

struct MaterialFigures {
  std::string name;    ///< as shown in the report
  std::string source;  ///< the document and any --set overrides
  std::vector<TierFigures> tiers;  ///< in the order of kAccuracies; the last is the reference
  ReferenceFigures reference;
  const TierFigures& tier(Accuracy a) const;
};

struct AccuracyReport {
  std::string device;
  std::string command;  ///< the command line that reproduces the report
  std::string date;
  uint32_t views = 0;        ///< view angles of the albedo
  uint32_t pairs = 0;        ///< direction pairs of f cos
  uint32_t imageSize = 0;    ///< the error image's width and height
  uint32_t imageBlocks = 0;  ///< compared as imageBlocks x imageBlocks blocks
  uint32_t tierFrames = 0;   ///< frames of the fast and balanced error images
  uint32_t frameSize = 0;    ///< the cost image's width and height
  std::vector<MaterialFigures> materials;
};

/// The median over the materials of a tier's figure, NaNs left out (NaN when none is left).
double medianOver(const AccuracyReport& report, Accuracy tier, double TierFigures::*figure);

/// The relative noise level the report quotes the reference's time to reach.
constexpr double kStatedNoise = 0.01;

std::string accuracyMarkdown(const AccuracyReport& report);
std::string accuracyCsv(const AccuracyReport& report);
/// Albedo error against frame time, log axes: one point per tier per material, the reference as
/// its noise at its cost. Text drawn with rt::drawText; an error message instead when it fails.
std::variant<rt::RgbaImage, std::string> accuracyPlot(const AccuracyReport& report);

}  // namespace mxc::cli
