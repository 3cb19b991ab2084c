#pragma once
/// \file
/// Doo-Sabin subdivision (dual split, QD arity 2, any polygon mesh); every
/// weight is in doo_sabin.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The weight alpha_i of the Doo-Sabin mask on the vertex i steps round a
/// k-gon from the corner whose new vertex is computed (Zorin's survey,
/// Fig.\ 9): alpha_0 = 1/4 + 5/(4k), alpha_i = (3 + 2 cos(2 i pi / k)) / (4k).
/// \param k the face size, >= 3.
/// \param i the steps from the corner, any integer (taken modulo \p k).
/// \return alpha_i.
/// \pre \p k != 0 (the index is reduced modulo \p k).
double doo_sabin_weight(int k, int i) noexcept;

/// The registered "doo-sabin" scheme: dual split, any polygon mesh,
/// Chaikin (quadratic B-spline) boundaries; no crease, corner or hole rules.
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the boundary curve scheme it refers to.
const Scheme& doo_sabin_scheme();

}  // namespace subdiv
