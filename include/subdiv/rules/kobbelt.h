#pragma once
/// \file
/// Kobbelt's interpolatory quad scheme (quad split, QP arity 2, quad meshes);
/// every weight is in kobbelt.cpp.

#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The registered "kobbelt" scheme: interpolating, quad split, quad meshes,
/// tension w (TensionParameters, default 1/16; its check requires
/// w > -1/2).
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& kobbelt_scheme() noexcept;

/// The weights of Kobbelt's virtual point at an interior vertex with n >= 3
/// quads: the point opposite edge neighbour q_i, over the edge neighbours
/// q_0 .. q_{n-1} (counter-clockwise) and the diagonals r_j, r_j opposite
/// the vertex in the quad between q_j and q_{j+1}. Tension w as in the
/// four-point rule (1/16 standard). The weights sum to 1.
struct KobbeltVirtualWeights {
  std::vector<double> edge_neighbours;  ///< n weights, on q_0 .. q_{n-1}
  std::vector<double> diagonals;        ///< n weights, on r_0 .. r_{n-1}
};

/// Kobbelt's virtual point opposite q_i (see KobbeltVirtualWeights):
/// (4/n) sum q - (q_{i-1} + q_i + q_{i+1}) + c (r_{i-2} + .. + r_{i+1})
/// - (4c/n) sum r, c = kobbelt_diagonal_weight(tension); indices modulo n.
/// \param n the quads around the vertex, >= 3.
/// \param i the edge neighbour the point is opposite, 0 .. n - 1.
/// \param tension the four-point tension w, > -1/2.
/// \return the weights.
/// \pre \p n >= 1.
/// \throws std::bad_alloc if memory runs out.
KobbeltVirtualWeights kobbelt_virtual_point_weights(int n, int i, double tension);

/// c(w) = 2w / (1 + 2w), the weight of the four diagonals next to q_i.
/// \param tension the four-point tension w, > -1/2.
/// \return c(w); 1/9 at w = 1/16.
double kobbelt_diagonal_weight(double tension) noexcept;

}  // namespace subdiv
