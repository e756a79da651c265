#include "tools/RationalFit.h"

#include <algorithm>
#include <cmath>

namespace mxc::tools {

std::array<double, 15> monomials(double u, double v) {
  const double u2 = u * u, v2 = v * v;
  return {1.0, u, v, u2, u * v, v2, u2 * u, u2 * v, u * v2, v2 * v, u2 * u2, u2 * u * v, u2 * v2, u * v2 * v, v2 * v2};
}

double RationalFit::numerator(double u, double v) const {
  const std::array<double, 15> m = monomials(u, v);
  double sum = 0.0;
  for (size_t k = 0; k < m.size(); ++k) sum += p[k] * m[k];
  return sum;
}

double RationalFit::denominator(double u, double v) const {
  const std::array<double, 15> m = monomials(u, v);
  double sum = 1.0;
  for (size_t k = 1; k < m.size(); ++k) sum += q[k - 1] * m[k];
  return sum;
}

namespace {

/// Least squares min |A x - b| for a rows x cols matrix (row-major, rows >= cols) by Householder
/// QR. Nullopt when a column is (numerically) dependent on the others.
std::optional<std::vector<double>> leastSquares(std::vector<double> a, std::vector<double> b, size_t rows, size_t cols) {
  // A column is dependent on the ones before it when what is left of it after their reflections
  // is below 1e-10 of its own length.
  std::vector<double> length(cols, 0.0);
  for (size_t k = 0; k < cols; ++k) {
    for (size_t i = 0; i < rows; ++i) length[k] += a[i * cols + k] * a[i * cols + k];
    length[k] = std::sqrt(length[k]);
  }
  for (size_t k = 0; k < cols; ++k) {
    double norm = 0.0;
    for (size_t i = k; i < rows; ++i) norm += a[i * cols + k] * a[i * cols + k];
    norm = std::sqrt(norm);
    if (norm <= 1e-10 * length[k] || norm < 1e-300) return std::nullopt;
    const double alpha = a[k * cols + k] > 0.0 ? -norm : norm;
    // The Householder vector v = x - alpha e_k, stored in column k from row k on.
    a[k * cols + k] -= alpha;
    double vv = 0.0;
    for (size_t i = k; i < rows; ++i) vv += a[i * cols + k] * a[i * cols + k];
    // vv >= norm^2 > 0 (the sign of alpha is chosen against the pivot): the division below is safe.
    for (size_t j = k + 1; j < cols; ++j) {
      double dot = 0.0;
      for (size_t i = k; i < rows; ++i) dot += a[i * cols + k] * a[i * cols + j];
      const double s = 2.0 * dot / vv;  // vv > 0
      for (size_t i = k; i < rows; ++i) a[i * cols + j] -= s * a[i * cols + k];
    }
    double dot = 0.0;
    for (size_t i = k; i < rows; ++i) dot += a[i * cols + k] * b[i];
    const double s = 2.0 * dot / vv;
    for (size_t i = k; i < rows; ++i) b[i] -= s * a[i * cols + k];
    a[k * cols + k] = alpha;  // R's diagonal
  }
  std::vector<double> x(cols, 0.0);
  for (size_t k = cols; k-- > 0;) {
    double sum = b[k];
    for (size_t j = k + 1; j < cols; ++j) sum -= a[k * cols + j] * x[j];
    if (std::abs(a[k * cols + k]) < 1e-300) return std::nullopt;
    x[k] = sum / a[k * cols + k];  // |R_kk| = the column's norm > 0
  }
  return x;
}

}  // namespace

double maxShortfall(const RationalFit& fit, const std::vector<FitSample>& samples) {
  double worst = 0.0;
  for (const FitSample& s : samples) worst = std::max(worst, s.value - fit(s.u, s.v));
  return worst;
}

std::optional<RationalFit> fitRational(const std::vector<FitSample>& samples, size_t denominatorTerms, int iterations,
                                       double below) {
  const size_t qTerms = std::clamp<size_t>(denominatorTerms, 1, 15) - 1;  // free coefficients of Q
  const size_t cols = 15 + qTerms;
  const size_t rows = samples.size();
  if (rows < cols) return std::nullopt;
  RationalFit fit;
  std::vector<double> weights(rows, 1.0);
  for (int it = 0; it < iterations; ++it) {
    std::vector<double> a(rows * cols), b(rows);
    for (size_t i = 0; i < rows; ++i) {
      const FitSample& s = samples[i];
      const std::array<double, 15> m = monomials(s.u, s.v);
      // P(z) - f Q(z) = 0 with Q = 1 + sum q_k m_k: sum p_k m_k - f sum q_k m_k = f.
      for (size_t k = 0; k < 15; ++k) a[i * cols + k] = weights[i] * m[k];
      for (size_t k = 1; k <= qTerms; ++k) a[i * cols + 14 + k] = -weights[i] * s.value * m[k];
      b[i] = weights[i] * s.value;
    }
    std::optional<std::vector<double>> x = leastSquares(std::move(a), std::move(b), rows, cols);
    if (!x) return std::nullopt;
    std::copy(x->begin(), x->begin() + 15, fit.p.begin());
    fit.q.fill(0.0);
    std::copy(x->begin() + 15, x->end(), fit.q.begin());
    // The next step divides by this step's Q: the weights make the linearised residual the
    // true one at convergence. |Q| is floored so a near-zero Q cannot blow a weight up.
    for (size_t i = 0; i < rows; ++i) {
      const FitSample& s = samples[i];
      weights[i] = 1.0 / std::max(std::abs(fit.denominator(s.u, s.v)), 1e-3);
      if (fit(s.u, s.v) < s.value) weights[i] *= std::sqrt(below);  // squared in the residual: `below` times
    }
  }
  double sum = 0.0;
  for (const FitSample& s : samples) {
    const double e = std::abs(fit(s.u, s.v) - s.value);
    fit.maxError = std::max(fit.maxError, e);
    sum += e;
  }
  fit.meanError = sum / static_cast<double>(rows);  // rows >= cols >= 15
  fit.minDenominator = 1e300;
  for (int i = 0; i <= 100; ++i) {
    for (int j = 0; j <= 100; ++j) fit.minDenominator = std::min(fit.minDenominator, fit.denominator(i / 100.0, j / 100.0));
  }
  return fit;
}

}  // namespace mxc::tools
