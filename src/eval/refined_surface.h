#pragma once
// Approximate evaluation's levels: the uniform refinement, kept level by
// level, down to the first level whose vertices' limit points lie within the
// requested accuracy of the previous level's interpolant (the piecewise
// bilinear or linear surface through that level's limit points, over the
// ptex parameter). Its last level holds limit positions and normals.

#include <optional>
#include <string>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

/// The levels refine_to_accuracy() made.
struct RefinedSurface {
  Hierarchy hierarchy;        ///< every level, the last one's positions moved to their limits
  std::vector<Vec3> normals;  ///< the last level's limit normals (zero where none)
  /// The largest distance, at the last level's new vertices, between their
  /// limit points and the previous level's interpolant at their parameter.
  double measured_change = 0.0;
  Index unresolved = 0;  ///< last-level vertices whose limit no mask gave (left where refinement put them)
};

/// Why \p scheme has no evaluation by refinement, or nullopt: it needs a
/// split that divides each face into sub-faces (quad or triangle) and limit
/// positions (not composite schemes).
std::optional<std::string> refined_evaluation_unavailable(const Scheme& scheme);

/// Refines \p mesh until the measured change is at most \p accuracy (at
/// least one level; a level with nothing to measure, such as the first
/// level below n-gons, does not count).
/// \throws InvalidInputError where \p accuracy is not positive and finite,
///   the scheme has no such evaluation, or the accuracy is not reached
///   within \p max_levels or within the memory budget (refused before the
///   level is made, with the change measured so far).
/// \throws what refine_hierarchy() and limit_positions() throw.
RefinedSurface refine_to_accuracy(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                                  double accuracy, int max_levels);

}  // namespace subdiv::detail
