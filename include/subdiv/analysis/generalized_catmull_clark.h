#pragma once
// The closed forms and conditions of Chen and Prautzsch, "Generalized
// Catmull-Clark subdivision" (2012), for comparison with the numerical
// analysis (analyze.h), which reads the same schemes' matrices off their
// stencils:
//   Example 6.2: mu_0(m) and lambda_{2 pi/m}(m) of M_3-bar = B_{alpha,beta} R;
//   Lemma 4.7: the bounds on the spectral radii rho_B, rho_A;
//   Theorem 6.1 and Remark 5.7: when M_n-bar is C1 at valence m
//     (conditions 5.1 and 5.2);
//   Theorem 3.1 and Lemma 3.2: the regular case, the norm of the second
//     difference scheme U_dd against max{(2a + b)/4, 1/2 - (2a + b)/4}.

#include <complex>
#include <string>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// Example 6.2 for U = B_{alpha,beta} R at valence m >= 3: t = 2 alpha(4) +
/// beta(4), c = cos(2 pi / m),
///   mu_0 = (3 alpha(m) + beta(m) + sqrt((3 alpha(m) + beta(m))^2 - 4 t alpha(m))) / 8,
///   lambda = (4 + t + (2 - t) c + sqrt((2 - t)^2 c^2 + 2 (4 + t)(2 - t) c + (4 - t)^2)) / 16.
/// mu_0 is complex when the discriminant is negative.
std::complex<double> gcc_mu0(const SmoothingWeights& weights, int m);
double gcc_lambda(const SmoothingWeights& weights, int m);

/// Lemma 4.7: rho_B <= (1/2)^(floor(n/2) + 1) and rho_A <= (1/4)^(floor(n/2) + 1).
double gcc_rho_b_bound(int degree);
double gcc_rho_a_bound(int degree);

/// What the paper says about M_3-bar at valence m.
struct GccTheorem {
  int valence = 0;
  std::complex<double> mu0;  ///< Example 6.2
  double lambda = 0.0;       ///< lambda_{2 pi/m}, Example 6.2
  double rho_b_bound = 0.0;  ///< Lemma 4.7
  double rho_a_bound = 0.0;
  /// alpha(m) = alpha(4) and beta(m) = beta(4).
  bool constant = false;
  /// (5.1): lambda > max{|mu_0|, rho_B, rho_A}, checked with Lemma 4.7's
  /// bounds for rho_B, rho_A (sufficient); (5.2): lambda > |mu_0|.
  bool condition_5_1 = false;
  bool condition_5_2 = false;
  /// Whether the paper proves C1 there: Theorem 3.3 (m = 4), Theorem 6.1
  /// (constant weights, m >= 5), Remark 5.7 (m = 3 with (5.1), non-constant
  /// weights and m >= 5 with (5.2)).
  bool proves_c1 = false;
  std::string reason;  ///< which statement applies, or which condition fails
};

/// Throws InvalidInputError unless the scheme is a generalized
/// Catmull-Clark scheme of degree 3 and m >= 3.
GccTheorem gcc_theorem(const Scheme& scheme, int m);

/// Lemma 3.2 (c): max{(2 alpha + beta)/4, 1/2 - (2 alpha + beta)/4}, with
/// alpha = alpha(4), beta = beta(4): a bound on |(B_{alpha,beta} R)_dd|.
double gcc_second_difference_bound(const SmoothingWeights& weights);

/// The norm |U_dd| of the second difference scheme of one level of
/// `scheme` on regular quad meshes (Theorem 3.1), computed from the scheme's
/// own stencils on a regular grid: the regular mask a(z1, z2) divided by
/// (1 + z1)^2, (1 + z1)(1 + z2) and (1 + z2)^2, and the largest sum of
/// |weights| over one parity class of each. U is C1 on regular meshes when
/// it is below 1/2. Throws InvalidInputError when the mask does not divide
/// (a scheme without linear precision) or the scheme is not a quad scheme.
double regular_second_difference_norm(const Scheme& scheme);

}  // namespace subdiv
