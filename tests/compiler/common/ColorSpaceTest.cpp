// The colour-space table (compiler/common/ColorSpace.cpp): matrices derived from the
// primaries agree with the ones MaterialX's cmlib writes (libraries/cmlib/cmlib_ng.mtlx, given
// there row-major for row vectors, so its first three numbers are our first column), and the
// decodings are the standards'.

#include "compiler/common/ColorSpace.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace mxc {
namespace {

void expectColumn(const glm::mat3& m, int column, glm::vec3 expected, float tolerance) {
  for (int row = 0; row < 3; ++row) EXPECT_NEAR(m[column][row], expected[row], tolerance) << "row " << row;
}

TEST(ColorSpace, AcescgToRec709MatchesMaterialXCmlib) {
  // NG_acescg_to_lin_rec709: Bradford-adapted from the ACES white to D65.
  const glm::mat3 m = primariesConversion(Primaries::AP1, Primaries::Rec709);
  expectColumn(m, 0, {1.705050992658f, -0.130256417507f, -0.024003356805f}, 2e-4f);
  expectColumn(m, 1, {-0.621792120657f, 1.140804736575f, -0.128968976065f}, 2e-4f);
  expectColumn(m, 2, {-0.083258872001f, -0.010548319068f, 1.15297233287f}, 2e-4f);
}

TEST(ColorSpace, AdobeRgbAndDisplayP3ToRec709MatchMaterialXCmlib) {
  const glm::mat3 adobe = primariesConversion(Primaries::AdobeRgb, Primaries::Rec709);
  expectColumn(adobe, 0, {1.39835574f, 0.0f, 0.0f}, 2e-4f);
  expectColumn(adobe, 1, {-0.398355744f, 1.0f, -0.0429289893f}, 2e-4f);
  expectColumn(adobe, 2, {0.0f, 0.0f, 1.04292899f}, 2e-4f);
  const glm::mat3 p3 = primariesConversion(Primaries::P3D65, Primaries::Rec709);
  expectColumn(p3, 0, {1.22493029f, -0.04205868f, -0.01964128f}, 2e-4f);
  expectColumn(p3, 1, {-0.22492968f, 1.04205894f, -0.07864794f}, 2e-4f);
}

TEST(ColorSpace, WhiteStaysWhiteAndConversionsInvert) {
  const Primaries all[] = {Primaries::Rec709, Primaries::AP1,    Primaries::AP0,
                           Primaries::AdobeRgb, Primaries::P3D65, Primaries::Rec2020};
  for (Primaries from : all) {
    for (Primaries to : all) {
      const glm::mat3 m = primariesConversion(from, to);
      // RGB (1, 1, 1) is each space's white; with chromatic adaptation, white maps to white.
      const glm::vec3 white = m * glm::vec3(1.0f);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(white[i], 1.0f, 1e-4f);
      const glm::mat3 round = primariesConversion(to, from) * m;
      for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(round[c][r], c == r ? 1.0f : 0.0f, 1e-4f);
      }
    }
  }
}

TEST(ColorSpace, TheDeviceDecodesExactlyTheSrgbEncodedSpaces) {
  // The decodings themselves run in the shader or fold at compile time: tested through the
  // lowering (tests/compiler/lower/StdlibRulesTest.cpp, ColourValuesAreDecoded...).
  EXPECT_TRUE(deviceDecodes("srgb_texture"));
  EXPECT_TRUE(deviceDecodes("srgb_displayp3"));
  EXPECT_TRUE(deviceDecodes("Utility - sRGB - Texture"));
  EXPECT_FALSE(deviceDecodes("g22_rec709"));
  EXPECT_FALSE(deviceDecodes("lin_rec709"));
  EXPECT_FALSE(deviceDecodes("raw"));
  EXPECT_FALSE(deviceDecodes("bogus"));
}

TEST(ColorSpace, NamesAndAliases) {
  EXPECT_EQ(findColorSpace("lin_ap1"), findColorSpace("acescg"));
  EXPECT_EQ(findColorSpace("ACEScg"), findColorSpace("acescg"));
  EXPECT_EQ(findColorSpace("gamma24")->gamma, 2.4f);
  EXPECT_EQ(findColorSpace("Utility - sRGB - Texture")->encoding, Encoding::Srgb);
  EXPECT_EQ(findColorSpace("ACES2065-1")->primaries, Primaries::AP0);
  EXPECT_EQ(findColorSpace("bogus"), nullptr);
  EXPECT_TRUE(isDataSpace("raw"));
  EXPECT_TRUE(isDataSpace("none"));
  EXPECT_FALSE(isDataSpace("lin_rec709"));
  for (std::string_view name : linearColorSpaceNames()) EXPECT_EQ(findColorSpace(name)->encoding, Encoding::Linear);
}

}  // namespace
}  // namespace mxc
