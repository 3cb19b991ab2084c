// How a level of adaptive refinement's hierarchy nests in the next
// (adaptive_nesting.h). The sqrt3 split's two steps are read off its
// numbering (src/topology/sqrt3_split.cpp): face points first, in face order
// of the faces that have one, then the boundary points of trisecting steps,
// two per boundary edge, then the vertex points; child faces per edge in
// edge order, two for an interior edge, one for a boundary edge.

#include "depth/adaptive_nesting.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "subdiv/core/error.h"

namespace subdiv::detail {

namespace {

// The rank of each parent face's face point, or kInvalidIndex where it has none.
std::vector<Index> face_point_ranks(const SplitMap& map, Index faces) {
  std::vector<Index> rank(static_cast<std::size_t>(faces), kInvalidIndex);
  const Index points = map.edge_points - map.face_points;
  for (Index i = 0; i < points; ++i) rank[static_cast<std::size_t>(map.point_face(i))] = i;
  return rank;
}

bool has_vertex(const MeshTopology& t, Index f, Index v) {
  const auto face = t.face_vertices(f);
  return std::find(face.begin(), face.end(), v) != face.end();
}

void fail(const std::string& what) { throw std::logic_error("two rotating steps: " + what); }

}  // namespace

Nesting one_step_nesting(const MeshTopology& parent, const SplitMap& map) {
  Nesting n;
  n.vertex_points = map.vertex_points;
  n.edge_points.resize(static_cast<std::size_t>(parent.edge_count()));
  for (Index e = 0; e < parent.edge_count(); ++e) n.edge_points[static_cast<std::size_t>(e)] = map.edge_point(e);
  if (map.rule == SplitRule::quad) {
    n.face_centres.resize(static_cast<std::size_t>(parent.face_count()));
    for (Index f = 0; f < parent.face_count(); ++f) n.face_centres[static_cast<std::size_t>(f)] = map.face_point(f);
  }
  for (Index f = 0; f < parent.face_count(); ++f) {
    const auto [first, last] = child_faces(parent, map.rule, f);
    for (Index child = first; child < last; ++child) n.children.push_back(child);
    n.child_offsets.push_back(static_cast<Index>(n.children.size()));
  }
  return n;
}

Nesting two_sqrt3_steps_nesting(const MeshTopology& level, const SplitMap& first, const MeshTopology& middle,
                                const SplitMap& second, const PolygonMesh& next) {
  if (!first.boundary_edges.empty())
    throw InvalidInputError("the sqrt3 split's levels nest over two steps on an open mesh only from an even level "
                            "(from an odd one its first step trisects the boundary)");
  const Index nf = level.face_count(), ne = level.edge_count();
  const std::vector<Index> first_rank = face_point_ranks(first, nf);
  const std::vector<Index> second_rank = face_point_ranks(second, middle.face_count());
  Nesting n;
  n.vertex_points = second.vertex_points + first.vertex_points;
  n.points_per_edge = 2;

  n.face_centres.resize(static_cast<std::size_t>(nf));
  for (Index f = 0; f < nf; ++f) {
    const Index rank = first_rank[static_cast<std::size_t>(f)];
    if (rank == kInvalidIndex) fail("face " + std::to_string(f) + " has no face point");
    n.face_centres[static_cast<std::size_t>(f)] = second.vertex_point(first.face_points + rank);
  }

  // Each edge's thirds, from edge_vertices(e)[0] on: an interior edge's are
  // the second face points of its two middle faces (each holds one end),
  // a boundary edge's the second step's boundary points.
  n.edge_points.resize(2 * static_cast<std::size_t>(ne));
  Index middle_face = 0;
  for (Index e = 0; e < ne; ++e) {
    const auto [a, b] = level.edge_vertices(e);
    Index near_a = kInvalidIndex, near_b = kInvalidIndex;
    if (level.is_boundary_edge(e)) {
      const Index kept = middle.find_edge(first.vertex_point(a), first.vertex_point(b));
      const auto it = std::lower_bound(second.boundary_edges.begin(), second.boundary_edges.end(), kept);
      if (kept == kInvalidIndex || it == second.boundary_edges.end() || *it != kept)
        fail("boundary edge " + std::to_string(e) + " is not trisected");
      const Index point = second.edge_points + 2 * static_cast<Index>(it - second.boundary_edges.begin());
      const bool forward = middle.edge_vertices(kept)[0] == first.vertex_point(a);
      near_a = forward ? point : point + 1;
      near_b = forward ? point + 1 : point;
      middle_face += 1;
    } else {
      for (const Index g : {middle_face, middle_face + 1}) {
        if (g >= middle.face_count() || second_rank[static_cast<std::size_t>(g)] == kInvalidIndex)
          fail("edge " + std::to_string(e) + "'s middle faces have no face points");
        const Index point = second.face_points + second_rank[static_cast<std::size_t>(g)];
        if (has_vertex(middle, g, first.vertex_point(a))) near_a = point;
        else if (has_vertex(middle, g, first.vertex_point(b))) near_b = point;
      }
      middle_face += 2;
    }
    if (near_a == kInvalidIndex || near_b == kInvalidIndex) fail("edge " + std::to_string(e) + " has no thirds");
    n.edge_points[2 * static_cast<std::size_t>(e)] = near_a;
    n.edge_points[2 * static_cast<std::size_t>(e) + 1] = near_b;
  }
  if (middle_face != middle.face_count()) fail("the middle faces do not follow the edges");

  // The face each next face lies in: the face whose centre it holds, or
  // (a corner triangle: an old vertex and two thirds) the face holding both
  // thirds' edges.
  std::vector<Index> third_edge(static_cast<std::size_t>(next.vertex_count()), kInvalidIndex);
  for (Index e = 0; e < ne; ++e)
    for (const Index p : n.points_on(e)) third_edge[static_cast<std::size_t>(p)] = e;
  const Index centres_begin = second.vertex_point(first.face_points);
  const Index centres_end = second.vertex_point(first.edge_points);
  std::vector<Index> parent(static_cast<std::size_t>(next.face_count()), kInvalidIndex);
  for (Index g = 0; g < next.face_count(); ++g) {
    Index edges[2] = {kInvalidIndex, kInvalidIndex};
    int thirds = 0;
    for (Index c = next.face_offsets[g]; c < next.face_offsets[g + 1]; ++c) {
      const Index v = next.face_indices[c];
      if (v >= centres_begin && v < centres_end) {
        parent[static_cast<std::size_t>(g)] = first.point_face(v - centres_begin);
        break;
      }
      if (third_edge[static_cast<std::size_t>(v)] != kInvalidIndex && thirds < 2)
        edges[thirds++] = third_edge[static_cast<std::size_t>(v)];
    }
    if (parent[static_cast<std::size_t>(g)] != kInvalidIndex) continue;
    if (thirds != 2) fail("face " + std::to_string(g) + " two steps down holds no centre and not two thirds");
    for (const Index c1 : level.edge_corners(edges[0]))
      for (const Index c2 : level.edge_corners(edges[1]))
        if (level.corner_face(c1) == level.corner_face(c2)) parent[static_cast<std::size_t>(g)] = level.corner_face(c1);
    if (parent[static_cast<std::size_t>(g)] == kInvalidIndex)
      fail("face " + std::to_string(g) + " two steps down lies in no face");
  }
  n.child_offsets.assign(static_cast<std::size_t>(nf) + 1, 0);
  for (const Index f : parent) ++n.child_offsets[static_cast<std::size_t>(f) + 1];
  for (Index f = 0; f < nf; ++f) {
    if (n.child_offsets[static_cast<std::size_t>(f) + 1] != 9)
      fail("face " + std::to_string(f) + " holds " + std::to_string(n.child_offsets[static_cast<std::size_t>(f) + 1]) +
           " faces two steps down, not 9");
    n.child_offsets[static_cast<std::size_t>(f) + 1] += n.child_offsets[static_cast<std::size_t>(f)];
  }
  n.children.resize(parent.size());
  std::vector<Index> fill(n.child_offsets.begin(), n.child_offsets.end() - 1);
  for (Index g = 0; g < next.face_count(); ++g)
    n.children[static_cast<std::size_t>(fill[static_cast<std::size_t>(parent[static_cast<std::size_t>(g)])]++)] = g;
  return n;
}

Nesting two_sqrt2_steps_nesting(const MeshTopology& level, const SplitMap& first, const SplitMap& second,
                                const PolygonMesh& next) {
  const Index nf = level.face_count(), ne = level.edge_count();
  Nesting n;
  n.vertex_points = second.vertex_points + first.vertex_points;
  n.face_centres.resize(static_cast<std::size_t>(nf));
  for (Index f = 0; f < nf; ++f) n.face_centres[static_cast<std::size_t>(f)] = second.vertex_point(first.face_point(f));
  // The first step makes one quad per edge, in edge order; the second step's
  // face point of that quad is the edge's midpoint.
  n.edge_points.resize(static_cast<std::size_t>(ne));
  for (Index e = 0; e < ne; ++e) n.edge_points[static_cast<std::size_t>(e)] = second.face_point(e);
  // Each face two steps down holds one centre: its face's.
  const Index centres_begin = second.vertex_point(first.face_point(0));
  std::vector<Index> parent(static_cast<std::size_t>(next.face_count()), kInvalidIndex);
  for (Index g = 0; g < next.face_count(); ++g)
    for (Index c = next.face_offsets[g]; c < next.face_offsets[g + 1]; ++c)
      if (const Index v = next.face_indices[c]; v >= centres_begin && v < centres_begin + nf) {
        if (parent[static_cast<std::size_t>(g)] != kInvalidIndex) fail("a face two steps down holds two centres");
        parent[static_cast<std::size_t>(g)] = v - centres_begin;
      }
  n.child_offsets.assign(static_cast<std::size_t>(nf) + 1, 0);
  for (const Index f : parent) {
    if (f == kInvalidIndex) fail("a face two steps down holds no centre");
    ++n.child_offsets[static_cast<std::size_t>(f) + 1];
  }
  for (Index f = 0; f < nf; ++f) {
    if (n.child_offsets[static_cast<std::size_t>(f) + 1] != level.face_size(f))
      fail("face " + std::to_string(f) + " holds " + std::to_string(n.child_offsets[static_cast<std::size_t>(f) + 1]) +
           " faces two steps down, not one per corner");
    n.child_offsets[static_cast<std::size_t>(f) + 1] += n.child_offsets[static_cast<std::size_t>(f)];
  }
  n.children.resize(parent.size());
  std::vector<Index> fill(n.child_offsets.begin(), n.child_offsets.end() - 1);
  for (Index g = 0; g < next.face_count(); ++g)
    n.children[static_cast<std::size_t>(fill[static_cast<std::size_t>(parent[static_cast<std::size_t>(g)])]++)] = g;
  return n;
}

}  // namespace subdiv::detail
