// Loads a mesh, validates it, and walks the ordered one-ring of its first
// vertex: the basic moves of every subdivision rule.
//
//   inspect_mesh data/meshes/cube.obj

#include <cstdio>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: inspect_mesh MESH\n");
    return 1;
  }
  try {
    const subdiv::MeshFile file = subdiv::read_mesh(argv[1]);
    const subdiv::MeshTopology topology(file.mesh);
    const subdiv::ValidationReport report = subdiv::validate(file.mesh, topology, &file.lines);
    std::printf("%d vertices, %d faces, %d edges; %zu errors, %zu warnings\n", file.mesh.vertex_count(),
                file.mesh.face_count(), topology.edge_count(), report.error_count(), report.warning_count());
    if (file.mesh.vertex_count() == 0) return 0;

    const subdiv::Index v = 0;
    if (!topology.ring_ordered(v)) {
      std::printf("vertex 0 has no ordered ring (non-manifold or flipped faces around it)\n");
      return 0;
    }
    std::printf("vertex 0: %s, valence %d, ring (counter-clockwise):",
                topology.vertex_kind(v) == subdiv::VertexKind::boundary ? "boundary" : "interior",
                topology.valence(v));
    for (const subdiv::Index e : topology.vertex_edges(v)) std::printf(" %d", topology.other_vertex(e, v));
    std::printf("\n");
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "inspect_mesh: %s\n", e.what());
    return 1;
  }
  return 0;
}
