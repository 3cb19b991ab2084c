#pragma once
/// \file
/// The interpolating Butterfly schemes, triangle split, triangle meshes:
/// Dyn, Levin and Gregory's original 8-point rule and Zorin, Schroeder and
/// Sweldens' modified Butterfly; every weight is in butterfly.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The tension w of the registered `butterfly` scheme (Dyn, Levin and
/// Gregory 1990): 1/16, the value that reproduces cubic polynomials. The
/// modified Butterfly's regular rule always uses it; `butterfly` reads
/// SchemeParameters::tension.
inline constexpr double kButterflyTension = 1.0 / 16.0;

/// The modified Butterfly's weight s_j on the j-th ring neighbour of an
/// interior vertex of valence k (j = 0 is the edge's other end); the vertex
/// itself takes 3/4: s_j = (1/k) (1/4 + cos(2 pi j/k) + 1/2 cos(4 pi j/k))
/// for k >= 5; 5/12, -1/12, -1/12 for k = 3; 3/8, 0, -1/8, 0 for k = 4.
/// \param valence the vertex's valence k, >= 3.
/// \param j the ring position, 0 .. k - 1.
/// \return s_j.
double modified_butterfly_interior_weight(int valence, int j) noexcept;

/// The extraordinary crease rule for the new vertex on the i-th edge of a
/// crease sector with k faces (edges numbered 0 .. k from one sharp edge):
/// the weight c_ij on ring vertex j = 0 .. k (c_i0 = -c_ik).
/// \param faces the faces k in the sector, >= 1.
/// \param i the edge whose new vertex is made, 1 .. k - 1.
/// \param j the ring vertex, 0 .. k.
/// \return c_ij.
double modified_butterfly_crease_weight(int faces, int i, int j) noexcept;

/// The weight c_i of the extraordinary crease rule on the crease vertex
/// itself: 1 - (1/k) sin(theta) sin(i theta) / (1 - cos theta), theta = pi/k.
/// \param faces the faces k in the sector, >= 1.
/// \param i the edge whose new vertex is made, 1 .. k - 1.
/// \return c_i.
double modified_butterfly_crease_centre_weight(int faces, int i) noexcept;

/// The registered "butterfly" scheme (Dyn, Levin and Gregory 1990): the
/// 8-point rule with tension w (TensionParameters, default
/// kButterflyTension); interpolating, triangle split, triangle meshes.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& butterfly_scheme() noexcept;

/// The registered "modified-butterfly" scheme (Zorin, Schroeder and
/// Sweldens 1996): Butterfly with rules for extraordinary and crease
/// vertices; interpolating, triangle split, triangle meshes.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& modified_butterfly_scheme() noexcept;

}  // namespace subdiv
