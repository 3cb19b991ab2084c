#pragma once
// Meshes for the depth tests, built in code, and the check that a bound
// holds at every level.

#include <random>
#include <string>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// Torus of n x m quads, vertex (i, j) at index i * m + j (i around the
/// main circle of radius R, j around the tube of radius r); every vertex
/// has valence 4.
PolygonMesh quad_torus(int n, int m, double R, double r);
/// The same torus with every quad cut along one diagonal: valence 6.
PolygonMesh triangle_torus(int n, int m, double R, double r);
/// Two cones on a ring of n vertices (radius `radius`, apexes at `top` and
/// -`bottom`): the paper's spinning top, two poles of valence n, the ring at
/// valence 4.
PolygonMesh spinning_top(int n, double radius, double top, double bottom);
/// Every vertex moved by a uniform random offset in [-amount, amount]^3.
PolygonMesh perturbed(PolygonMesh mesh, double amount, std::mt19937& random);

/// The largest side of the mesh's bounding box.
double largest_extent(const PolygonMesh& mesh);
/// The mesh as \p scheme reads it: triangulated for the triangle schemes.
PolygonMesh for_scheme(PolygonMesh mesh, const Scheme& scheme);
/// Refines level by level (each level's state carried: the sqrt3 split's
/// boundary steps alternate) up to depth_bound()'s depth for an eps it
/// reaches within \p max_faces, expecting the bound at every level and eps
/// at the end (gtest expectations, \p name in their messages).
void check_bound_holds(const PolygonMesh& mesh, const Scheme& scheme, const std::string& name,
                       std::int64_t max_faces = 12000);

}  // namespace subdiv
