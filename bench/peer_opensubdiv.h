#pragma once
// OpenSubdiv (Debian's libosd-dev) as the peer of the refinement benchmarks:
// its refiner built from our face lists, and uniform refinement as its
// tutorials do it (TopologyRefiner::RefineUniform, then
// PrimvarRefiner::Interpolate level by level into one buffer), in double.

#include <opensubdiv/far/topologyRefiner.h>

#include <memory>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::bench {

struct OsdVertex {
  double x, y, z;
  void Clear(void* = nullptr) { x = y = z = 0.0; }
  void AddWithWeight(const OsdVertex& v, double w) {
    x += w * v.x;
    y += w * v.y;
    z += w * v.z;
  }
};

/// The base level from our face lists, boundaries edge-and-corner.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> osd_refiner(const PolygonMesh& mesh,
                                                              OpenSubdiv::Sdc::SchemeType type);

/// Refines `levels` uniform levels; `buffer` receives every level's vertices.
/// Returns the last level's face count.
int osd_refine_uniform(const PolygonMesh& mesh, OpenSubdiv::Sdc::SchemeType type, int levels,
                       std::vector<OsdVertex>& buffer);

}  // namespace subdiv::bench
