#pragma once
// The engine's side of hierarchical edits: each edit's face followed down
// the quad split's levels, and the edits of a level applied as it is made.

#include <vector>

#include "subdiv/mesh/topology.h"
#include "subdiv/refine/hierarchical_edits.h"

namespace subdiv::detail {

class EditFollower {
 public:
  /// Every path starts at its control face, on level 0.
  explicit EditFollower(HierarchicalEdits edits);
  EditFollower(const EditFollower&) = delete;  // holds pointers into its edits
  EditFollower& operator=(const EditFollower&) = delete;

  /// The deepest level an edit applies on (-1: none).
  int deepest_level() const noexcept { return edits_.deepest_level(); }
  /// Whether an edit applies on `level`.
  bool edits_level(int level) const noexcept;
  /// Follows the paths from `parent_level` (its topology) one level down.
  void descend(const MeshTopology& parent, int parent_level);
  /// Applies the edits of `level` to it: positions, corner and crease
  /// tags, holes. `mesh` has its faces.
  void apply(int level, PolygonMesh& mesh) const;

 private:
  struct Located {
    const EditPath* path;
    Index face;    // on the level reached
    int rotation;  // Hbr's corner i is this face's corner i - rotation
  };
  HierarchicalEdits edits_;
  std::vector<Located> located_;  // values, then sharpnesses, then holes
};

}  // namespace subdiv::detail
