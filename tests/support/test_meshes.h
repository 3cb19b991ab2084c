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
/// Regular tetrahedron.
PolygonMesh tetrahedron();

std::string data_path(const std::string& name);     ///< tests/data/<name>
std::string bundled_path(const std::string& name);  ///< data/meshes/<name>
std::string shared_mesh_dir();                      ///< ../shared/data/meshes

}  // namespace subdiv::test
