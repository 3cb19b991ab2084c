#include "refined_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/topology/split.h"

namespace subdiv::detail {

namespace {

// The most faces a kept level may have (the levels above it add a third).
constexpr Index kMaxFaces = Index{1} << 22;

/// The options limit_positions() is called with on a level `levels_made`
/// steps below the control mesh.
LimitOptions limit_options(const RefineOptions& options, int levels_made, bool normals) {
  LimitOptions limit;
  limit.normals = normals;
  // The generic masks apply once extraordinary vertices are two levels
  // apart: the levels made count (else an interpolating scheme's last level
  // would be refined twice more, sixteen times its faces).
  limit.isolation_levels = std::max(0, limit.isolation_levels - levels_made);
  limit.refine = options;
  limit.refine.levels = 0;
  limit.refine.on_level = nullptr;
  return limit;
}

/// The level's limit positions, with normals where they come with them (an
/// interpolating scheme's vertices are on the limit already: its normals
/// are left empty for the last level alone), and how many no mask reached.
LimitResult limits_of(const PolygonMesh& level, int levels_made, const Scheme& scheme, const RefineOptions& options) {
  if (scheme.traits.interpolating) {
    LimitResult result;
    result.positions = level.positions;
    return result;
  }
  return limit_positions(level, scheme, limit_options(options, levels_made, true));
}

/// The largest distance between the child's limit points and the parent's
/// interpolant at their parameters: an edge's midpoint (both ends' mean; the
/// interpolant along an edge is linear in both its faces) and, for the quad
/// split, a quad's centre (its corners' mean). Edges and faces of faces of
/// another size than the split's (a quad split's n-gons, whose ptex faces
/// start one level down) are not measured. nullopt where nothing is.
std::optional<double> change(const PolygonMesh& parent, const std::vector<Vec3>& parent_limits, const SplitMap& map,
                             const std::vector<Vec3>& child_limits, bool quads) {
  const MeshTopology t(parent);
  const Index regular = quads ? 4 : 3;
  const auto at = [](const std::vector<Vec3>& p, Index i) { return p[static_cast<std::size_t>(i)]; };
  double largest = 0.0;
  bool measured = false;
  for (Index e = 0; e < t.edge_count(); ++e) {
    bool regular_faces = true;
    for (const Index c : t.edge_corners(e)) regular_faces = regular_faces && t.face_size(t.corner_face(c)) == regular;
    if (!regular_faces) continue;
    const auto [a, b] = t.edge_vertices(e);
    const Vec3 interpolant = 0.5 * (at(parent_limits, a) + at(parent_limits, b));
    largest = std::max(largest, norm(at(child_limits, map.edge_point(e)) - interpolant));
    measured = true;
  }
  if (quads) {
    for (Index f = 0; f < t.face_count(); ++f) {
      if (t.face_size(f) != 4) continue;
      Vec3 interpolant{};
      for (const Index v : t.face_vertices(f)) interpolant += 0.25 * at(parent_limits, v);
      largest = std::max(largest, norm(at(child_limits, map.face_point(f)) - interpolant));
      measured = true;
    }
  }
  if (!measured) return std::nullopt;
  return largest;
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

}  // namespace

std::optional<std::string> refined_evaluation_unavailable(const Scheme& scheme) {
  if (scheme.split != SplitRule::quad && scheme.split != SplitRule::triangle)
    return std::string(
               "evaluation at (face, u, v) needs a split that divides each face into sub-faces (the quad or "
               "triangle split); the ") +
           to_string(scheme.split) + " does not";
  if (const auto reason = limit_unavailable(scheme)) return reason;
  return std::nullopt;
}

RefinedSurface refine_to_accuracy(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options,
                                  double accuracy, int max_levels) {
  if (!(accuracy > 0.0) || !std::isfinite(accuracy))
    throw InvalidInputError("approximate evaluation: the accuracy must be positive and finite, not " +
                            number(accuracy));
  if (const auto reason = refined_evaluation_unavailable(scheme))
    throw InvalidInputError("approximate evaluation: " + std::string(scheme.name) + ": " + *reason);
  const bool quads = scheme.split == SplitRule::quad;
  RefineOptions one = options;
  one.levels = 0;
  one.start_level = 0;
  RefinedSurface out;
  out.hierarchy = refine_hierarchy(mesh, scheme, one, KeepLevels::all);
  LimitResult limits = limits_of(mesh, 0, scheme, options);
  // One level's change can vanish by symmetry (the Butterfly's edge points
  // on a regular tetrahedron are midpoints, the next level's are not): two
  // levels in a row must be within the accuracy.
  std::optional<double> reached, before;
  const auto done = [&] { return reached && before && std::max(*reached, *before) <= accuracy; };
  for (int level = 1; !done(); ++level) {
    const PolygonMesh& finest = out.hierarchy.finest().mesh;
    const Index faces = quads ? finest.corner_count() : 4 * finest.face_count();
    const std::string so_far =
        reached ? " (the change measured at level " + std::to_string(level - 1) + " is " + number(*reached) + ")" : "";
    if (level > max_levels)
      throw InvalidInputError("approximate evaluation: accuracy " + number(accuracy) + " not reached within " +
                              std::to_string(max_levels) + " levels" + so_far);
    if (faces > kMaxFaces)
      throw InvalidInputError("approximate evaluation: accuracy " + number(accuracy) + " would need level " +
                              std::to_string(level) + " with " + std::to_string(faces) + " faces, more than " +
                              std::to_string(kMaxFaces) + so_far);
    refine_further(out.hierarchy, scheme, 1, one, KeepLevels::all);
    LimitResult child = limits_of(out.hierarchy.finest().mesh, level, scheme, options);
    const HierarchyLevel& parent = out.hierarchy.levels[out.hierarchy.levels.size() - 2];
    const auto measured =
        change(parent.mesh, limits.positions, *out.hierarchy.finest().map, child.positions, quads);
    if (measured) {
      before = reached;
      reached = measured;
    }
    limits = std::move(child);
  }
  out.measured_change = std::max(*reached, *before);
  out.unresolved = limits.approximated;
  PolygonMesh& last = out.hierarchy.levels.back().mesh;
  // An interpolating scheme's normals, from the masks where they apply.
  if (limits.normals.empty()) {
    const int levels_made = static_cast<int>(out.hierarchy.levels.size()) - 1;
    limits.normals = limit_positions(last, scheme, limit_options(options, levels_made, true)).normals;
  }
  // An interior vertex on a crease has a normal per side, and the masks give
  // one: none is kept there, and the faces around take their own du x dv.
  const MeshTopology t(last);
  const LevelCreasing creasing = compute_creasing(last, t, boundary_of(last, options), crease_method_of(last, options));
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const VertexRule rule = creasing.vertex_rule[static_cast<std::size_t>(v)];
    if (t.vertex_kind(v) == VertexKind::interior && (rule == VertexRule::crease || rule == VertexRule::corner))
      limits.normals[static_cast<std::size_t>(v)] = Vec3{};
  }
  last.positions = std::move(limits.positions);
  out.normals = std::move(limits.normals);
  return out;
}

}  // namespace subdiv::detail
