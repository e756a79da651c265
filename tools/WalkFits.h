#pragma once
/// \file
/// What tools/GenerateWalkFits.cpp measures of the reference walk and how it makes the walk's
/// tables of it (generated/tables/mxc_walk_tables.bin; compiler/glsl/WalkTables.h): the
/// measurement counts, the measurements' CSV form, and the fits.

#include <string>
#include <vector>

namespace mxc::tools {

/// The grids are the tables' (compiler/glsl/Bindings.h, WalkTables.h): eta, g and roughness
/// steps; the gloss rows' roughness is the tables' kTableSize columns. Per interface: Gauss-
/// Legendre view cosines and walks per view; per medium: s = k / kMediumSteps for k = 1..
/// kMediumSteps, and walks per estimate.
inline constexpr int kInterfaceViews = 16;
inline constexpr unsigned kInterfaceSamples = 8192;
inline constexpr unsigned kReflectanceSamples = 8192;
inline constexpr int kMediumSteps = 15;
inline constexpr unsigned kMediumSamples = 32768;

/// One estimate: `kind` "interface" or "reflectance" (x: the view cosine, value: the
/// reflectance) or "medium" (x: van de Hulst's s, value: the albedo at normal incidence).
struct WalkMeasurement {
  std::string kind;
  double eta = 1.0;
  double g = 0.0;
  double roughness = 0.0;
  double x = 0.0;
  double value = 0.0;
  double error = 0.0;  ///< the estimate's standard error
};

std::string writeMeasurements(const std::vector<WalkMeasurement>& measurements);
/// Throws std::runtime_error naming the line of a malformed row.
std::vector<WalkMeasurement> readMeasurements(const std::string& text);

/// Gauss-Legendre nodes and weights on [0, 1].
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

/// The walk's table rows (kWalkTableRows x kTableSize RGBA, layout: compiler/glsl/Bindings.h)
/// from the measurements; prints each fit's errors on stderr. Throws std::runtime_error when a
/// grid point is missing or a fit fails.
std::vector<float> walkTableRows(const std::vector<WalkMeasurement>& measurements);

}  // namespace mxc::tools
