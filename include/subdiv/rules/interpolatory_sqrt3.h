#pragma once
// Labsik and Greiner's interpolatory sqrt3 subdivision (sqrt3 split,
// closed triangle meshes); every weight is in interpolatory_sqrt3.cpp.

#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The weights of the extraordinary rule of a vertex v of valence k on its
/// ring u_0 .. u_{k-1} (u_0 and u_{k-1} the corners of the face whose point
/// is made, u_0 the one before v in it, the ring turning away from that
/// face), then on v itself: k + 1 numbers.
std::vector<double> interpolatory_sqrt3_weights(int k);

const Scheme& interpolatory_sqrt3_scheme();

}  // namespace subdiv
