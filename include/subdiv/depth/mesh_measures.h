#pragma once
/// \file
/// The quantities the depth bounds start from, measured on a control mesh.

#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/analysis/limit.h"

namespace subdiv {

/// The largest second difference |P_a - 2 P_v + P_b| over the mesh lines:
/// through every interior vertex with 4 edges and 4 faces, the two pairs of
/// opposite neighbours; through every boundary vertex with 3 edges, its two
/// boundary neighbours. These are Cheng's M (Catmull-Clark) and the paper's
/// M for Doo-Sabin on a grid; vertices of other valences have no lines.
/// \param mesh The mesh.
/// \return The largest second difference (mesh units), 0 when no vertex has
///         lines.
/// \throws InvalidInputError if the mesh's index arrays are malformed.
/// \throws std::bad_alloc if memory runs out.
double max_second_difference(const PolygonMesh& mesh);

/// Each vertex's distance to its limit position, and the largest.
struct LimitDistances {
  std::vector<double> distances;  ///< |P_v - limit(P_v)| per vertex
  double max = 0.0;               ///< the largest distance; 0 for a mesh without vertices
  Index max_vertex = kInvalidIndex;  ///< a vertex at `max` (the first); kInvalidIndex without vertices
  Index approximated = 0;  ///< vertices whose limit is only approximated (see LimitResult)
  /// Per vertex, 1 where its limit is only approximated (its distance is to
  /// its refined position, LimitSource::refined_position).
  std::vector<char> approximated_vertices;
};

/// Every vertex's distance to its limit position under \p scheme
/// (through limit_positions(), without normals).
/// \param mesh The mesh.
/// \param scheme The scheme.
/// \param options The limit options (`normals` is ignored).
/// \return The distances, the largest and where it is.
/// \throws InvalidInputError as limit_positions() does: a composite or
///         midedge scheme, negative caps, or a mesh refinement rejects.
/// \throws Error if the Schur iteration of an eigenvalue computation does not
///         converge.
/// \throws std::bad_alloc if memory runs out.
LimitDistances limit_distances(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options = {});

/// limit_distances(), with LimitOptions::isolation_levels raised one at a
/// time, up to 4, while some vertices' limits are only approximated and
/// each raise resolves more of them: schemes with wide rules (composite
/// sqrt3) need their extraordinary vertices further apart than two levels
/// leave them. The result's `approximated` is what remains.
/// \param mesh The mesh.
/// \param scheme The scheme.
/// \param options The limit options; `isolation_levels` is where the search starts.
/// \return The distances, as limit_distances().
/// \throws As limit_distances().
LimitDistances resolved_limit_distances(const PolygonMesh& mesh, const Scheme& scheme, LimitOptions options = {});

}  // namespace subdiv
