// Sqrt3 split (TP, arity sqrt 3; L. Kobbelt, "sqrt(3)-subdivision",
// SIGGRAPH 2000): every triangle gets a face point, and every interior edge
// (a, b) between faces F and G is flipped into the edge joining their
// points, which makes the two child triangles (a, point(G), point(F)) and
// (b, point(F), point(G)) (for the side of F that runs a -> b). Two steps
// trisect every old edge: the child level of the child level is the
// parent's triangles split 1-to-9, aligned with them.
//
// Boundaries follow Kobbelt's alternation, which keeps the boundary polygon
// a refinement of the parent's by thirds every second step:
//   odd steps (levels 0, 2, 4, ... of the refined mesh, counted from the
//     control mesh): every face gets a face point, boundary edges are not
//     flipped: boundary edge (a, b) of F becomes the triangle (a, b, point(F));
//   even steps (levels 1, 3, ...): every boundary edge (a, b) gets two
//     boundary points, near a and near b, and a triangle with a boundary
//     edge (a "boundary face") gets no face point: it becomes the triangle
//     (near a, near b, apex) and lends, to each of its two other edges, the
//     boundary point near that edge's end on the boundary in place of a face
//     point; those edges are flipped like any other. Where two boundary
//     faces meet at an edge this cuts off the corner between them.
// After an odd step every boundary face has one boundary edge and an interior
// apex (a face point), which the even step needs; an even step refuses a
// face with two or three boundary edges.
//
// Child vertices are numbered [face points, in face order of the faces that
// have one (SplitMap::point_faces; all faces on odd steps) | boundary points
// (even steps: two per edge of SplitMap::boundary_edges, the one near
// edge_vertices(e)[0] first) | vertex points]. Child faces: per edge in edge
// order, two for an interior edge (at the end its side runs from, then the
// other), one for a boundary edge. Every face keeps the parent's orientation.

#include <algorithm>
#include <atomic>

#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"
#include "split_detail.h"
#include "subdiv/core/error.h"

namespace subdiv {

bool sqrt3_step_trisects(int level) noexcept { return level % 2 == 1; }

}  // namespace subdiv

namespace subdiv::detail {

void sqrt3_keep_one_face_corners(const MeshTopology& parent, const SplitMap& map, Tags& child_tags) {
  if (parent.boundary_loops().empty()) return;
  for (Index v = 0; v < parent.vertex_count(); ++v) {
    if (parent.vertex_kind(v) != VertexKind::boundary || parent.vertex_face_count(v) != 1) continue;
    const Index child = map.vertex_point(v);
    const bool tagged = std::any_of(child_tags.corners.begin(), child_tags.corners.end(), [&](const CornerTag& c) {
      return c.vertex == child && c.sharpness >= kInfiniteSharpness;
    });
    if (!tagged) child_tags.corners.push_back({child, kInfiniteSharpness, CornerType::unspecified, std::nullopt});
  }
}

namespace {

// Whether topo has a boundary edge, checking (in parallel) that it is a
// manifold triangle mesh; the error names the first face or edge that is not.
bool checked_has_boundary(const MeshTopology& topo) {
  const Index nf = topo.face_count(), ne = topo.edge_count();
  std::atomic<bool> all_triangles = true, manifold = true, boundary = false;
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 16384), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f)
      if (topo.face_size(f) != 3) all_triangles = false;
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 16384), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto n = topo.edge_corners(e).size();
      if (n > 2) manifold = false;
      if (n == 1) boundary = true;
    }
  });
  if (!all_triangles)
    for (Index f = 0; f < nf; ++f)
      if (topo.face_size(f) != 3)
        throw TopologyError("the sqrt3 split needs a triangle mesh, but face " + std::to_string(f) + " has " +
                            std::to_string(topo.face_size(f)) + " vertices (triangulate it first)");
  if (!manifold)
    for (Index e = 0; e < ne; ++e)
      if (topo.edge_corners(e).size() > 2)
        throw TopologyError("the sqrt3 split needs a manifold mesh, but edge " + std::to_string(e) + " has " +
                            std::to_string(topo.edge_corners(e).size()) + " faces");
  return boundary;
}

}  // namespace

