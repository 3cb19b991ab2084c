// Limit positions and normals: where each control vertex ends up after
// infinitely many steps, and the surface's unit normal there, from the
// scheme's limit masks (closed forms where the scheme has them, else the
// eigenvectors of its subdivision matrices). Prints the first vertices and
// how each result was obtained.
//
//   limit_points data/meshes/tetrahedron.obj loop

#include <algorithm>
#include <cstdio>

#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/scheme.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: limit_points MESH SCHEME\n");
    return 1;
  }
  const subdiv::Scheme* scheme = subdiv::find_scheme(argv[2]);
  if (scheme == nullptr) {
    std::fprintf(stderr, "unknown scheme '%s'\n", argv[2]);
    return 1;
  }
  try {
    const subdiv::MeshFile file = subdiv::read_mesh(argv[1]);
    subdiv::LimitOptions options;
    options.normals = true;
    const subdiv::LimitResult limit = subdiv::limit_positions(file.mesh, *scheme, options);
    const subdiv::Index shown = std::min<subdiv::Index>(file.mesh.vertex_count(), 4);
    for (subdiv::Index v = 0; v < shown; ++v) {
      const auto i = static_cast<std::size_t>(v);
      const subdiv::Vec3 p = limit.positions[i], n = limit.normals[i];
      const char* how = limit.sources[i] == subdiv::LimitSource::closed_form ? "closed form"
                        : limit.sources[i] == subdiv::LimitSource::generic   ? "eigenvector masks"
                                                                             : "refined position";
      std::printf("vertex %d: limit (%.6f, %.6f, %.6f), normal (%.6f, %.6f, %.6f), %s\n", v, p.x, p.y, p.z, n.x, n.y,
                  n.z, how);
    }
    std::printf("%d vertices, %d left at a refined position\n", file.mesh.vertex_count(), limit.approximated);
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "limit_points: %s\n", e.what());
    return 1;
  }
  return 0;
}
