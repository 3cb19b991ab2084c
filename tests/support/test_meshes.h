#pragma once
// Small meshes built in code for the tests, and paths to test data.

#include <string>

#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::test {

/// Unit cube, 6 counter-clockwise quads.
PolygonMesh cube();
/// n x m grid of unit quads in the z = 0 plane, counter-clockwise seen from +z.
PolygonMesh quad_grid(int n, int m);
/// Grid whose quads are each split into two triangles.
PolygonMesh triangle_grid(int n, int m);
/// Grid whose quads are each split along the diagonal from (i + 1, j) to
/// (i, j + 1): the lattice of directions e1, e2 and e2 - e1 on which Loop's
/// box spline is written (analysis/patch_basis.h).
PolygonMesh box_spline_grid(int n, int m);
/// Regular tetrahedron.
PolygonMesh tetrahedron();
/// A closed double pyramid over a regular n-gon (n >= 3) in z = 0, apexes at
/// z = 1.2 and -0.9: apexes of valence n, the equator's vertices of valence 4.
PolygonMesh bipyramid(int n);
/// The unit cube with each quad split into four (26 vertices), infinitely
/// sharp creases along its equator z = 1/2 and its meridian x = 1/2: crease
/// vertices of four edges, and two where the creases cross (corners of four
/// sharp edges). The cube's corners keep valence 3.
PolygonMesh creased_cube();
/// The largest distance of a vertex from the origin: the scale that
/// position tolerances are relative to.
double radius(const PolygonMesh& mesh);
/// The mesh with every vertex moved by up to 0.1 along each axis, the same
/// for the same seed (std::mt19937).
PolygonMesh jittered(PolygonMesh mesh, unsigned seed);
/// The mesh with heights z drawn uniformly from [-1, 1], the same for the
/// same seed (std::mt19937): a generic function sampled on a planar grid.
PolygonMesh with_random_heights(PolygonMesh mesh, unsigned seed);
/// Triangle, quad and pentagon over coordinates that round-trip only if every
/// digit is kept (thirds, 1e300, denormals, -0.0, the largest double).
PolygonMesh hard_numbers_mesh();

std::string data_path(const std::string& name);     ///< tests/data/<name>
std::string bundled_path(const std::string& name);  ///< data/meshes/<name>
std::string shared_mesh_dir();                      ///< ../shared/data/meshes

}  // namespace subdiv::test
