#include "subdiv/depth/mesh_measures.h"

#include <algorithm>

#include "subdiv/mesh/topology.h"

namespace subdiv {

double max_second_difference(const PolygonMesh& mesh) {
  const MeshTopology t(mesh);
  const auto position = [&](Index v) { return mesh.positions[static_cast<std::size_t>(v)]; };
  double worst = 0.0;
  const auto line = [&](Index v, Index a, Index b) {
    worst = std::max(worst, norm(position(a) - 2.0 * position(v) + position(b)));
  };
  for (Index v = 0; v < t.vertex_count(); ++v) {
    if (!t.ring_ordered(v)) continue;
    const auto edges = t.vertex_edges(v);
    const auto neighbour = [&](std::size_t j) { return t.other_vertex(edges[j], v); };
    // Counter-clockwise edges: opposite edges of a 4-valent vertex continue
    // each other, as do the two boundary edges of a 3-valent boundary vertex.
    if (t.vertex_kind(v) == VertexKind::interior && edges.size() == 4 && t.vertex_face_count(v) == 4) {
      line(v, neighbour(0), neighbour(2));
      line(v, neighbour(1), neighbour(3));
    } else if (t.vertex_kind(v) == VertexKind::boundary && edges.size() == 3) {
      line(v, neighbour(0), neighbour(2));
    }
  }
  return worst;
}

LimitDistances limit_distances(const PolygonMesh& mesh, const Scheme& scheme, const LimitOptions& options) {
  LimitOptions positions_only = options;
  positions_only.normals = false;
  const LimitResult limit = limit_positions(mesh, scheme, positions_only);
  LimitDistances out;
  out.approximated = limit.approximated;
  out.distances.resize(mesh.positions.size());
  out.approximated_vertices.resize(mesh.positions.size());
  for (std::size_t v = 0; v < limit.sources.size() && v < mesh.positions.size(); ++v)
    out.approximated_vertices[v] = limit.sources[v] == LimitSource::refined_position ? 1 : 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    out.distances[v] = norm(mesh.positions[v] - limit.positions[v]);
    if (out.distances[v] > out.max || out.max_vertex == kInvalidIndex) {
      out.max = out.distances[v];
      out.max_vertex = static_cast<Index>(v);
    }
  }
  return out;
}

LimitDistances resolved_limit_distances(const PolygonMesh& mesh, const Scheme& scheme, LimitOptions options) {
  constexpr int kMostIsolationLevels = 4;
  LimitDistances distances = limit_distances(mesh, scheme, options);
  while (distances.approximated > 0 && options.isolation_levels < kMostIsolationLevels) {
    ++options.isolation_levels;
    LimitDistances more = limit_distances(mesh, scheme, options);
    if (more.approximated >= distances.approximated) break;
    distances = std::move(more);
  }
  return distances;
}

}  // namespace subdiv
