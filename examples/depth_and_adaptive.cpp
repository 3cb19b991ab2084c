// How many uniform steps bring a mesh within eps of its limit surface, known
// before refining (the a priori depth bound), checked by refining to that
// depth; then adaptive refinement to the same eps, which refines only where
// the control vertices are still far from their limits.
//
//   depth_and_adaptive data/meshes/tetrahedron.obj loop 0.001

#include <cstdio>
#include <cstdlib>

#include "subdiv/core/error.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/depth.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/rules/scheme.h"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: depth_and_adaptive MESH SCHEME EPS\n");
    return 1;
  }
  const subdiv::Scheme* scheme = subdiv::find_scheme(argv[2]);
  if (scheme == nullptr) {
    std::fprintf(stderr, "unknown scheme '%s'\n", argv[2]);
    return 1;
  }
  const double eps = std::strtod(argv[3], nullptr);
  try {
    const subdiv::MeshFile file = subdiv::read_mesh(argv[1]);

    // The bound reads the control mesh only: no refinement happens here.
    const subdiv::DepthBound bound = subdiv::depth_bound(file.mesh, *scheme, {}, &file.lines);
    const int depth = bound.depth_for(eps);
    std::printf("a priori depth for eps %g: %d (bound %.3g, from the %s)\n", eps, depth, bound.at(depth),
                bound.source.c_str());

    // Refining to that depth measures what the bound promised.
    const subdiv::DepthCheck check = subdiv::check_depth(file.mesh, *scheme, bound, depth);
    std::printf("refined to depth %d: largest vertex-to-limit distance %.3g (%s)\n", check.depth,
                check.measured, check.measured <= eps ? "within eps" : "NOT within eps");

    const subdiv::AdaptiveResult adaptive = subdiv::adaptive_refine(file.mesh, *scheme, eps);
    std::printf("adaptive: %d faces (%lld transition faces), uniform to depth %d: %lld faces\n",
                adaptive.mesh.face_count(), static_cast<long long>(adaptive.transition_faces),
                adaptive.uniform_depth, static_cast<long long>(adaptive.uniform_faces));
    return check.measured <= eps ? 0 : 1;
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "depth_and_adaptive: %s\n", e.what());
    return 1;
  }
}
