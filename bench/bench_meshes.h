#pragma once
// Inputs for the benchmarks: generated meshes of any size, and the shared
// collection's large real meshes when present.

#include <string>

#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::bench {

/// A closed torus of n x n quads with slightly irregular positions (so that
/// numbers have full-length decimal forms, like scanned data).
PolygonMesh torus(int n);
/// The same torus split into triangles.
PolygonMesh triangulated_torus(int n);
/// The whole file as text.
std::string read_text(const std::string& path);
/// Path of a mesh in ../shared/data/meshes, or "" when absent.
std::string shared_mesh(const std::string& relative);

}  // namespace subdiv::bench