SplitMap sqrt3_split(const MeshTopology& topo, PolygonMesh& child, int level) {
  const Index nf = topo.face_count(), ne = topo.edge_count(), nv = topo.vertex_count();
  const bool open = checked_has_boundary(topo);
  const bool trisect = sqrt3_step_trisects(level);
  SplitMap map;
  map.rule = SplitRule::sqrt3;

  // Boundary faces (even steps) have no face point; the others are numbered.
  // Without a boundary every face has one, numbered as the faces.
  std::vector<Index> point_of, boundary_edge_of;
  if (open) {
    point_of.assign(static_cast<std::size_t>(nf), kInvalidIndex);
    boundary_edge_of.assign(static_cast<std::size_t>(nf), kInvalidIndex);
  }
  if (trisect && open) {
    for (Index e = 0; e < ne; ++e) {
      if (!topo.is_boundary_edge(e)) continue;
      const Index f = topo.corner_face(topo.edge_corners(e)[0]);
      if (boundary_edge_of[static_cast<std::size_t>(f)] != kInvalidIndex)
        throw TopologyError("the sqrt3 split's trisecting step needs one boundary edge per triangle, but face " +
                            std::to_string(f) + " has more (refine from an odd step)");
      boundary_edge_of[static_cast<std::size_t>(f)] = e;
    }
  }
  Index face_points = nf;
  if (open) {
    for (Index f = 0; f < nf; ++f)
      if (boundary_edge_of[static_cast<std::size_t>(f)] == kInvalidIndex) {
        point_of[static_cast<std::size_t>(f)] = static_cast<Index>(map.point_faces.size());
        map.point_faces.push_back(f);
      }
    face_points = static_cast<Index>(map.point_faces.size());
    if (face_points == nf) map.point_faces.clear();  // all of them
  }
  std::vector<Index> boundary_rank;
  if (trisect && open) {
    boundary_rank.assign(static_cast<std::size_t>(ne), kInvalidIndex);
    for (Index e = 0; e < ne; ++e)
      if (topo.is_boundary_edge(e)) {
        boundary_rank[static_cast<std::size_t>(e)] = static_cast<Index>(map.boundary_edges.size());
        map.boundary_edges.push_back(e);
      }
  }
  map.face_points = 0;
  map.edge_points = face_points;  // the boundary points
  map.vertex_points = face_points + 2 * static_cast<Index>(map.boundary_edges.size());
  map.child_vertex_count = map.vertex_points + nv;
  auto boundary_point = [&](Index e, Index v) {
    return map.edge_points + 2 * boundary_rank[static_cast<std::size_t>(e)] + (topo.edge_vertices(e)[0] == v ? 0 : 1);
  };
  auto point_of_face = [&](Index f) { return open ? point_of[static_cast<std::size_t>(f)] : f; };
  // What face f contributes to its interior edge e in place of the edge:
  // its face point, or (a boundary face) the boundary point near e's end on
  // its boundary edge.
  auto point_for = [&](Index f, Index e) {
    const Index p = point_of_face(f);
    if (p != kInvalidIndex) return map.face_points + p;
    const Index b = boundary_edge_of[static_cast<std::size_t>(f)];
    const auto [b0, b1] = topo.edge_vertices(b);
    const auto [e0, e1] = topo.edge_vertices(e);
    return boundary_point(b, e0 == b0 || e0 == b1 ? e0 : e1);
  };

  // Child faces per edge, two per interior edge: offsets first (open meshes),
  // so that edges fill in parallel.
  std::vector<Index> first_face;
  if (open) {
    first_face.assign(static_cast<std::size_t>(ne) + 1, 0);
    for (Index e = 0; e < ne; ++e)
      first_face[static_cast<std::size_t>(e) + 1] = first_face[static_cast<std::size_t>(e)] + (topo.is_boundary_edge(e) ? 1 : 2);
  }
  auto first_face_of = [&](Index e) { return open ? first_face[static_cast<std::size_t>(e)] : 2 * e; };
  const auto child_faces = static_cast<std::size_t>(first_face_of(ne));
  detail::assign_large(child.positions, static_cast<std::size_t>(map.child_vertex_count), Vec3{});
  detail::assign_large(child.face_offsets, child_faces + 1);
  detail::assign_large(child.face_indices, 3 * child_faces);
  tbb::parallel_for(tbb::blocked_range<Index>(0, ne, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = topo.edge_corners(e);
      const Index cf = sides[0], f = topo.corner_face(cf);
      // Side cf runs a -> b in face f.
      const Index a = topo.corner_vertex(cf), b = topo.corner_vertex(topo.corner_next(cf));
      const auto out = static_cast<std::size_t>(first_face_of(e));
      Index* t = child.face_indices.data() + 3 * out;
      if (sides.size() == 1) {
        if (trisect) {
          const Index apex = topo.corner_vertex(topo.corner_prev(cf));
          t[0] = boundary_point(e, a), t[1] = boundary_point(e, b), t[2] = map.vertex_point(apex);
        } else {
          t[0] = map.vertex_point(a), t[1] = map.vertex_point(b), t[2] = map.face_points + point_of_face(f);
        }
      } else {
        const Index g = topo.corner_face(sides[1]);
        const Index pf = point_for(f, e), pg = point_for(g, e);
        t[0] = map.vertex_point(a), t[1] = pg, t[2] = pf;
        t[3] = map.vertex_point(b), t[4] = pf, t[5] = pg;
      }
      for (std::size_t i = 0; i < sides.size(); ++i)
        child.face_offsets[out + i] = static_cast<Index>(3 * (out + i));
    }
  });
  child.face_offsets[child_faces] = static_cast<Index>(3 * child_faces);
  return map;
}

