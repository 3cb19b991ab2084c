#pragma once
// OpenSubdiv (Far::TopologyRefiner) set up as the comparison tests need it,
// and the correspondence between subdiv's refined levels and its.
//
// The two libraries number child vertices differently (both list face, edge
// and vertex points, but in different orders, and edges are numbered
// differently), so the correspondence follows the levels: our level-0
// vertices and faces are theirs; a child of our parent face f is the child
// of their face map(f), a child of our parent edge (a, b) the child of their
// edge FindEdge(map(a), map(b)), a child of our parent vertex v the child of
// their vertex map(v). Child faces are matched by their vertices.

#include <opensubdiv/far/topologyRefiner.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/topology/split.h"

namespace subdiv::test {

/// PrimvarRefiner's vertex interface for positions, in double precision.
struct OsdVertex {
  double x = 0.0, y = 0.0, z = 0.0;
  void Clear() { x = y = z = 0.0; }
  void AddWithWeight(const OsdVertex& src, double w) {
    x += w * src.x;
    y += w * src.y;
    z += w * src.z;
  }
  Vec3 vec() const { return {x, y, z}; }
};

/// The positions of every level of `refiner`, refined from `mesh`'s level by
/// level through PrimvarRefiner.
std::vector<std::vector<OsdVertex>> their_positions(const OpenSubdiv::Far::TopologyRefiner& refiner,
                                                    const PolygonMesh& mesh);

/// The length of the points' bounding-box diagonal (0 for none).
double bbox_diagonal(const std::vector<Vec3>& points);

/// OpenSubdiv's name for a boundary interpolation.
OpenSubdiv::Sdc::Options::VtxBoundaryInterpolation boundary_option(BoundaryInterpolation boundary);

/// OpenSubdiv's regression harness reads `t interpolateboundary` 0/1/2 as
/// VTX_BOUNDARY_NONE / EDGE_AND_CORNER / EDGE_ONLY, and uses NONE when the
/// tag is absent.
OpenSubdiv::Sdc::Options::VtxBoundaryInterpolation their_boundary(const Tags& tags);

/// OpenSubdiv stores sharpness as float: rounds the tags so that both
/// libraries refine the same values.
void round_sharpness_to_float(Tags& tags);

/// OpenSubdiv's refiner for `mesh` (its creases, corners, holes, creasing
/// method and triangle rule) under `boundary`, refined uniformly `levels`
/// times with full topology (0: the base level alone). Where `channel` is
/// given it becomes face-varying channel 0, refined under `face_varying`.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> make_refiner(
    const PolygonMesh& mesh, OpenSubdiv::Sdc::SchemeType scheme, int levels,
    OpenSubdiv::Sdc::Options::VtxBoundaryInterpolation boundary, const FaceVaryingChannel* channel = nullptr,
    FaceVaryingInterpolation face_varying = FaceVaryingInterpolation::all);

/// Our vertices and faces of one level, as OpenSubdiv's indices.
struct Correspondence {
  std::vector<OpenSubdiv::Far::Index> vertices;
  std::vector<OpenSubdiv::Far::Index> faces;
  /// The control mesh's: the identity.
  static Correspondence identity(const PolygonMesh& mesh);
};

/// The child vertex ranges of our quad or triangle split of `parent`
/// (split.h): face points, edge points, vertex points.
SplitMap split_ranges(const PolygonMesh& parent, SplitRule rule);

/// Where our child vertex i comes from, for messages.
std::string describe_child(const SplitMap& map, Index i);

/// The correspondence of `child`, our quad or triangle split of `parent`,
/// with OpenSubdiv's level `their_child`, from the parent's.
/// \return "" on success, else what does not correspond.
std::string child_correspondence(const PolygonMesh& parent, SplitRule rule, const PolygonMesh& child,
                                 const OpenSubdiv::Far::TopologyLevel& their_parent,
                                 const OpenSubdiv::Far::TopologyLevel& their_child, const Correspondence& parent_map,
                                 Correspondence& child_map);

}  // namespace subdiv::test
