#pragma once
// Catmull-Clark subdivision (Catmull and Clark 1978), quad split, any polygon
// mesh; every weight of the scheme is in catmull_clark.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& catmull_clark_scheme();
/// The piecewise-smooth edge weight gamma(theta) = 3/8 - 1/4 cos(theta).
double catmull_clark_gamma(double theta);

/// The subdominant eigenvalue at an interior vertex of this valence
/// (Halstead, Kass and DeRose 1993); 1/2 at valence 4.
double catmull_clark_subdominant_eigenvalue(int valence);

}  // namespace subdiv
