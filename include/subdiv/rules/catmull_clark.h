#pragma once
// Catmull-Clark subdivision (Catmull and Clark 1978), quad split, any polygon
// mesh; every weight of the scheme is in catmull_clark.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& catmull_clark_scheme();
/// The piecewise-smooth edge weight gamma(theta) = 3/8 - 1/4 cos(theta).
double catmull_clark_gamma(double theta);

}  // namespace subdiv
