#pragma once
// A vertex's limit position and tangents from its scheme's closed-form masks
// (rules/limit_mask.h), on a refined level where the masks apply.

#include <optional>
#include <span>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

struct VertexLimit {
  Vec3 position;
  Vec3 tangent1;
  Vec3 tangent2;
  /// From the eigenvectors of the vertex's own matrix (a dart), not the
  /// scheme's closed forms.
  bool eigenvectors = false;
};

/// The level a vertex is evaluated on: its topology, creasing, positions,
/// and which vertices carry a finite (semi-sharp) vertex sharpness.
struct LimitLevel {
  const MeshTopology& topology;
  const LevelCreasing& creasing;
  std::span<const Vec3> positions;
  std::span<const char> semi_sharp_vertex;
};

/// nullopt where the scheme's masks do not apply: a non-manifold vertex, a
/// face of another size than the split's, a semi-sharp edge or vertex sharpness
/// still to resolve, or a neighbourhood the scheme has no closed form for.
/// Darts take their own matrix's eigenvectors (dart_limit.h).
std::optional<VertexLimit> closed_form_limit(const Scheme& scheme, const LimitLevel& level, Index v,
                                             LimitMasks& scratch);

}  // namespace subdiv::detail
