// The measure that judges two renders of a material (runtime/ImageDifference.h): relative where
// bright, absolute where dark, coverage counted, background skipped, NaN a full difference.

#include <gtest/gtest.h>

#include <cmath>

#include "runtime/ImageDifference.h"

namespace mxc::rt {
namespace {

RgbaImage image(std::initializer_list<float> pixels) {
  RgbaImage out;
  out.pixels = pixels;
  out.width = uint32_t(out.pixels.size() / 4);
  out.height = 1;
  return out;
}

TEST(ImageDifference, RelativeWhereBrightAbsoluteWhereDarkAndBackgroundSkipped) {
  const RgbaImage reference = image({2.0f, 0.0f, 0.0f, 1.0f,    // bright: 2.2 is 10% off
                                     0.01f, 0.0f, 0.0f, 1.0f,   // dark: 0.02 is 0.01 / 0.05 = 0.2 off
                                     5.0f, 5.0f, 5.0f, 0.0f});  // background in both: skipped
  const RgbaImage other = image({2.2f, 0.0f, 0.0f, 1.0f, 0.02f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f});
  const ImageDifference d = compareImages(other, reference, 0.15);
  EXPECT_EQ(d.covered, 2u);
  EXPECT_EQ(d.over, 1u);
  EXPECT_NEAR(d.worst, 0.2, 1e-6);
  EXPECT_NEAR(d.mean, 0.15, 1e-6);
  EXPECT_DOUBLE_EQ(d.share(), 0.5);
  EXPECT_EQ(compareImages(reference, reference).over, 0u);
  EXPECT_EQ(compareImages(reference, reference).mean, 0.0);
}

TEST(ImageDifference, CoverageAndNonFiniteValuesCount) {
  const RgbaImage reference = image({0.5f, 0.5f, 0.5f, 1.0f, 0.5f, 0.5f, 0.5f, 1.0f});
  // Same colour, half the coverage; and a NaN in the green channel (std::max alone would drop it).
  const RgbaImage other = image({0.5f, 0.5f, 0.5f, 0.5f, 0.5f, NAN, 0.5f, 1.0f});
  const ImageDifference d = compareImages(other, reference);
  EXPECT_EQ(d.covered, 2u);
  EXPECT_EQ(d.over, 2u);
  EXPECT_DOUBLE_EQ(d.worst, 1.0);
  EXPECT_DOUBLE_EQ(d.mean, 0.75);
  EXPECT_EQ(compareImages(image({}), image({})).covered, 0u);
}

}  // namespace
}  // namespace mxc::rt
