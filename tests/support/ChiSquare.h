#pragma once
/// \file
/// Pearson's chi-square test of observed counts against expected counts, as the sampling tests
/// use it: a sampler that draws from another density than the one it reports fails it.

#include <cmath>
#include <vector>

namespace mxc::test {

/// Upper quantile of chi-square with `dof` degrees of freedom at the standard normal quantile z
/// (Wilson & Hilferty 1931: (X / dof)^(1/3) is close to normal).
inline double chiSquareQuantile(double dof, double z) {
  const double v = 2.0 / (9.0 * dof);  // dof > 0
  return dof * std::pow(1.0 - v + z * std::sqrt(v), 3.0);
}

struct PearsonResult {
  double statistic = 0.0;
  int bins = 0;                 ///< bins in the statistic, the pooled one included
  double pooledObserved = 0.0;  ///< the bins expecting fewer than the minimum, together
  double pooledExpected = 0.0;
};

/// Pearson's statistic over the bins expecting at least `minExpected`, the rest pooled into one
/// bin (counted when it expects at least `minExpected` itself).
inline PearsonResult pearson(const std::vector<double>& observed, const std::vector<double>& expected,
                             double minExpected = 20.0) {
  PearsonResult r;
  for (size_t b = 0; b < expected.size() && b < observed.size(); ++b) {
    if (expected[b] < minExpected) {
      r.pooledObserved += observed[b];
      r.pooledExpected += expected[b];
      continue;
    }
    r.statistic += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];  // >= minExpected > 0
    ++r.bins;
  }
  if (r.pooledExpected >= minExpected) {
    r.statistic += (r.pooledObserved - r.pooledExpected) * (r.pooledObserved - r.pooledExpected) / r.pooledExpected;
    ++r.bins;
  }
  return r;
}

}  // namespace mxc::test