// One value per child vertex, seams not kept (child faces straddle the
// parent's edges): a face point's is its face's centroid value, a boundary
// point's 2/3 and 1/3 of its edge's end values, a vertex point's its
// vertex's value in the first face around it. The sqrt2 split's levels have
// no boundary points and use it too.
void point_split_face_varying(const MeshTopology& topo, const SplitMap& map, const PolygonMesh& child,
                              const FaceVaryingChannel& in, FaceVaryingChannel& out) {
  const auto k = static_cast<std::size_t>(in.components);
  out.name = in.name;
  out.components = in.components;
  out.values.assign(static_cast<std::size_t>(map.child_vertex_count) * k, 0.0);
  auto value = [&](Index corner) {
    return in.values.data() + static_cast<std::size_t>(in.indices[static_cast<std::size_t>(corner)]) * k;
  };
  auto at = [&](Index child_vertex) { return out.values.data() + static_cast<std::size_t>(child_vertex) * k; };
  for (Index i = 0; i < map.edge_points; ++i) {
    const Index f = map.point_face(i);
    for (Index c = topo.face_first_corner(f); c < topo.face_first_corner(f) + topo.face_size(f); ++c)
      for (std::size_t j = 0; j < k; ++j) at(map.face_points + i)[j] += value(c)[j] / topo.face_size(f);
  }
  for (std::size_t r = 0; r < map.boundary_edges.size(); ++r) {
    const Index side = topo.edge_corners(map.boundary_edges[r])[0];
    const bool forward = topo.corner_vertex(side) == topo.edge_vertices(map.boundary_edges[r])[0];
    const double* v0 = value(forward ? side : topo.corner_next(side));
    const double* v1 = value(forward ? topo.corner_next(side) : side);
    for (std::size_t j = 0; j < k; ++j) {
      at(map.edge_points + 2 * static_cast<Index>(r))[j] = (2.0 * v0[j] + v1[j]) / 3.0;
      at(map.edge_points + 2 * static_cast<Index>(r) + 1)[j] = (v0[j] + 2.0 * v1[j]) / 3.0;
    }
  }
  for (Index v = 0; v < topo.vertex_count(); ++v) {
    const auto corners = topo.vertex_corners(v);
    if (corners.empty()) continue;
    for (std::size_t j = 0; j < k; ++j) at(map.vertex_point(v))[j] = value(corners[0])[j];
  }
  out.indices = child.face_indices;
}

}  // namespace subdiv::detail
