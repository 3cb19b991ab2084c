#pragma once
// The a priori depth of a mesh under a scheme: the bound (depth_bound.h)
// measured on the mesh, what each level up to that depth costs, and a check
// that refines and measures.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/depth/depth_bound.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

struct DepthOptions {
  /// Boundary interpolation and non-manifold handling, as for refine().
  RefineOptions refine;
};

/// The bound for `mesh` under `scheme`: Loop and Catmull-Clark as the paper
/// gives them, with a term for extraordinary vertices derived from the
/// analysis where the paper's argument does not reach (Catmull-Clark);
/// every other scheme from the analysis alone: the largest distance of a
/// control vertex to its limit, contracted per step by the slowest rate
/// among the configurations present (docs/depth.md). A scheme
/// with a two-step scheme (Scheme::fast_path.two_steps: 4-8) is bounded through it,
/// in levels of two steps (DepthBound::steps_per_level).
/// Throws as refine() does for meshes it cannot refine, and
/// InvalidInputError naming a vertex (with its file and line from `lines`)
/// whose configuration the analysis has no rate for (an interior vertex of
/// two triangles).
DepthBound depth_bound(const PolygonMesh& mesh, const Scheme& scheme, const DepthOptions& options = {},
                       const SourceLines* lines = nullptr);

/// Why depth_bound() refuses `scheme` whatever the mesh (composite schemes,
/// splits without a bound, interpolating schemes with wide masks), or
/// nothing where a bound applies.
std::optional<std::string> depth_bound_unavailable(const Scheme& scheme, const DepthOptions& options = {});

/// Whether the scheme interpolates with masks wider than a face (the
/// Butterfly schemes, Kobbelt's): its vertices are on the limit surface from
/// the start, so their distance to it bounds nothing; depth_bound and
/// adaptive_refine refuse such schemes.
bool interpolates_with_wide_masks(const Scheme& scheme, const DepthOptions& options = {});

/// Size of the mesh after `level` uniform steps, counted from the control
/// mesh's topology alone (nothing is refined): exact for the quad, triangle
/// and dual splits, and for the sqrt3, sqrt2 and midedge splits on closed
/// meshes; an upper bound for the sqrt3 split's boundaries and for quasi
/// 4-8's geometric bisection.
struct LevelCost {
  int level = 0;
  std::int64_t vertices = 0;
  std::int64_t faces = 0;
  std::int64_t edges = 0;
  std::int64_t corners = 0;
  /// Positions (3 doubles per vertex) plus face arrays (one 32-bit index per
  /// corner and per face offset): what a PolygonMesh of that level holds.
  std::int64_t bytes = 0;
};

/// Levels 0 .. `levels` of `mesh` under `scheme`'s split (4-8: levels of
/// two steps, as its bound counts them).
std::vector<LevelCost> level_costs(const PolygonMesh& mesh, const Scheme& scheme, int levels);

struct DepthCheck {
  int depth = 0;
  double bound = 0.0;     ///< the bound at `depth`
  double measured = 0.0;  ///< largest vertex-to-limit distance after `depth` levels
  /// The same one level less (when depth > 0): was depth - 1 already enough?
  bool has_previous = false;
  double measured_previous = 0.0;
  Index approximated = 0;  ///< vertices whose limit is only approximated at `depth`
};

/// Refines `depth` levels (and depth - 1) of bound.steps_per_level steps
/// each and measures every vertex's distance to its limit position, both
/// with the scheme's own steps and limits.
DepthCheck check_depth(const PolygonMesh& mesh, const Scheme& scheme, const DepthBound& bound, int depth,
                       const DepthOptions& options = {});

}  // namespace subdiv
