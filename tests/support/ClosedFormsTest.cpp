// The closed forms the physical tests compare against (support/ClosedForms.h), each checked
// against values published or derived independently.

#include "support/ClosedForms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mxc::test::closed {
namespace {

// Physics notes 2.3: F0 = ((n - 1) / (n + 1))^2, the hemispherical averages E_F(1.5) = 0.09178
// and E_F(1.33) = 0.06593, and the identity E_F(1 / n) = 1 - (1 - E_F(n)) / n^2.
TEST(ClosedForms, FresnelAnchors) {
  EXPECT_NEAR(fresnel(1.0, 1.5), 0.04, 1e-12);
  EXPECT_NEAR(fresnel(1.0, 2.0), 1.0 / 9.0, 1e-12);
  EXPECT_EQ(fresnel(0.3, 1.0 / 1.5), 1.0);  // beyond the critical angle (sin 0.954 > 1 / 1.5)
  EXPECT_NEAR(fresnelAverage(1.5), 0.09178, 2e-5);
  EXPECT_NEAR(fresnelAverage(1.33), 0.06593, 2e-5);
  for (double n : {1.2, 1.5, 2.0}) {
    EXPECT_NEAR(fresnelAverage(1.0 / n), 1.0 - (1.0 - fresnelAverage(n)) / (n * n), 2e-5) << n;
  }
}

// Physics notes 2.9: rho = 0.5 under eta = 1.5 at normal incidence gives 0.316; a white base
// loses nothing at any angle.
TEST(ClosedForms, InterfacedLambertian) {
  EXPECT_NEAR(interfacedLambertian(1.0, 0.5, 1.5), 0.31607, 5e-5);
  for (double mu : {1.0, 0.5, 0.1}) EXPECT_NEAR(interfacedLambertian(mu, 1.0, 1.5), 1.0, 1e-9) << mu;
  EXPECT_LT(interfacedLambertian(0.5, 0.2, 1.5), interfacedLambertian(0.5, 0.8, 1.5));
}

TEST(ClosedForms, GaussLegendreIntegratesPolynomialsExactly) {
  std::vector<double> x, w;
  gaussLegendre(64, x, w);
  for (int k : {0, 1, 7, 127}) {  // exact up to degree 2n - 1 = 127
    double sum = 0.0;
    for (size_t i = 0; i < x.size(); ++i) sum += w[i] * std::pow(x[i], k);
    EXPECT_NEAR(sum, 1.0 / (k + 1), 1e-13) << "x^" << k;
  }
}

// The H-function's moments (Chandrasekhar 1960, ch. V): integral_0^1 H dmu = 2 (1 - sqrt(1 - omega)) / omega,
// so 2 in the conservative case, where also integral_0^1 H mu dmu = 2 / sqrt(3); H(0) = 1, and
// the conservative H(1) = 2.9078 of Chandrasekhar's table.
TEST(ClosedForms, ChandrasekharH) {
  std::vector<double> x, w;
  gaussLegendre(64, x, w);
  for (double omega : {0.3, 0.8, 0.99, 1.0}) {
    double h0 = 0.0, h1 = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
      const double h = chandrasekharH(omega, x[i]);
      h0 += w[i] * h;
      h1 += w[i] * h * x[i];
    }
    EXPECT_NEAR(h0, 2.0 * (1.0 - std::sqrt(1.0 - omega)) / omega, 1e-6) << omega;
    if (omega == 1.0) {
      EXPECT_NEAR(h1, 2.0 / std::sqrt(3.0), 1e-6);
    }
    EXPECT_NEAR(chandrasekharH(omega, 0.0), 1.0, 1e-12) << omega;
  }
  EXPECT_NEAR(chandrasekharH(1.0, 1.0), 2.9078, 1e-4);
  // The albedo of a semi-infinite medium: 1 without absorption, lower with it, and higher at
  // grazing incidence, where light scatters nearer the surface.
  EXPECT_NEAR(semiInfiniteAlbedo(1.0, 0.5), 1.0, 1e-12);
  EXPECT_LT(semiInfiniteAlbedo(0.9, 1.0), semiInfiniteAlbedo(0.9, 0.1));
  EXPECT_GT(semiInfiniteAlbedo(0.9, 1.0), 0.0);
}

}  // namespace
}  // namespace mxc::test::closed
