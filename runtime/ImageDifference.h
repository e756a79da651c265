#pragma once
/// \file
/// How far one render is from another: the measure with which the specialization proof
/// (tests/corpus/SpecializationTest.cpp, tests/cli/SceneSpecializationTest.cpp) and
/// `mxc bench specialize` judge two shaders' images of the same material.

#include <cstddef>

#include "runtime/ImageIO.h"

namespace mxc::rt {

/// Per pixel that either image covers (alpha > 0): the largest of the coverage difference and of
/// each channel's difference relative to max(|reference|, 0.05), so dark pixels are judged in
/// absolute terms and bright ones in relative terms; a pixel with a NaN or infinite value counts
/// as a difference of 1.
struct ImageDifference {
  size_t covered = 0;  ///< pixels either image covers
  size_t over = 0;     ///< of those, pixels whose difference exceeds the threshold
  double mean = 0.0;   ///< the mean difference over the covered pixels (0 when none)
  double worst = 0.0;  ///< the largest
  /// over / covered (0 when none is covered).
  double share() const { return covered ? double(over) / double(covered) : 0.0; }
};

/// `image` against `reference` (the same size; pixels beyond the smaller one are not compared).
ImageDifference compareImages(const RgbaImage& image, const RgbaImage& reference, double threshold = 1e-3);

}  // namespace mxc::rt
