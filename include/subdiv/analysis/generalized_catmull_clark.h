#pragma once
/// \file
/// The closed forms and conditions of Chen and Prautzsch, "Generalized
/// Catmull-Clark subdivision" (2012), for comparison with the numerical
/// analysis (analyze.h), which reads the same schemes' matrices off their
/// stencils:
/// - Example 6.2: mu_0(m) and lambda_{2 pi/m}(m) of M_3-bar = B_{alpha,beta} R;
/// - Lemma 4.7: the bounds on the spectral radii rho_B, rho_A;
/// - Theorem 6.1 and Remark 5.7: when M_n-bar is C1 at valence m
///     (conditions 5.1 and 5.2);
/// - Theorem 3.1 and Lemma 3.2: the regular case, the norm of the second
///     difference scheme U_dd against max{(2a + b)/4, 1/2 - (2a + b)/4}.

#include <complex>
#include <string>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// Example 6.2's mu_0(m) for U = B_{alpha,beta} R at valence m >= 3, complex
/// when the discriminant is negative. With t = 2 alpha(4) + beta(4):
///
///     mu_0 = (3 alpha(m) + beta(m) + sqrt((3 alpha(m) + beta(m))^2 - 4 t alpha(m))) / 8
///
/// \param weights The smoothing operator's weights alpha(m), beta(m).
/// \param m The valence.
/// \return mu_0(m).
/// \pre \p m >= 3.
std::complex<double> gcc_mu0(const SmoothingWeights& weights, int m) noexcept;
/// Example 6.2's lambda_{2 pi/m}(m) for U = B_{alpha,beta} R at valence m >= 3.
/// With t = 2 alpha(4) + beta(4) and c = cos(2 pi / m):
///
///     lambda = (4 + t + (2 - t) c + sqrt((2 - t)^2 c^2 + 2 (4 + t)(2 - t) c + (4 - t)^2)) / 16
///
/// \param weights The smoothing operator's weights (only alpha(4), beta(4) are read).
/// \param m The valence.
/// \return lambda_{2 pi/m}(m).
/// \pre \p m >= 3.
double gcc_lambda(const SmoothingWeights& weights, int m) noexcept;

/// Lemma 4.7's bound rho_B <= (1/2)^(floor(n/2) + 1).
/// \param degree The degree n of M_n-bar.
/// \return (1/2)^(floor(n/2) + 1).
double gcc_rho_b_bound(int degree) noexcept;
/// Lemma 4.7's bound rho_A <= (1/4)^(floor(n/2) + 1).
/// \param degree The degree n of M_n-bar.
/// \return (1/4)^(floor(n/2) + 1).
double gcc_rho_a_bound(int degree) noexcept;

/// What the paper says about M_3-bar at valence m.
struct GccTheorem {
  int valence = 0;           ///< m
  std::complex<double> mu0;  ///< Example 6.2
  double lambda = 0.0;       ///< lambda_{2 pi/m}, Example 6.2
  double rho_b_bound = 0.0;  ///< Lemma 4.7's bound on rho_B
  double rho_a_bound = 0.0;  ///< Lemma 4.7's bound on rho_A
  /// alpha(m) = alpha(4) and beta(m) = beta(4).
  bool constant = false;
  /// (5.1): lambda > max{|mu_0|, rho_B, rho_A}, checked with Lemma 4.7's
  /// bounds for rho_B, rho_A (sufficient).
  bool condition_5_1 = false;
  /// (5.2): lambda > |mu_0|.
  bool condition_5_2 = false;
  /// Whether the paper proves C1 there: Theorem 3.3 (m = 4), Theorem 6.1
  /// (constant weights, m >= 5), Remark 5.7 (m = 3 with (5.1), non-constant
  /// weights and m >= 5 with (5.2)).
  bool proves_c1 = false;
  std::string reason;  ///< which statement applies, or which condition fails
};

/// The closed forms and the paper's conditions for \p scheme, M_3-bar with
/// its one smoothing operator, at valence \p m.
/// \param scheme A generalized Catmull-Clark scheme of degree 3.
/// \param m The valence, at least 3.
/// \return The closed forms, the conditions and whether the paper proves C1.
/// \throws InvalidInputError unless \p scheme is a generalized Catmull-Clark
///         scheme of degree 3 with one smoothing operator, or if \p m < 3.
/// \throws std::bad_alloc if memory runs out.
GccTheorem gcc_theorem(const Scheme& scheme, int m);

/// Lemma 3.2 (c): max{(2 alpha + beta)/4, 1/2 - (2 alpha + beta)/4}, with
/// alpha = alpha(4), beta = beta(4): a bound on |(B_{alpha,beta} R)_dd|.
/// \param weights The smoothing operator's weights.
/// \return The bound.
double gcc_second_difference_bound(const SmoothingWeights& weights) noexcept;

/// The norm |U_dd| of the second difference scheme of one level of
/// `scheme` on regular quad meshes (Theorem 3.1), computed from the scheme's
/// own stencils on a regular grid: the regular mask a(z1, z2) divided by
/// (1 + z1)^2, (1 + z1)(1 + z2) and (1 + z2)^2, and the largest sum of
/// |weights| over one parity class of each. U is C1 on regular meshes when
/// it is below 1/2.
/// \param scheme A quad-split or dual-split scheme (the grid's width follows
///        its DegreeParameters' degree where it has them, else degree 3).
/// \return |U_dd|.
/// \throws InvalidInputError if the scheme's split is neither quad nor dual,
///         the mask does not divide (a scheme without linear precision), a
///         refined point is off the refined grid, or refinement rejects the
///         grid or the scheme's parameters.
/// \throws std::bad_alloc if memory runs out.
double regular_second_difference_norm(const Scheme& scheme);

}  // namespace subdiv
