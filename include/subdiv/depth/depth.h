#pragma once
/// \file
/// The a priori depth of a mesh under a scheme: the bound (depth_bound.h)
/// measured on the mesh, what each level up to that depth costs, and a check
/// that refines and measures.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/depth/depth_bound.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// How depth_bound(), check_depth() and adaptive_refine() refine.
struct DepthOptions {
  /// Boundary interpolation and non-manifold handling, as for refine().
  RefineOptions refine;
};

/// The bound for `mesh` under `scheme`: Loop and Catmull-Clark as the paper
/// gives them, with a term for extraordinary vertices derived from the
/// analysis where the paper's argument does not reach (Catmull-Clark);
/// every other scheme from the analysis alone: the largest distance of a
/// control vertex to its limit, contracted per step by the slowest rate
/// among the configurations present, the rate of one step being the root of
/// the analysis's rate over its period (two steps for the sqrt3 split, with
/// a term for the distances one step in); composite schemes of the quad,
/// triangle and sqrt3 splits likewise. Interpolating schemes with wide
/// rules (the Butterflies, Kobbelt's, interpolatory-sqrt3 and
/// interpolating-sqrt2) are bounded on the level's linear surface against
/// the limit (DepthMeasure::surface_to_limit): the first steps' largest
/// displacement of new vertices from it, summed over the steps to come at
/// the slowest rate (docs/depth.md); on the sqrt3 and sqrt2 splits, whose
/// faces nest after two steps, in levels of two steps
/// (DepthBound::steps_per_level). A scheme with a two-step scheme
/// (Scheme::fast_path.two_steps: 4-8) is bounded through it, in levels of
/// two steps.
/// \param mesh The control mesh.
/// \param scheme The scheme.
/// \param options The refinement rules.
/// \param lines Where the mesh's elements were read from, for error
///        messages; nullptr: none.
/// \return The bound, with `scheme` set to \p scheme's name.
/// \throws InvalidInputError if depth_bound_unavailable() gives a reason,
///         some vertex's limit is only approximated after four isolation
///         levels (resolved_limit_distances()), an interpolating scheme's
///         regular rules give no contraction bound (or, on a mesh with a
///         boundary, its regular boundary rules cannot be read: the sqrt3
///         split's), an open sqrt3 mesh starts at an odd level,
///         refinement rejects the mesh (as refine() does: TopologyError,
///         ValidationError, ParameterError), limit positions fail (as
///         limit_positions() does), or a vertex's configuration has no rate
///         (the message names the vertex, with its file and line from
///         \p lines: an interior vertex of two triangles).
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
DepthBound depth_bound(const PolygonMesh& mesh, const Scheme& scheme, const DepthOptions& options = {},
                       const SourceLines* lines = nullptr);

/// Why depth_bound() refuses \p scheme whatever the mesh (schemes without
/// limit positions, composite schemes that end with a dual step, splits
/// without a bound, interpolating schemes with wide masks), or nothing where
/// a bound applies.
/// \param scheme The scheme.
/// \param options The refinement rules the scheme is analysed under.
/// \return The reason, one sentence; nullopt where a bound applies.
/// \throws InvalidInputError if the analysis of the scheme's regular
///         interior configuration fails (see interpolates_with_wide_masks()).
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
std::optional<std::string> depth_bound_unavailable(const Scheme& scheme, const DepthOptions& options = {});

/// Whether the scheme interpolates with masks wider than a face (the
/// Butterfly schemes, Kobbelt's): its vertices are on the limit surface from
/// the start, so their distance to it bounds nothing; depth_bound and
/// adaptive_refine refuse such schemes. Decided by analyze() at the regular
/// interior configuration (valence 4 for the quad split, else 6): its limit
/// mask is the centre alone over a neighbourhood wider than one ring.
/// \param scheme The scheme.
/// \param options The refinement rules the scheme is analysed under.
/// \return Whether the scheme interpolates with wide masks.
/// \throws InvalidInputError as analyze() does for that configuration (a
///         scheme the ring layout does not cover, a period below 1, rules
///         refinement rejects).
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
bool interpolates_with_wide_masks(const Scheme& scheme, const DepthOptions& options = {});

/// Size of the mesh after `level` uniform steps, counted from the control
/// mesh's topology alone (nothing is refined): exact for the quad, triangle
/// and dual splits, and for the sqrt3, sqrt2 and midedge splits on closed
/// meshes; an upper bound for the sqrt3 split's boundaries and for quasi
/// 4-8's geometric bisection.
struct LevelCost {
  int level = 0;              ///< the level (levels of two steps for 4-8)
  std::int64_t vertices = 0;  ///< vertex count
  std::int64_t faces = 0;     ///< face count
  std::int64_t edges = 0;     ///< edge count
  std::int64_t corners = 0;   ///< face corners (the sum of the face sizes)
  /// Positions (3 doubles per vertex) plus face arrays (one 32-bit index per
  /// corner and per face offset): what a PolygonMesh of that level holds.
  std::int64_t bytes = 0;
};

/// Levels 0 .. \p levels of \p mesh under \p scheme's split (4-8: levels of
/// two steps, as its bound counts them).
/// \param mesh The control mesh.
/// \param scheme The scheme whose split is counted.
/// \param levels The last level counted; below 0 gives no entries.
/// \return levels + 1 entries, level 0 first.
/// \throws InvalidInputError if the mesh's index arrays are malformed.
/// \throws std::bad_alloc if memory runs out.
std::vector<LevelCost> level_costs(const PolygonMesh& mesh, const Scheme& scheme, int levels);

/// What check_depth() measures: the bound at a depth against the real
/// vertex-to-limit distances there.
struct DepthCheck {
  int depth = 0;          ///< the level checked
  double bound = 0.0;     ///< the bound at `depth`
  /// After `depth` levels, the largest vertex-to-limit distance, or for a
  /// DepthMeasure::surface_to_limit bound the largest distance of the
  /// level's linear surface to the next level's vertices (on the limit).
  double measured = 0.0;
  /// The same one level less (when depth > 0): was depth - 1 already enough?
  bool has_previous = false;
  double measured_previous = 0.0;  ///< `measured` after `depth` - 1 levels
  Index approximated = 0;  ///< vertices whose limit is only approximated at `depth`
};

/// Refines \p depth levels (and depth - 1) of bound.steps_per_level steps
/// each and measures every vertex's distance to its limit position, both
/// with the scheme's own steps and limits; for a
/// DepthMeasure::surface_to_limit bound, the level's linear surface against
/// the scheme's next level (whose vertices are on the limit).
/// \param mesh The control mesh.
/// \param scheme The scheme.
/// \param bound The bound checked (its `steps_per_level` and at()).
/// \param depth The level checked; 0 measures the control mesh.
/// \param options The refinement rules.
/// \return The bound and the measured distances at \p depth (and
///         \p depth - 1 when \p depth > 0).
/// \throws InvalidInputError if refinement rejects the mesh (as refine()
///         does) or limit positions fail (as limit_positions() does).
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
DepthCheck check_depth(const PolygonMesh& mesh, const Scheme& scheme, const DepthBound& bound, int depth,
                       const DepthOptions& options = {});

}  // namespace subdiv
