#pragma once
// Doo-Sabin subdivision (dual split, QD arity 2, any polygon mesh); every
// weight is in doo_sabin.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The weight alpha_i of the Doo-Sabin mask on the vertex i steps round a
/// k-gon from the corner whose new vertex is computed (Zorin's survey,
/// Fig. 9): alpha_0 = 1/4 + 5/(4k), alpha_i = (3 + 2 cos(2 i pi / k)) / (4k).
double doo_sabin_weight(int k, int i);

const Scheme& doo_sabin_scheme();

}  // namespace subdiv
