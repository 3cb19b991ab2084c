#pragma once
/// \file
/// Refinement as a hierarchy: every level a complete mesh, never edited,
/// linked to its parent level by its split's map, and numbered by its level,
/// which is the split's state (the sqrt3 split trisects boundary edges on
/// every second step, counted from the control mesh). Refining a hierarchy
/// further continues from its finest level, so refining one level at a time
/// gives what refining all levels at once gives, bit for bit.

#include <cstdint>
#include <optional>
#include <vector>

#include "subdiv/refine/refine.h"

namespace subdiv {

/// Where a child vertex comes from in its parent level.
struct ChildOrigin {
  /// The kind of parent element.
  enum class Kind : std::uint8_t {
    vertex,          ///< a vertex point: `parent` is the parent vertex
    edge,            ///< an edge point (midedge child, quasi 4-8 split point): `parent` is the parent edge
    face,            ///< a face point: `parent` is the parent face
    corner,          ///< a corner point (dual split): `parent` is the parent face corner
    /// One of the two points cut from a boundary edge (dual split, trisecting
    /// sqrt3 steps): `parent` is the parent edge.
    boundary_point,
  };
  Kind kind = Kind::vertex;  ///< the kind of parent element
  Index parent = -1;         ///< the parent element's index (vertex, edge, face or corner)
};

/// The origin of child vertex `child` of a level split by `map`. Parent
/// edges and corners are numbered as MeshTopology(parent mesh) numbers them.
/// \param map the level's split.
/// \param child a child vertex.
/// \return its parent element.
/// \throws InvalidInputError if \p child is outside [0, map.child_vertex_count).
ChildOrigin origin_of(const SplitMap& map, Index child);

/// One level of a Hierarchy.
struct HierarchyLevel {
  PolygonMesh mesh;  ///< the level's complete mesh
  /// Steps from the control mesh (0 for the control mesh itself).
  int level = 0;
  /// The split that made this level from the previous one; empty for the
  /// control mesh. For a level made by a composite scheme (its smoothing
  /// steps keep the numbering) or by two steps at once it is the split that
  /// numbers the level's vertices. Quasi 4-8's bisection reads positions:
  /// its map holds the edges it split.
  std::optional<SplitMap> map;
};

/// Which levels a Hierarchy keeps.
enum class KeepLevels {
  all,   ///< every level, the control mesh first
  last,  ///< the finest level only: the memory of refine()
};

/// Refined levels, each a complete mesh linked to its parent by its split.
struct Hierarchy {
  std::vector<HierarchyLevel> levels;  ///< coarsest kept first; never empty once made
  /// The finest level.
  /// \return levels.back().
  /// \pre `levels` is not empty (unchecked; refine_hierarchy() never makes
  ///   an empty one).
  const HierarchyLevel& finest() const noexcept { return levels.back(); }
};

/// Refines `mesh` (at level options.start_level) options.levels steps with
/// `scheme`. With KeepLevels::all every level is made (4-8's two steps at
/// once are not taken, since they skip a level); with KeepLevels::last this
/// is refine() with the level number kept (without the grid path).
/// Hierarchical edits are applied to each level as refine() applies them;
/// the levels drop the edit tags, so refine_further() does not apply edits
/// below the hierarchy's finest level.
/// \param mesh the mesh to refine, at level options.start_level.
/// \param scheme the scheme.
/// \param options the rule choices and run controls (options.on_level is
///   called after each level).
/// \param keep which levels to keep.
/// \param lines where given, the source lines that errors name.
/// \return the hierarchy: options.levels + 1 levels, or one with
///   KeepLevels::last.
/// \throws InvalidInputError, ParameterError or ValidationError as
///   check_refinable() does; InvalidInputError also where a position of the
///   finest level is not finite (an overflow, as refine() says).
/// \throws TopologyError where a split refuses a level (see split_topology()).
/// \throws std::bad_alloc if memory runs out.
Hierarchy refine_hierarchy(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options = {},
                           KeepLevels keep = KeepLevels::all, const SourceLines* lines = nullptr);

/// Refines the finest level `levels` more steps, continuing at its level
/// number (options.levels and options.start_level are not read), and
/// appends the new levels (KeepLevels::last: replaces the levels with the
/// finest). `scheme` and the rule options must be those the hierarchy was
/// made with.
/// \param hierarchy the hierarchy to extend, not empty.
/// \param scheme the scheme the hierarchy was made with.
/// \param levels the steps to add, >= 0.
/// \param options the rule choices and run controls.
/// \param keep which of the new levels to keep.
/// \throws InvalidInputError if \p hierarchy has no level, or as
///   refine_hierarchy() does (ParameterError, ValidationError, TopologyError
///   included).
/// \throws std::bad_alloc if memory runs out.
void refine_further(Hierarchy& hierarchy, const Scheme& scheme, int levels, const RefineOptions& options = {},
                    KeepLevels keep = KeepLevels::all);

}  // namespace subdiv
