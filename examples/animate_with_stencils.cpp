// Stencil tables for animation: the refinement of a mesh's topology is
// recorded once as a table of weights (refined point = sum of weights times
// control points); each new pose of the control points is then refined by
// applying the table, without refining again. The example moves the control
// points through a few frames and checks each against a full refinement.
//
//   animate_with_stencils data/meshes/spot_control_mesh.obj catmull-clark 2

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

int main(int argc, char** argv) {
  int levels = 0;
  if (argc != 4 || std::from_chars(argv[3], argv[3] + std::strlen(argv[3]), levels).ec != std::errc()) {
    std::fprintf(stderr, "usage: animate_with_stencils MESH SCHEME LEVELS\n");
    return 1;
  }
  const subdiv::Scheme* scheme = subdiv::find_scheme(argv[2]);
  if (scheme == nullptr) {
    std::fprintf(stderr, "unknown scheme '%s'\n", argv[2]);
    return 1;
  }
  try {
    subdiv::PolygonMesh mesh = subdiv::read_mesh(argv[1]).mesh;
    subdiv::RefineOptions options;
    options.levels = levels;
    // Once: the table from the control points to the last level's points.
    const subdiv::StencilTable table = subdiv::refine_stencil_table(mesh, *scheme, options);
    std::printf("stencil table: %d control points -> %d refined points, %zu weights\n", table.source_count(),
                table.row_count(), table.entry_count());

    const std::vector<subdiv::Vec3> rest = mesh.positions;
    std::vector<subdiv::Vec3> refined(static_cast<std::size_t>(table.row_count()));
    double worst = 0.0;
    for (int frame = 1; frame <= 3; ++frame) {
      // A pose: every control point pushed along a wave in x.
      for (std::size_t i = 0; i < rest.size(); ++i)
        mesh.positions[i] = rest[i] + subdiv::Vec3{0.0, 0.0, 0.1 * std::sin(frame + 3.0 * rest[i].x)};
      table.apply(mesh.positions, refined);  // per frame: one sparse product
      // The same pose refined from scratch: the table must agree.
      const subdiv::PolygonMesh again = subdiv::refine(mesh, *scheme, options);
      double difference = 0.0;
      for (std::size_t i = 0; i < refined.size(); ++i)
        for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(refined[i][c] - again.positions[i][c]));
      worst = std::max(worst, difference);
      std::printf("frame %d: largest difference from refining again %.3g\n", frame, difference);
    }
    if (worst > 1e-12) {
      std::fprintf(stderr, "the table and refinement disagree by %.3g\n", worst);
      return 1;
    }
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "animate_with_stencils: %s\n", e.what());
    return 1;
  }
  return 0;
}
