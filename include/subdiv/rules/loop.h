#pragma once
// Loop subdivision (Loop 1987), triangle split, triangle meshes, with two
// named choices of the vertex weight beta(k); every weight is in loop.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// beta(k) = (1/k) (5/8 - (3/8 + 1/4 cos(2 pi / k))^2): Loop's original.
double loop_beta(int valence);
/// beta(k) = 3/(8k) for k > 3 and 3/16 for k = 3: Warren's simplification.
double loop_warren_beta(int valence);
/// The piecewise-smooth edge weight gamma(theta) = 1/2 - 1/4 cos(theta).
double loop_gamma(double theta);

const Scheme& loop_scheme();
const Scheme& loop_warren_scheme();

}  // namespace subdiv
