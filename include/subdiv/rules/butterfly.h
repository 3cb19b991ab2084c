#pragma once
// The interpolating Butterfly schemes, triangle split, triangle meshes:
// Dyn, Levin and Gregory's original 8-point rule and Zorin, Schroeder and
// Sweldens' modified Butterfly; every weight is in butterfly.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The tension w of the registered `butterfly` scheme (Dyn, Levin and
/// Gregory 1990): 1/16, the value that reproduces cubic polynomials. The
/// modified Butterfly's regular rule always uses it; `butterfly` reads
/// SchemeParameters::tension.
inline constexpr double kButterflyTension = 1.0 / 16.0;

/// The modified Butterfly's weight s_j on the j-th ring neighbour of an
/// interior vertex of valence k (j = 0 is the edge's other end); the vertex
/// itself takes 3/4.
double modified_butterfly_interior_weight(int valence, int j);

/// The extraordinary crease rule for the new vertex on the i-th edge of a
/// crease sector with k faces (edges numbered 0 .. k from one sharp edge):
/// the weight c_ij on ring vertex j = 0 .. k, and on the crease vertex itself.
double modified_butterfly_crease_weight(int faces, int i, int j);
double modified_butterfly_crease_centre_weight(int faces, int i);

const Scheme& butterfly_scheme();
const Scheme& modified_butterfly_scheme();

}  // namespace subdiv
