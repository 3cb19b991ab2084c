#include "input_mesh.h"

#include "subdiv/mesh/triangulate.h"

namespace subdiv::cli {

void triangulate_if_asked(const Scheme& scheme, bool triangulate, MeshFile& file) {
  if (!triangulate || !scheme.needs_triangles) return;
  file.mesh = subdiv::triangulate(file.mesh);
  file.lines.face_lines.clear();
  file.lines.hole_lines.clear();
}

}  // namespace subdiv::cli
