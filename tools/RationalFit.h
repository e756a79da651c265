#pragma once
/// \file
/// Least-squares fits of a rational function of two variables u, v in [0, 1], P(u, v) / Q(u, v) with P and Q
/// cubic (10 monomials each, Q's constant term 1), to tabulated samples: the fast tier's
/// analytic albedos (tools/GenerateTables.cpp). The monomial order is the one the GLSL
/// evaluator uses (mxc_fit_eval in compiler/glsl/library/mxc_lobes.glsl):
/// 1, u, v, u^2, u v, v^2, u^3, u^2 v, u v^2, v^3, u^4, u^3 v, u^2 v^2, u v^3, v^4.

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mxc::tools {

struct FitSample {
  double u = 0.0;
  double v = 0.0;
  double value = 0.0;
};

struct RationalFit {
  std::array<double, 15> p{};
  std::array<double, 14> q{};  ///< Q's coefficients of the monomials 1..14 (its constant is 1)
  double maxError = 0.0;      ///< over the samples, absolute
  double meanError = 0.0;
  double minDenominator = 0.0;  ///< of Q over [0, 1]^2 (a 101 x 101 grid)

  double numerator(double u, double v) const;
  double denominator(double u, double v) const;
  double operator()(double u, double v) const { return numerator(u, v) / denominator(u, v); }
};

/// The monomials at (u, v), in the evaluator's order.
std::array<double, 15> monomials(double u, double v);

/// Fits by Sanathanan-Koerner iteration: each step solves the linear least-squares problem
/// min sum ((P - f Q) / Q_previous)^2 (Householder QR), which converges to the rational
/// least-squares fit. Nullopt when the system is singular (fewer samples than coefficients, or
/// samples that cannot tell the monomials apart).
/// `denominatorTerms` (1 to 15) of Q's monomials are free (the others 0): fewer keep Q away from
/// zero where a full quartic would put a pole inside the square.
/// `below` > 1 weighs the samples the previous step fitted from below that many times more
/// (asymmetric least squares, an expectile fit): the fit then errs upwards, where an albedo
/// that is too high only loses energy.
std::optional<RationalFit> fitRational(const std::vector<FitSample>& samples, size_t denominatorTerms = 15,
                                       int iterations = 30, double below = 1.0);
/// The largest amount by which the fit falls below a sample (0 when it never does).
double maxShortfall(const RationalFit& fit, const std::vector<FitSample>& samples);

}  // namespace mxc::tools
