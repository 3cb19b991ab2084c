#pragma once
/// \file
/// Loop subdivision (Loop 1987), triangle split, triangle meshes, with two
/// named choices of the vertex weight beta(k); every weight is in loop.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// beta(k) = (1/k) (5/8 - (3/8 + 1/4 cos(2 pi / k))^2): Loop's original.
/// \param valence the vertex's valence k, >= 1 (tabulated up to 63).
/// \return beta(k), the weight on each ring neighbour.
double loop_beta(int valence) noexcept;

/// beta(k) = 3/(8k) for k > 3 and 3/16 for k = 3: Warren's simplification.
/// \param valence the vertex's valence k, >= 3.
/// \return beta(k), the weight on each ring neighbour.
double loop_warren_beta(int valence) noexcept;

/// The piecewise-smooth edge weight gamma(theta) = 1/2 - 1/4 cos(theta).
/// \param theta the sector angle per face theta_k, in radians.
/// \return gamma(theta).
double loop_gamma(double theta) noexcept;

/// The registered "loop" scheme (Loop 1987): triangle split, triangle
/// meshes, cubic B-spline boundaries and creases, loop_beta().
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the boundary curve scheme it refers to.
const Scheme& loop_scheme();

/// The registered "loop-warren" scheme: Loop with loop_warren_beta().
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the boundary curve scheme it refers to.
const Scheme& loop_warren_scheme();

}  // namespace subdiv
