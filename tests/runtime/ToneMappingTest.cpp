// The tone curves of 8-bit outputs (runtime/ToneMapping.h).

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "runtime/ToneMapping.h"

namespace mxc::test {
namespace {

using rt::ToneMapping;

TEST(ToneMapping, NamesRoundTrip) {
  for (ToneMapping tone : {ToneMapping::None, ToneMapping::AcesFit, ToneMapping::PbrNeutral}) {
    EXPECT_EQ(rt::parseToneMapping(rt::toneMappingName(tone)), tone);
  }
  EXPECT_FALSE(rt::parseToneMapping("filmic"));
}

TEST(ToneMapping, PbrNeutralKeepsColoursBelowItsShoulder) {
  // Above the toe (min channel >= 0.08) only the constant offset 0.04 is taken.
  const glm::vec3 out = rt::pbrNeutral({0.5f, 0.3f, 0.2f});
  EXPECT_NEAR(out.r, 0.46f, 1e-6f);
  EXPECT_NEAR(out.g, 0.26f, 1e-6f);
  EXPECT_NEAR(out.b, 0.16f, 1e-6f);
  // In the toe the offset x - 6.25 x^2 meets 0.04 at x = 0.08, continuously.
  const float below = rt::pbrNeutral(glm::vec3(0.08f - 1e-4f)).r, above = rt::pbrNeutral(glm::vec3(0.08f + 1e-4f)).r;
  EXPECT_NEAR(below, above, 3e-4f);
  EXPECT_EQ(rt::pbrNeutral(glm::vec3(0.0f)), glm::vec3(0.0f));
}

TEST(ToneMapping, CurvesAreMonotoneBoundedAndContinuous) {
  for (ToneMapping tone : {ToneMapping::None, ToneMapping::AcesFit, ToneMapping::PbrNeutral}) {
    float previous = 0.0f;
    for (int i = 0; i <= 4000; ++i) {
      const float x = float(i) * 0.005f;  // 0 to 20, through the shoulders
      const float y = rt::applyToneMapping(tone, glm::vec3(x)).g;
      ASSERT_GE(y, previous - 1e-6f) << rt::toneMappingName(tone) << " at " << x;
      ASSERT_LE(y - previous, 0.02f) << rt::toneMappingName(tone) << " jumps at " << x;
      ASSERT_LE(y, 1.0f);
      previous = y;
    }
  }
  // The filmic and neutral curves approach white; none clips at 1.
  EXPECT_GT(rt::applyToneMapping(ToneMapping::AcesFit, glm::vec3(1000.0f)).r, 0.999f);
  EXPECT_GT(rt::applyToneMapping(ToneMapping::PbrNeutral, glm::vec3(1000.0f)).r, 0.999f);
  EXPECT_EQ(rt::applyToneMapping(ToneMapping::None, glm::vec3(0.3f, 2.0f, -1.0f)), glm::vec3(0.3f, 1.0f, 0.0f));
}

TEST(ToneMapping, HugeInfiniteAndNaNRadianceGiveDisplayValuesInTheUnitRange) {
  // A 3e38 environment texel rendered a 1.2e35 pixel: ACES's x * x overflowed to inf / inf, and
  // the PNG held NaN with exit 0. Huge and infinite radiance is white, NaN black.
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (ToneMapping tone : {ToneMapping::None, ToneMapping::AcesFit, ToneMapping::PbrNeutral}) {
    for (float huge : {1e19f, 1.2e35f, 3.4e38f, inf}) {
      const glm::vec3 y = rt::applyToneMapping(tone, glm::vec3(huge, huge, 0.5f * huge));
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(y[c], 0.999f) << rt::toneMappingName(tone) << " at " << huge;
        EXPECT_LE(y[c], 1.0f) << rt::toneMappingName(tone) << " at " << huge;
      }
    }
    // (With an infinite channel beside it, PBR Neutral's desaturation would rightly whiten it.)
    const glm::vec3 y = rt::applyToneMapping(tone, glm::vec3(nan, 0.5f, 0.25f));
    EXPECT_EQ(y.r, 0.0f) << rt::toneMappingName(tone);
    EXPECT_TRUE(y.g > 0.0f && y.g < 1.0f && y.b > 0.0f && y.b < 1.0f) << rt::toneMappingName(tone);
  }
}

TEST(ToneMapping, PbrNeutralKeepsTheOrderOfChannelsInItsShoulder) {
  // A bright orange: compressed and desaturated towards white, never reordered.
  const glm::vec3 out = rt::pbrNeutral({4.0f, 2.0f, 0.5f});
  EXPECT_GT(out.r, out.g);
  EXPECT_GT(out.g, out.b);
  EXPECT_LE(out.r, 1.0f);
}

}  // namespace
}  // namespace mxc::test
