#pragma once
// Meshes for the depth tests, built in code.

#include <random>

#include "subdiv/mesh/polygon_mesh.h"

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

}  // namespace subdiv
