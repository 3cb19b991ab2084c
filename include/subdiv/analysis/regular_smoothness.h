#pragma once
/// \file
/// Smoothness of a scheme's regular rules, decided from its own masks.
///
/// Reif's criterion (analyze.h) decides smoothness at an extraordinary point
/// *given* that the scheme is C1 on regular meshes; the eigenvalues at one
/// point cannot decide the regular case. This is the regular case's own test:
/// the matrix form of the difference-scheme test (Dyn and Levin, "Subdivision
/// schemes in geometric modelling", Acta Numerica 2002, sections 4 and 6;
/// Jia, "Subdivision schemes in L_p spaces", 1995, for the transition
/// matrices).
///
/// A regular rule is shift-invariant on a lattice Z^d (d = 1 for curves, 2
/// for surfaces): child c <- sum_j a(c - M j) p_j, M the dilation (2 I for the
/// binary splits; a scaled rotation for the sqrt3, sqrt2 and midedge splits).
/// For each digit e (a representative of Z^d / M Z^d) the transition matrix
/// T_e maps the control points on a window K to the children on K + e; K is
/// closed (those children read no parent outside K) and contains the
/// 1-neighbourhood of the origin, so every child of every level lies in some
/// window together with its neighbours. Linear functions of the lattice
/// index are invariant under every T_e when the rules reproduce them; on the
/// quotient by them (the data's second differences) the joint spectral
/// radius rho of {T_e} measures how fast the data leave a linear function.
/// With mu = |det M|^(1/d) (the lattice shrinks by 1/mu per step, M a
/// similarity):
///
/// - rho < 1/mu: C1 (the divided differences converge uniformly);
/// - rho >= 1/mu: not C1 (a product T_w with rho(T_w)^(1/|w|) >= 1/mu keeps
///   data that are not linear from flattening faster than the lattice
///   shrinks; for interpolating schemes these data are values of the limit,
///   for the others the step assumes the basis functions' shifts are stable,
///   as B-splines' are).
///
/// rho is bracketed: below by the spectral radii of products up to a length,
/// above by the largest norm of products of one length, in a norm fitted to
/// the family (an ellipsoid from the products' Gram sums). When the bracket
/// contains 1/mu the verdict is inconclusive.
///
/// Boundaries: the regular boundary (a straight boundary of a regular mesh,
/// with the boundary rules) is shift-invariant along the boundary only. Its
/// transition matrices are read row by row from the rules on a cylinder and
/// use the digits along the boundary; a sequence that leaves the boundary
/// ends in the interior family, so the boundary is C1 when both families are.

#include <array>
#include <string>
#include <vector>

#include "subdiv/analysis/verdict.h"
#include "subdiv/curves/curve_scheme.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// One weight of a lattice rule: child c gets `weight` times parent j where
/// c - M j = offset. Curves use offset[1] = 0.
struct LatticeWeight {
  std::array<int, 2> offset{};  ///< c - M j, lattice coordinates
  double weight = 0.0;          ///< the parent's weight in the child
};

/// A regular rule on the lattice Z^dimension.
struct LatticeRule {
  int dimension = 2;  ///< d: 1 for curves, 2 for surfaces
  /// M, row-major; for curves only dilation[0][0] is used.
  std::array<std::array<int, 2>, 2> dilation{};
  /// The interior (shift-invariant) rule.
  std::vector<LatticeWeight> mask;
  /// A boundary at lattice row 0 (surfaces, M = m I only): the rule of the
  /// children in child row r, for r < boundary_rows.size(); rows above use
  /// `mask`. Parents lie in rows >= 0. Empty: no boundary.
  std::vector<std::vector<LatticeWeight>> boundary_rows;
  std::string description;  ///< where the rule was read, for messages
};

/// The interior rule of a surface scheme, read off its own recorded
/// stencils on a regular torus (a quad grid, or a triangle grid for schemes
/// of triangle meshes), one step of its split.
/// \param scheme The surface scheme.
/// \param rules The refinement options the torus is refined with (its level
///        count, threads, start level and callback are replaced).
/// \return The rule: dilation and interior mask, no boundary rows.
/// \throws InvalidInputError if the children do not form a lattice, the rule
///         is not shift-invariant, or refinement rejects the torus or the
///         scheme's parameters.
/// \throws std::bad_alloc if memory runs out.
LatticeRule regular_interior_rule(const Scheme& scheme, const RefineOptions& rules = {});
/// The regular boundary rule: `period` steps on a cylinder whose straight
/// boundary carries the boundary rules.
/// \param scheme The surface scheme.
/// \param rules The refinement options (boundary rules, flatness) the
///        cylinder is refined with; its level count, threads, start level
///        and callback are replaced.
/// \return The rule with its boundary rows.
/// \throws InvalidInputError as regular_interior_rule() does, and if the
///         scheme refuses meshes with a boundary, no child lies on the
///         boundary, a child lies below it, or the children's lattice turns
///         against the boundary (M is not m I).
/// \throws std::bad_alloc if memory runs out.
LatticeRule regular_boundary_rule(const Scheme& scheme, const RefineOptions& rules = {});
/// A curve scheme's rule on Z (its even and odd masks), dilation 2.
/// \param scheme The curve scheme.
/// \return The rule, dimension 1.
/// \throws std::bad_alloc if memory runs out.
LatticeRule curve_lattice_rule(const CurveScheme& scheme);

/// How far regular_smoothness() enumerates products, and its margin.
struct RegularSmoothnessOptions {
  /// Products are enumerated up to about this many per length.
  int products_per_length = 4096;
  /// Relative margin around 1/mu inside which neither verdict is given.
  double margin = 1e-9;
};

/// The verdict of the difference-scheme test on a regular rule, with the
/// bracket on the joint spectral radius it rests on.
struct RegularSmoothness {
  SmoothnessVerdict verdict = SmoothnessVerdict::inconclusive;  ///< c1, not_c1 or inconclusive
  double critical = 0.0;  ///< 1/mu
  double lower = 0.0;     ///< rho >= lower
  double upper = 0.0;     ///< rho <= upper
  int lower_length = 0;   ///< the length of the product that gives `lower`
  int upper_length = 0;   ///< the product length of the norm bound
  int window = 0;         ///< |K|
  int digits = 0;         ///< |det M| (interior), the digits along a boundary
  std::string reason;     ///< one sentence: what the verdict rests on
};

/// The difference-scheme test of this header on the interior rule, or, for a rule with boundary rows,
/// on the boundary family (the interior family must be tested on its own).
/// Rules that do not reproduce linear functions, whose dilation is not a
/// similarity, or whose window exceeds 400 points are inconclusive.
/// \param rule The lattice rule.
/// \param options Product enumeration and margin.
/// \return The verdict, the bracket [lower, upper] on rho and the reason.
/// \pre The dilation is nonsingular (for curves, dilation[0][0] != 0).
/// \throws std::bad_alloc if memory runs out.
RegularSmoothness regular_smoothness(const LatticeRule& rule, const RegularSmoothnessOptions& options = {});

/// The interior verdict of \p scheme (and with \p boundary, the boundary's
/// too, combined: C1 only when both are), computed once per distinct rule and
/// remembered (thread-safe): analyze() asks it at every configuration.
/// Rules that cannot be read give an inconclusive result naming why.
/// \param scheme The surface scheme.
/// \param rules The refinement options the rules are read under.
/// \param boundary Also test the regular boundary rule.
/// \return The (combined) verdict and reason.
/// \throws std::bad_alloc if memory runs out.
RegularSmoothness regular_smoothness_of(const Scheme& scheme, const RefineOptions& rules, bool boundary);

}  // namespace subdiv
