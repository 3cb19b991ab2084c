#pragma once
// Kobbelt's sqrt3 subdivision (sqrt3 split, TP arity sqrt 3, triangle
// meshes); every weight is in sqrt3.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// Kobbelt's alpha_n = (4 - 2 cos(2 pi / n)) / 9: a vertex of valence n
/// moves to (1 - alpha_n) v + alpha_n / n (sum of its neighbours).
double sqrt3_alpha(int n);

const Scheme& sqrt3_scheme();

}  // namespace subdiv
