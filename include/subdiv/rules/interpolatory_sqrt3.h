#pragma once
/// \file
/// Labsik and Greiner's interpolatory sqrt3 subdivision (sqrt3 split,
/// closed triangle meshes); every weight is in interpolatory_sqrt3.cpp.

#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The weights of the extraordinary rule of a vertex v of valence k on its
/// ring u_0 .. u_{k-1} (u_0 and u_{k-1} the corners of the face whose point
/// is made, u_0 the one before v in it, the ring turning away from that
/// face), then on v itself: k + 1 numbers.
/// \param k the valence of v, >= 3.
/// \return the k + 1 weights.
/// \pre \p k >= 0.
/// \throws std::bad_alloc if memory runs out.
std::vector<double> interpolatory_sqrt3_weights(int k);

/// The registered "interpolatory-sqrt3" scheme (Labsik and Greiner 2000):
/// interpolating, sqrt3 split, triangle meshes, the ternary four-point
/// rule on boundaries.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& interpolatory_sqrt3_scheme() noexcept;

}  // namespace subdiv
