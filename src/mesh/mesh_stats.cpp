#include "subdiv/mesh/mesh_stats.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "union_find.h"

namespace subdiv {

namespace {

bool joins_itself(const MeshTopology& topo, Index e) { return topo.edge_vertices(e)[0] == topo.edge_vertices(e)[1]; }

}  // namespace

MeshStats compute_stats(const PolygonMesh& mesh, const MeshTopology& given) {
  // One edge per vertex pair: the keys merge the sides along each pair.
  std::optional<MeshTopology> merged;
  if (given.has_coincident_edges()) merged.emplace(mesh, std::vector<Index>(static_cast<std::size_t>(mesh.corner_count()), 0));
  const MeshTopology& topo = merged ? *merged : given;
  Index self_edges = 0;  // sides joining a vertex to itself, each an edge of the topology
  std::vector<Index> self_edges_at;
  if (topo.has_coincident_edges()) {
    self_edges_at.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
    for (Index e = 0; e < topo.edge_count(); ++e)
      if (joins_itself(topo, e)) {
        ++self_edges;
        ++self_edges_at[static_cast<std::size_t>(topo.edge_vertices(e)[0])];
      }
  }
  MeshStats s;
  s.vertices = mesh.vertex_count();
  s.faces = mesh.face_count();
  s.edges = topo.edge_count() - self_edges;
  s.corners = mesh.corner_count();

  detail::UnionFind components(mesh.face_count());  // faces joined through shared edges
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    const auto n = static_cast<Index>(face.size());
    ++s.face_sizes[n];
    if (n == 3) ++s.triangles;
    else if (n == 4) ++s.quads;
    else if (n >= 5) ++s.polygons;
    bool degenerate = n < 3;
    for (Index i = 0; i < n && !degenerate; ++i)
      for (Index j = i + 1; j < n; ++j)
        if (face[static_cast<std::size_t>(i)] == face[static_cast<std::size_t>(j)]) { degenerate = true; break; }
    if (degenerate) ++s.degenerate_faces;
  }

  Index used = 0;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (topo.vertex_kind(v) == VertexKind::isolated) {
      ++s.isolated_vertices;
      continue;
    }
    ++used;
    const Index k = topo.valence(v) - (self_edges_at.empty() ? 0 : 2 * self_edges_at[static_cast<std::size_t>(v)]);
    ++s.valences[k];
    s.max_valence = std::max(s.max_valence, k);
    if (topo.fan_count(v) > 1) ++s.non_manifold_vertices;
  }
  for (Index e = 0; e < topo.edge_count(); ++e) {
    if (self_edges > 0 && joins_itself(topo, e)) continue;
    const auto sides = topo.edge_corners(e);
    for (std::size_t i = 1; i < sides.size(); ++i)
      components.unite(topo.corner_face(sides[0]), topo.corner_face(sides[i]));
    if (topo.is_boundary_edge(e)) ++s.boundary_edges;
    if (topo.is_non_manifold_edge(e)) ++s.non_manifold_edges;
    if (topo.is_flipped_edge(e)) ++s.flipped_edges;
  }
  for (Index f = 0; f < mesh.face_count(); ++f)
    if (components.find(f) == f) ++s.components;
  // A boundary component of a single vertex is made of sides joining it to itself.
  s.boundary_loops = static_cast<Index>(std::count_if(topo.boundary_loops().begin(), topo.boundary_loops().end(),
                                                      [](const BoundaryLoop& l) { return l.vertices.size() > 1; }));
  s.euler_characteristic = static_cast<std::int64_t>(used) - s.edges + mesh.face_count();

  if (!mesh.positions.empty()) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    s.bbox_min = {inf, inf, inf};
    s.bbox_max = {-inf, -inf, -inf};
    for (const Vec3& p : mesh.positions)
      for (int i = 0; i < 3; ++i) {
        s.bbox_min[i] = std::min(s.bbox_min[i], p[i]);
        s.bbox_max[i] = std::max(s.bbox_max[i], p[i]);
      }
  }
  return s;
}

}  // namespace subdiv
