#pragma once
// A priori subdivision depth: how many uniform steps bring every control
// vertex within eps of its limit position, from numbers read off the control
// mesh before any refinement ("A priori computation of the subdivision
// depth", Loop, Catmull-Clark and Doo-Sabin; docs/depth.md).
//
// Every bound here has the form
//     distance after k steps <= max over terms of amplitude * rate^(k - start)
// for k >= start: `start` is the number of steps the bound needs before it
// applies (the first Catmull-Clark or Doo-Sabin step that makes the mesh
// regular enough), `amplitude` is measured on the mesh after those steps.

#include <string>
#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// One geometric decay: distance <= amplitude * rate^(steps after start).
struct DepthTerm {
  std::string what;       ///< what the amplitude measures and where the rate comes from
  double amplitude = 0.0;
  double rate = 0.0;      ///< contraction per step, in [0, 1)
};

struct DepthBound {
  /// The bounded scheme's name: set by depth_bound(); empty in the published
  /// bounds below, which are formulas in the papers' measures.
  std::string scheme;
  /// "paper" for the published bounds, "analysis" for bounds derived from
  /// the scheme's eigenvalues (docs/depth.md says which is which).
  std::string source;
  int start = 0;
  std::vector<DepthTerm> terms;
  /// Refinement steps per level of the bound: 1, or 2 for a scheme bounded
  /// through its two-step scheme (Scheme::fast_path.two_steps: 4-8, whose levels are
  /// then quad splits, two of its steps each).
  int steps_per_level = 1;

  /// The bound on the vertex-to-limit distance after `level` steps; infinite
  /// for level < start (nothing is claimed there).
  double at(int level) const;
  /// The smallest level >= start whose bound is <= eps. Throws
  /// InvalidInputError for eps <= 0 or a term whose rate is not below 1.
  int depth_for(double eps) const;
};

/// Loop's even-vertex contraction 5/8 - n beta(n) with Loop's beta (paper,
/// Theorem 3): the distance of a valence-n vertex to its limit shrinks by
/// exactly this factor per step. Equals (3/8 + 1/4 cos(2 pi / n))^2.
/// Read off `scheme`'s own masks (Loop's rules: the vertex mask's weight on
/// the vertex less the edge mask's weight on its end).
double loop_contraction(const Scheme& scheme, int valence);

/// The paper's Loop bound (Theorem 3, Corollary 3): distance after k steps
/// <= (5/8 - n beta)^k M0, with M0 the largest control-vertex-to-limit
/// distance and n the largest valence at any level (at least 6: refinement
/// creates valence-6 vertices).
DepthBound loop_paper_bound(const Scheme& scheme, double max_limit_distance, int max_valence);

/// Cheng's Catmull-Clark bound (paper, Theorem 2, Corollary 2) on a quad
/// mesh: distance after k steps <= (1/3) (1/4)^k M, with M the largest
/// second difference |P_{k-1} - 2 P_k + P_{k+1}| along the mesh lines.
/// `start` is 1 when M was measured after the first step (non-quad input).
DepthBound cheng_catmull_clark_bound(double max_second_difference, int start);

/// The paper's Doo-Sabin bound (Theorem 5, Corollary 5): after the first
/// step every vertex has valence 4, and then distance after k more steps
/// <= (1/4) (1/4)^k M, with M the largest second difference along the
/// lines of the mesh after `start` >= 1 steps (the paper: start = 1).
DepthBound doo_sabin_bound(double max_second_difference, int start);

}  // namespace subdiv
