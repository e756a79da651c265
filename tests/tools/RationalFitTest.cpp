// The least-squares rational fit behind the fast tier's albedos (tools/RationalFit.h).

#include "tools/RationalFit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mxc::tools {
namespace {

std::vector<FitSample> grid(double (*f)(double, double)) {
  std::vector<FitSample> samples;
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 20; ++j) samples.push_back({i / 20.0, j / 20.0, f(i / 20.0, j / 20.0)});
  }
  return samples;
}

// A rational function of the fit's form is recovered exactly, coefficients included.
TEST(RationalFit, RecoversARationalOfItsForm) {
  // A quartic over a cubic, fitted with a cubic denominator (10 terms): the representation is
  // unique (a full quartic denominator could multiply both by a common linear factor).
  auto f = [](double u, double v) {
    return (0.5 + u - 2.0 * v * v + 0.3 * u * u * v + 0.1 * u * u * v * v) / (1.0 + 0.7 * u * v + 0.2 * v * v * v);
  };
  std::optional<RationalFit> fit = fitRational(grid(f), 10);
  ASSERT_TRUE(fit.has_value());
  EXPECT_LT(fit->maxError, 1e-9);
  EXPECT_NEAR(fit->p[0], 0.5, 1e-7);
  EXPECT_NEAR(fit->p[1], 1.0, 1e-7);
  EXPECT_NEAR(fit->p[5], -2.0, 1e-7);
  EXPECT_NEAR(fit->q[3], 0.7, 1e-7);  // the u v monomial, Q's fifth (its constant is implicit)
  EXPECT_NEAR(fit->q[8], 0.2, 1e-7);
  EXPECT_NEAR(fit->p[12], 0.1, 1e-7);  // u^2 v^2
  for (size_t k = 9; k < fit->q.size(); ++k) EXPECT_EQ(fit->q[k], 0.0);  // the quartic terms of Q are held
  EXPECT_GT(fit->minDenominator, 0.99);
  EXPECT_NEAR((*fit)(0.37, 0.81), f(0.37, 0.81), 1e-9);  // between the samples too
}

// With the denominator held to its constant, the fit is the least-squares quartic polynomial: a
// quartic is exact, and a function it cannot express leaves a residual it reports honestly.
TEST(RationalFit, PolynomialWhenTheDenominatorIsFixed) {
  auto cubic = [](double u, double v) { return 1.0 - u * v + 3.0 * u * u * u - v * v * v * v; };
  std::optional<RationalFit> exact = fitRational(grid(cubic), 1);
  ASSERT_TRUE(exact.has_value());
  EXPECT_LT(exact->maxError, 1e-10);
  for (double q : exact->q) EXPECT_EQ(q, 0.0);
  auto wavy = [](double u, double v) { return std::sin(12.0 * u) * std::cos(9.0 * v); };
  std::optional<RationalFit> rough = fitRational(grid(wavy), 1);
  ASSERT_TRUE(rough.has_value());
  double worst = 0.0;
  for (const FitSample& s : grid(wavy)) worst = std::max(worst, std::abs((*rough)(s.u, s.v) - s.value));
  EXPECT_NEAR(rough->maxError, worst, 1e-12);
  EXPECT_GT(rough->maxError, 0.1);
}

// Weighing the undershot samples more (an expectile fit) moves the fit above the data: the
// largest shortfall of a function the model cannot express falls, at the price of overshoot.
TEST(RationalFit, WeighingUndershootsKeepsTheFitAbove) {
  auto kink = [](double u, double v) { return std::abs(u - 0.37) + 0.5 * std::sqrt(v); };
  const std::vector<FitSample> samples = grid(kink);
  std::optional<RationalFit> plain = fitRational(samples, 1);
  std::optional<RationalFit> above = fitRational(samples, 1, 30, 100.0);
  ASSERT_TRUE(plain.has_value());
  ASSERT_TRUE(above.has_value());
  EXPECT_GT(maxShortfall(*plain, samples), 0.01);
  EXPECT_LT(maxShortfall(*above, samples), 0.5 * maxShortfall(*plain, samples));
  EXPECT_GT(above->meanError, plain->meanError);  // least squares is the best fit without the weights
}

TEST(RationalFit, TooFewSamplesOrADegenerateSetIsRefused) {
  EXPECT_FALSE(fitRational({{0.1, 0.2, 1.0}, {0.3, 0.4, 2.0}}).has_value());
  // Every sample at one point: the monomial columns are dependent.
  std::vector<FitSample> same(50, FitSample{0.5, 0.5, 1.0});
  EXPECT_FALSE(fitRational(same).has_value());
}

}  // namespace
}  // namespace mxc::tools
