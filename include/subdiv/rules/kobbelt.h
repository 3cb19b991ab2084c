#pragma once
// Kobbelt's interpolatory quad scheme (quad split, QP arity 2, quad meshes);
// every weight is in kobbelt.cpp.

#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& kobbelt_scheme();

/// The weights of Kobbelt's virtual point at an interior vertex with n >= 3
/// quads: the point opposite edge neighbour q_i, over the edge neighbours
/// q_0 .. q_{n-1} (counter-clockwise) and the diagonals r_j, r_j opposite
/// the vertex in the quad between q_j and q_{j+1}. Tension w as in the
/// four-point rule (1/16 standard). The weights sum to 1.
struct KobbeltVirtualWeights {
  std::vector<double> edge_neighbours;
  std::vector<double> diagonals;
};
KobbeltVirtualWeights kobbelt_virtual_point_weights(int n, int i, double tension);

/// c(w) = 2w / (1 + 2w), the weight of the four diagonals next to q_i.
double kobbelt_diagonal_weight(double tension);

}  // namespace subdiv
