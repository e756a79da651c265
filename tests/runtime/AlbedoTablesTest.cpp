// The albedo tables (runtime/AlbedoTables): the committed ones are what the tables shader
// computes, and they hold their anchors (physics notes 2.2, 2.3).

#include "runtime/AlbedoTables.h"

#include <gtest/gtest.h>

#include <cmath>

#include "compiler/glsl/Bindings.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

// scripts/generate-tables wrote what the shader computes on this device (lavapipe is
// deterministic; the tolerance allows another device's float rounding).
TEST(AlbedoTables, CommittedTablesMatchTheShader) {
  const std::vector<float> computed = rt::AlbedoTables::compute(Device::get().context);
  const std::vector<float>& all = Device::get().tables.values();
  ASSERT_EQ(computed.size(), size_t{glsl::kTableSize} * glsl::kComputedTableHeight * 4);
  ASSERT_GE(all.size(), computed.size());
  const std::vector<float> committed(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(computed.size()));
  float worst = 0.0f;
  for (size_t k = 0; k < computed.size(); ++k) worst = std::max(worst, std::abs(computed[k] - committed[k]));
  EXPECT_LE(worst, 1e-4f) << "run scripts/generate-tables";
}

// The split sum at alpha = 0 is a perfect mirror (A + B = 1), and at alpha = 1, mu = 1 it is the
// GGX anchor 1 - ln 2; the sheen albedo is finite and positive (it may exceed 1 near grazing:
// the lobe is normalised by it). In every dielectric slice R + T is at most 1 and exactly 1 for
// a smooth interface; at eta = 1 nothing is reflected.
TEST(AlbedoTables, HoldTheirAnchors) {
  const std::vector<float>& t = Device::get().tables.values();
  const size_t n = glsl::kTableSize;
  ASSERT_EQ(t.size(), n * glsl::kTableHeight * 4);
  auto at = [&](size_t i, size_t j) { return &t[(j * n + i) * 4]; };
  for (size_t i = 0; i < n; ++i) EXPECT_NEAR(at(i, 0)[0] + at(i, 0)[1], 1.0f, 1e-5f);
  EXPECT_NEAR(at(n - 1, n - 1)[0] + at(n - 1, n - 1)[1], 1.0f - std::log(2.0f), 2e-3f);
  for (size_t j = 0; j < n; ++j) {
    for (size_t i = 0; i < n; ++i) {
      EXPECT_GE(at(i, j)[2], 0.0f);
      EXPECT_TRUE(std::isfinite(at(i, j)[2]));
    }
  }
  for (size_t row = n; row < glsl::kComputedTableHeight; ++row) {
    for (size_t i = 0; i < n; ++i) {
      const float* v = at(i, row);
      EXPECT_LE(v[1], 1.0f + 1e-4f) << "row " << row << ", column " << i;
      EXPECT_LE(v[2], 1.0f + 1e-4f) << "row " << row << ", column " << i;
      // Away from index matching (slice 7 on: eta >= 1.1) and from grazing (mu >= 0.27) single
      // scattering keeps at least 15% of the light, so the multiple-scattering factor 1 / E_RT
      // stays moderate. Near eta = 1 or near grazing, height-correlated masking on both sides of
      // a refraction takes E_RT towards 0 (0.024 at mu = 0.07, alpha = 1); mxc_lobe_ms_scale
      // floors it at 0.05 there.
      if (row >= 8 * n && i >= 16) {
        EXPECT_GT(v[1], 0.15f) << "row " << row << ", column " << i;
        EXPECT_GT(v[2], 0.15f) << "row " << row << ", column " << i;
      }
    }
    if (row % n == 0) {  // alpha = 0: a smooth interface loses nothing
      for (size_t i = 0; i < n; ++i) EXPECT_FLOAT_EQ(at(i, row)[1], 1.0f);
    }
  }
  // The first dielectric slice is eta = 1: no reflection at all.
  for (size_t i = 0; i < n; ++i) EXPECT_NEAR(at(i, n + n / 2)[0], 0.0f, 1e-6f);
  // 2.2: R + T of a rough dielectric at eta 1.5 is below 1 (0.894 at alpha = 1, normal
  // incidence, with separable Smith; the height-correlated refraction, B(1 + Lo, 1 + Li) <=
  // G1(o) G1(i), loses a little more).
  // Slice s has eta = 1 + 2 (s / 31)^2: eta = 1.5 lies between slices 15 and 16.
  const float rt15 = at(n - 1, n * 16 + n - 1)[1], rt16 = at(n - 1, n * 17 + n - 1)[1];
  EXPECT_GT(std::min(rt15, rt16), 0.85f);
  EXPECT_LT(std::max(rt15, rt16), 0.99f);
}

}  // namespace
}  // namespace mxc::test
