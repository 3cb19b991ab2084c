// Two steps of the sqrt3 or sqrt2 split with every vertex on the level's
// linear surface (nested_linear_surface.h). Each step's new vertices are
// placed by where the split makes them:
//
//   first step: a face point at its face's centre (the mean of its corners:
//     the centroid of a triangle, the bilinear centre of a quad);
//   second step: the first step's child faces belong to the level's edges
//     (sqrt3: two per interior edge (a, b), each with one old vertex, a;
//     sqrt2: one per edge, with both ends). A face point of such a face lies
//     on its edge: at the third next to a (sqrt3), at the midpoint (sqrt2).
//     The sqrt3 split's boundary points trisect boundary edges, which are
//     the level's own edges on that step.
//
// Old vertices keep their positions. The split's numbering (SplitMap) says
// which child vertex is which, and the child faces follow the parent's edges
// in edge order (src/topology/sqrt3_split.cpp, sqrt2_split.cpp).

#include "depth/nested_linear_surface.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"

namespace subdiv::detail {

namespace {

// The split's first step: face points at their faces' centres.
void place_face_centres(const PolygonMesh& level, const SplitMap& map, PolygonMesh& child) {
  const Index face_points = map.edge_points - map.face_points;
  for (Index i = 0; i < face_points; ++i) {
    const Index f = map.point_face(i);
    Vec3 sum{};
    for (Index c = level.face_offsets[f]; c < level.face_offsets[f + 1]; ++c)
      sum = sum + level.positions[level.face_indices[c]];
    child.positions[map.face_points + i] = (1.0 / level.face_size(f)) * sum;
  }
}

// Boundary points (the sqrt3 split's trisecting steps) at the thirds of
// their edges, the one near edge_vertices(e)[0] first.
void place_boundary_thirds(const PolygonMesh& parent, const MeshTopology& topology, const SplitMap& map,
                           PolygonMesh& child) {
  for (std::size_t k = 0; k < map.boundary_edges.size(); ++k) {
    const auto [a, b] = topology.edge_vertices(map.boundary_edges[k]);
    const Vec3 pa = parent.positions[a], pb = parent.positions[b];
    child.positions[map.edge_points + 2 * static_cast<Index>(k)] = (1.0 / 3.0) * (2.0 * pa + pb);
    child.positions[map.edge_points + 2 * static_cast<Index>(k) + 1] = (1.0 / 3.0) * (pa + 2.0 * pb);
  }
}

void keep_old_vertices(const PolygonMesh& parent, const SplitMap& map, PolygonMesh& child) {
  for (Index v = 0; v < parent.vertex_count(); ++v) child.positions[map.vertex_point(v)] = parent.positions[v];
}

// The level's edge each first-step child face belongs to: the faces follow
// the edges in order, one per edge of the sqrt2 split, two per interior edge
// and one per boundary edge of the sqrt3 split.
std::vector<Index> parent_edges_of_faces(const MeshTopology& level, SplitRule rule, Index child_faces) {
  std::vector<Index> edge_of;
  edge_of.reserve(static_cast<std::size_t>(child_faces));
  for (Index e = 0; e < level.edge_count(); ++e) {
    const int faces = rule == SplitRule::sqrt3 && !level.is_boundary_edge(e) ? 2 : 1;
    for (int i = 0; i < faces; ++i) edge_of.push_back(e);
  }
  if (static_cast<Index>(edge_of.size()) != child_faces)
    throw std::logic_error("nested_linear_refinement: the split's child faces do not follow the level's edges");
  return edge_of;
}

// The second step's face points, on the level's edges.
void place_edge_points(const PolygonMesh& level, const MeshTopology& level_topology, const SplitMap& first,
                       const PolygonMesh& middle, const SplitMap& second, SplitRule rule, PolygonMesh& fine) {
  const std::vector<Index> edge_of = parent_edges_of_faces(level_topology, rule, middle.face_count());
  const Index face_points = second.edge_points - second.face_points;
  for (Index i = 0; i < face_points; ++i) {
    const Index m = second.point_face(i);
    const auto [a, b] = level_topology.edge_vertices(edge_of[static_cast<std::size_t>(m)]);
    Vec3 point{};
    if (rule == SplitRule::sqrt2) {
      point = 0.5 * (level.positions[a] + level.positions[b]);
    } else {
      // The face's one old vertex is the end its third is next to.
      Index old = kInvalidIndex;
      int olds = 0;
      for (Index c = middle.face_offsets[m]; c < middle.face_offsets[m + 1]; ++c)
        if (const Index u = middle.face_indices[c]; u >= first.vertex_points) {
          old = u - first.vertex_points;
          ++olds;
        }
      if (olds != 1 || (old != a && old != b))
        throw std::logic_error("nested_linear_refinement: a sqrt3 child face with a face point has " +
                               std::to_string(olds) + " old vertices, not one end of its edge");
      const Index other = old == a ? b : a;
      point = (1.0 / 3.0) * (2.0 * level.positions[old] + level.positions[other]);
    }
    fine.positions[second.face_points + i] = point;
  }
}

bool has_boundary(const MeshTopology& topology) {
  for (Index e = 0; e < topology.edge_count(); ++e)
    if (topology.is_boundary_edge(e)) return true;
  return false;
}

}  // namespace

PolygonMesh nested_linear_refinement(const PolygonMesh& level, int level_number, SplitRule rule) {
  if (rule != SplitRule::sqrt3 && rule != SplitRule::sqrt2)
    throw InvalidInputError(std::string("the nested linear surface is written for the sqrt3 and sqrt2 splits, not the ") +
                            to_string(rule));
  const Index sides = rule == SplitRule::sqrt3 ? 3 : 4;
  for (Index f = 0; f < level.face_count(); ++f)
    if (level.face_size(f) != sides)
      throw InvalidInputError("the " + std::string(to_string(rule)) + " nests over two steps on faces of " +
                              std::to_string(sides) + " sides, but face " + std::to_string(f) + " has " +
                              std::to_string(level.face_size(f)));
  PolygonMesh bare;
  bare.positions = level.positions;
  bare.face_offsets = level.face_offsets;
  bare.face_indices = level.face_indices;
  const MeshTopology topology(bare);
  if (has_boundary(topology)) {
    if (rule == SplitRule::sqrt2)
      throw InvalidInputError("the sqrt2 split has no boundary rule: the nested linear surface needs a closed mesh");
    if (sqrt3_step_trisects(level_number))
      throw InvalidInputError("the sqrt3 split nests over two steps on an open mesh only from an even level: from "
                              "level " + std::to_string(level_number) +
                              " the first step trisects the boundary and the second step's triangles at the "
                              "boundary straddle two of the level's faces");
  }

  SplitOptions options;
  options.level = level_number;
  PolygonMesh middle;
  const SplitMap first = split_topology(bare, topology, rule, middle, options);
  place_face_centres(bare, first, middle);
  place_boundary_thirds(bare, topology, first, middle);
  keep_old_vertices(bare, first, middle);
  middle.tags = {};
  middle.face_varying_channels.clear();

  const MeshTopology middle_topology(middle);
  options.level = level_number + 1;
  PolygonMesh fine;
  const SplitMap second = split_topology(middle, middle_topology, rule, fine, options);
  place_edge_points(bare, topology, first, middle, second, rule, fine);
  place_boundary_thirds(middle, middle_topology, second, fine);
  keep_old_vertices(middle, second, fine);
  fine.tags = {};
  fine.face_varying_channels.clear();
  return fine;
}

}  // namespace subdiv::detail
