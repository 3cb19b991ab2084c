#pragma once
/// \file
/// Kobbelt's sqrt3 subdivision (sqrt3 split, TP arity sqrt 3, triangle
/// meshes); every weight is in sqrt3.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// Kobbelt's alpha_n = (4 - 2 cos(2 pi / n)) / 9: a vertex of valence n
/// moves to (1 - alpha_n) v + alpha_n / n (sum of its neighbours).
/// \param n the vertex's valence, >= 1 (tabulated up to 63, computed above).
/// \return alpha_n.
double sqrt3_alpha(int n) noexcept;

/// The registered "sqrt3" scheme (Kobbelt 2000): sqrt3 split, triangle
/// meshes, cubic B-spline boundaries.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& sqrt3_scheme() noexcept;

}  // namespace subdiv
