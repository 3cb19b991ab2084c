#pragma once
/// \file
/// Catmull-Clark subdivision (Catmull and Clark 1978), quad split, any polygon
/// mesh; every weight of the scheme is in catmull_clark.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The registered "catmull-clark" scheme, also default_scheme(): quad split,
/// any polygon mesh, cubic B-spline boundaries and creases.
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the boundary curve scheme it refers to.
const Scheme& catmull_clark_scheme();

/// The piecewise-smooth edge weight gamma(theta) = 3/8 - 1/4 cos(theta).
/// \param theta the sector angle per face theta_k, in radians.
/// \return gamma(theta).
double catmull_clark_gamma(double theta) noexcept;

/// The subdominant eigenvalue at an interior vertex of this valence
/// (Halstead, Kass and DeRose 1993); 1/2 at valence 4.
/// \param valence the vertex's valence k, >= 3.
/// \return (5 + cos(2 pi/k) + cos(pi/k) sqrt(2 (9 + cos(2 pi/k)))) / 16.
double catmull_clark_subdominant_eigenvalue(int valence) noexcept;

}  // namespace subdiv
