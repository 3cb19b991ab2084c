#pragma once
/// \file
/// A priori subdivision depth: how many uniform steps bring every control
/// vertex within eps of its limit position, from numbers read off the control
/// mesh before any refinement ("A priori computation of the subdivision
/// depth", Loop, Catmull-Clark and Doo-Sabin; docs/depth.md).
///
/// Every bound here has the form
///     distance after k steps <= max over terms of amplitude * rate^(k - start)
/// for k >= start: `start` is the number of steps the bound needs before it
/// applies (the first Catmull-Clark or Doo-Sabin step that makes the mesh
/// regular enough), `amplitude` is measured on the mesh after those steps.

#include <cstdint>
#include <string>
#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// One geometric decay: distance <= amplitude * rate^(steps after start).
struct DepthTerm {
  std::string what;       ///< what the amplitude measures and where the rate comes from
  double amplitude = 0.0;  ///< the distance bound at `start` steps (mesh units)
  double rate = 0.0;      ///< contraction per step, in [0, 1)
};

/// What a DepthBound bounds.
enum class DepthMeasure : std::uint8_t {
  /// Every vertex's distance to its own limit position.
  vertex_to_limit,
  /// The level's linear surface (flat triangles, bilinear quads) against
  /// the limit surface at the same parameter of the nested splits: the
  /// measure of interpolating schemes, whose vertices are on the limit.
  surface_to_limit,
};

/// The measure's name: "vertex-to-limit" or "surface-to-limit".
/// \param m The measure.
/// \return Its name, a static string.
const char* to_string(DepthMeasure m) noexcept;

/// An a priori bound on the distance to the limit after k refinement steps
/// (`measure` says of what: every vertex, or the level's linear surface):
/// the largest of its terms' amplitude * rate^(k - start), for k >= start.
struct DepthBound {
  /// The bounded scheme's name: set by depth_bound(); empty in the published
  /// bounds (loop_paper_bound(), cheng_catmull_clark_bound(),
  /// doo_sabin_bound()), which are formulas in the papers' measures.
  std::string scheme;
  /// "paper" for the published bounds, "analysis" for bounds derived from
  /// the scheme's eigenvalues (docs/depth.md says which is which).
  std::string source;
  /// Steps the bound needs before it applies (the terms' amplitudes are
  /// measured after them).
  int start = 0;
  /// The geometric decays; the bound is their maximum.
  std::vector<DepthTerm> terms;
  /// Refinement steps per level of the bound: 1, or 2 for a scheme bounded
  /// through its two-step scheme (Scheme::fast_path.two_steps: 4-8, whose levels are
  /// then quad splits, two of its steps each).
  int steps_per_level = 1;
  /// What the bound bounds.
  DepthMeasure measure = DepthMeasure::vertex_to_limit;

  /// The bound on the distance to the limit after \p level levels;
  /// infinite for level < start (nothing is claimed there).
  /// \param level Levels of the bound (`steps_per_level` refinement steps
  ///        each).
  /// \return max over terms of amplitude * rate^(level - start), 0 without
  ///         terms.
  double at(int level) const noexcept;
  /// The smallest level >= start whose bound is <= eps.
  /// \param eps The accuracy: a positive, finite distance.
  /// \return The level, at most start + 64.
  /// \throws InvalidInputError if \p eps is not positive and finite, a term's
  ///         rate is not in [0, 1) or its amplitude is not finite, or more
  ///         than 64 levels after `start` are needed.
  int depth_for(double eps) const;
};

/// Loop's even-vertex contraction 5/8 - n beta(n) with Loop's beta (paper,
/// Theorem 3): the distance of a valence-n vertex to its limit shrinks by
/// exactly this factor per step. Equals (3/8 + 1/4 cos(2 pi / n))^2.
/// Read off \p scheme's own masks (Loop's rules: the vertex mask's weight on
/// the vertex less the edge mask's weight on its end) at an interior vertex
/// of a triangle ring.
/// \param scheme A triangle-split scheme with vertex-point and edge-point
///        masks (Loop's, for the paper's meaning).
/// \param valence The vertex's valence n, at least 3.
/// \return The contraction factor 5/8 - n beta(n).
/// \pre `scheme.masks.vertex_point` and `scheme.masks.edge_point` are set.
/// \throws InvalidInputError if \p valence < 3.
/// \throws std::bad_alloc if memory runs out.
double loop_contraction(const Scheme& scheme, int valence);

/// The paper's Loop bound (Theorem 3, Corollary 3): distance after k steps
/// <= (5/8 - n beta)^k M0, with M0 the largest control-vertex-to-limit
/// distance and n the largest valence at any level (at least 6: refinement
/// creates valence-6 vertices).
/// \param scheme The Loop scheme (its masks give the rate, loop_contraction()).
/// \param max_limit_distance M0, the largest control-vertex-to-limit distance.
/// \param max_valence The largest valence in the mesh; values below 6 count
///        as 6.
/// \return The bound: source "paper", start 0, one term; `scheme` empty.
/// \pre `scheme.masks.vertex_point` and `scheme.masks.edge_point` are set.
/// \throws std::bad_alloc if memory runs out.
DepthBound loop_paper_bound(const Scheme& scheme, double max_limit_distance, int max_valence);

/// Cheng's Catmull-Clark bound (paper, Theorem 2, Corollary 2) on a quad
/// mesh: distance after k steps <= (1/3) (1/4)^k M, with M the largest
/// second difference |P_{k-1} - 2 P_k + P_{k+1}| along the mesh lines.
/// \p start is 1 when M was measured after the first step (non-quad input).
/// \param max_second_difference M, measured by max_second_difference() after
///        \p start steps.
/// \param start Steps taken before M was measured.
/// \return The bound: source "paper", one term (M/3, rate 1/4); `scheme` empty.
/// \throws std::bad_alloc if memory runs out.
DepthBound cheng_catmull_clark_bound(double max_second_difference, int start);

/// The paper's Doo-Sabin bound (Theorem 5, Corollary 5): after the first
/// step every vertex has valence 4, and then distance after k more steps
/// <= (1/4) (1/4)^k M, with M the largest second difference along the
/// lines of the mesh after \p start >= 1 steps (the paper: start = 1).
/// \param max_second_difference M, measured by max_second_difference() after
///        \p start steps.
/// \param start Steps taken before M was measured, at least 1.
/// \return The bound: source "paper", one term (M/4, rate 1/4); `scheme` empty.
/// \throws std::bad_alloc if memory runs out.
DepthBound doo_sabin_bound(double max_second_difference, int start);

}  // namespace subdiv
