#pragma once
// Refinement as a hierarchy: every level a complete mesh, never edited,
// linked to its parent level by its split's map, and numbered by its level,
// which is the split's state (the sqrt3 split trisects boundary edges on
// every second step, counted from the control mesh). Refining a hierarchy
// further continues from its finest level, so refining one level at a time
// gives what refining all levels at once gives, bit for bit.

#include <cstdint>
#include <optional>
#include <vector>

#include "subdiv/refine/refine.h"

namespace subdiv {

/// Where a child vertex comes from in its parent level.
struct ChildOrigin {
  enum class Kind : std::uint8_t {
    vertex,          ///< a vertex point: `parent` is the parent vertex
    edge,            ///< an edge point: `parent` is the parent edge
    face,            ///< a face point: `parent` is the parent face
    corner,          ///< a corner point (dual split): `parent` is the parent face corner
    boundary_point,  ///< one of the two points cut from a boundary edge (dual, trisecting sqrt3 steps)
  };
  Kind kind = Kind::vertex;
  Index parent = -1;
};

/// The origin of child vertex `child` of a level split by `map`. Parent
/// edges and corners are numbered as MeshTopology(parent mesh) numbers them.
/// Throws InvalidInputError for a child outside the map.
ChildOrigin origin_of(const SplitMap& map, Index child);

struct HierarchyLevel {
  PolygonMesh mesh;
  /// Steps from the control mesh (0 for the control mesh itself).
  int level = 0;
  /// The split that made this level from the previous one; empty for the
  /// control mesh. For a level made by a composite scheme (its smoothing
  /// steps keep the numbering) or by two steps at once it is the split that
  /// numbers the level's vertices. Quasi 4-8's bisection reads positions:
  /// its map holds the edges it split.
  std::optional<SplitMap> map;
};

enum class KeepLevels {
  all,   ///< every level, the control mesh first
  last,  ///< the finest level only: the memory of refine()
};

struct Hierarchy {
  std::vector<HierarchyLevel> levels;  ///< coarsest kept first; never empty once made
  const HierarchyLevel& finest() const { return levels.back(); }
};

/// Refines `mesh` (at level options.start_level) options.levels steps with
/// `scheme`. With KeepLevels::all every level is made (4-8's two steps at
/// once are not taken, since they skip a level); with KeepLevels::last this
/// is refine() with the level number kept. Throws as refine() does.
Hierarchy refine_hierarchy(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options = {},
                           KeepLevels keep = KeepLevels::all, const SourceLines* lines = nullptr);

/// Refines the finest level `levels` more steps, continuing at its level
/// number (options.levels and options.start_level are not read), and
/// appends the new levels (KeepLevels::last: replaces the levels with the
/// finest). `scheme` and the rule options must be those the hierarchy was
/// made with.
void refine_further(Hierarchy& hierarchy, const Scheme& scheme, int levels, const RefineOptions& options = {},
                    KeepLevels keep = KeepLevels::all);

}  // namespace subdiv
