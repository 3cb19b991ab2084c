#pragma once
// Smooth face-varying interpolation: OpenSubdiv's face-varying options
// (Sdc::Options::FVarLinearInterpolation, Tags::face_varying_interpolation)
// other than "all", for the schemes whose traits ask for them
// (SchemeTraits::smooth_face_varying: Catmull-Clark and Loop).
//
// A channel's values around a vertex split it into regions ("siblings", one
// per distinct value); an edge whose two faces disagree at either end is a
// seam. The behaviour is OpenSubdiv's (Vtr::FVarLevel,
// Vtr::FVarRefinement, Far::PrimvarRefiner::InterpolateFaceVarying),
// re-derived here on subdiv's topology:
//
// - Where a vertex or edge has one value and no seam touches it, the child
//   value takes the scheme's own mask (the engine's, with its creases,
//   boundaries and semi-sharp blends), read on that value's side.
// - Seams are curves: an edge point on a seam is the midpoint of its face's
//   two values; a vertex value bounded by two seam or boundary edges is a
//   crease (the cubic B-spline's 3/4, 1/8, 1/8 along them) or a corner
//   (kept), as the option says:
//   none: only seams split values; corners_only: also single-face regions
//   and, under edge-only boundaries, single-face boundary vertices are
//   corners; corners_plus1: also every value of a vertex with three or more
//   values, and both values of a two-valued vertex where a seam or an
//   infinitely sharp edge runs inside a region; corners_plus2: also both
//   values where one is a corner, and darts (an interior vertex with one
//   seam); boundaries: every value on a seam or mesh boundary is a corner.
// - A value whose region holds semi-sharp edges (or at a semi-sharp vertex)
//   stays a corner until they decay, then blends into the crease by
//   OpenSubdiv's fractional weight. Under corners_plus1/plus2, a two-valued
//   vertex with semi-sharp edges in one region only sharpens the other too.
// The tags are computed on the control mesh and carried level to level, as
// OpenSubdiv carries them; the channel's values are made unique per vertex
// first (the same numbers), so each level's values belong to one vertex.

#include <cstdint>
#include <functional>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/tags.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/topology/split.h"

namespace subdiv::detail {

/// Child vertex i's mask, as the engine computes it for positions.
using ChildMask = std::function<void(Index child, MaskBuilder& mask)>;

/// Refines the face-varying channels of successive levels smoothly; one
/// object per refinement, called once per level in order.
class FaceVaryingRefiner {
 public:
  /// Whether `scheme` refines face-varying channels smoothly under `mode`.
  /// \param scheme the scheme of the level.
  /// \param mode the face-varying interpolation option.
  /// \return true unless mode is `all` or the scheme's traits say linear.
  static bool applies(const Scheme& scheme, FaceVaryingInterpolation mode) noexcept;

  /// \param mode the face-varying interpolation option (not `all`).
  /// \param boundary the boundary interpolation.
  FaceVaryingRefiner(FaceVaryingInterpolation mode, BoundaryInterpolation boundary);

  /// Replaces `child`'s face-varying channels (the split's linear ones)
  /// with the smooth ones refined from `parent`'s.
  /// \param parent the parent level (its channels and tags are read).
  /// \param topology the parent's topology.
  /// \param creasing the parent's creasing.
  /// \param map the quad or triangle split that made `child`.
  /// \param mask_of the engine's mask of a child vertex.
  /// \param child the child level; its face arrays must be the split's.
  /// \throws std::bad_alloc if memory runs out.
  void refine(const PolygonMesh& parent, const MeshTopology& topology, const LevelCreasing& creasing,
              const SplitMap& map, const ChildMask& mask_of, PolygonMesh& child);

  /// A value's tags (Vtr::FVarLevel::ValueTag's interpolation bits).
  struct ValueTag {
    bool mismatch = false;    ///< the vertex's values do not follow its topology
    bool crease = false;      ///< a smooth seam value (else, when mismatched, a corner)
    bool semi_sharp = false;  ///< a corner until its semi-sharp features decay
    bool dep_sharp = false;   ///< semi-sharp because the vertex's other value is
  };

 private:
  struct ChannelState {
    std::vector<ValueTag> tags;              ///< per value of the parent level
    std::vector<std::uint8_t> previous_edges;  ///< the previous parent level's edge tags
  };
  FaceVaryingInterpolation mode_;
  BoundaryInterpolation boundary_;
  bool started_ = false;
  SplitMap previous_map_;  ///< the split that made the current parent level
  std::vector<ChannelState> channels_;
};

}  // namespace subdiv::detail
