// The triangle split's numbering by levels (triangle_numbering.h): the
// same arithmetic as MeshTopology::from_triangle_split(), without vertex
// incidence.

#include "triangle_numbering.h"

#include <algorithm>
#include <atomic>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "../core/large_buffers.h"

namespace subdiv::detail {

namespace {

// first[]: per edge, 2 halves plus its partners, the other edges of its
// faces with a larger number; then the prefix sums.
void number_child_edges(TriangleLevel& level) {
  assign_large(level.first, static_cast<std::size_t>(level.edges) + 1, 0);
  tbb::parallel_for(tbb::blocked_range<Index>(0, level.edges, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      Index count = 2;
      for (const Index f : level.edge_faces[static_cast<std::size_t>(e)])
        if (f != kInvalidIndex)
          for (const Index other : level.face_edges[static_cast<std::size_t>(f)]) count += other > e;
      level.first[static_cast<std::size_t>(e) + 1] = count;
    }
  });
  std::partial_sum(level.first.begin(), level.first.end(), level.first.begin());
}

}  // namespace

void TriangleLevel::keep_counts_only() {
  face_vertices = {};
  face_edges = {};
  edge_faces = {};
}

std::optional<TriangleLevel> triangle_level(const MeshTopology& t) {
  TriangleLevel level;
  level.faces = t.face_count();
  level.edges = t.edge_count();
  level.vertices = t.vertex_count();
  assign_large(level.face_vertices, static_cast<std::size_t>(level.faces));
  assign_large(level.face_edges, static_cast<std::size_t>(level.faces));
  assign_large(level.edge_faces, static_cast<std::size_t>(level.edges));
  std::atomic<bool> simple = true;
  tbb::parallel_for(tbb::blocked_range<Index>(0, level.faces, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f) {
      if (t.face_size(f) != 3) simple = false;
      const Index first = t.face_first_corner(f);
      for (Index i = 0; i < 3 && simple; ++i) {
        level.face_vertices[static_cast<std::size_t>(f)][static_cast<std::size_t>(i)] = t.corner_vertex(first + i);
        level.face_edges[static_cast<std::size_t>(f)][static_cast<std::size_t>(i)] = t.corner_edge(first + i);
      }
    }
  });
  if (!simple) return std::nullopt;
  tbb::parallel_for(tbb::blocked_range<Index>(0, level.edges, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e) {
      const auto sides = t.edge_corners(e);
      std::array<Index, 2>& faces = level.edge_faces[static_cast<std::size_t>(e)];
      faces = {kInvalidIndex, kInvalidIndex};
      if (sides.empty() || sides.size() > 2) {
        simple = false;
        continue;
      }
      for (std::size_t s = 0; s < sides.size(); ++s) faces[s] = t.corner_face(sides[s]);
      if (sides.size() < 2) continue;
      // Two faces sharing a second edge would give a repeated partner.
      const auto& a = level.face_edges[static_cast<std::size_t>(faces[0])];
      const auto& b = level.face_edges[static_cast<std::size_t>(faces[1])];
      for (const Index x : a)
        if (x != e && std::find(b.begin(), b.end(), x) != b.end()) simple = false;
    }
  });
  if (!simple) return std::nullopt;
  number_child_edges(level);
  return level;
}

TriangleLevel child_level(const TriangleLevel& p) {
  TriangleLevel c;
  c.faces = 4 * p.faces;
  c.edges = p.child_edges();
  c.vertices = p.edges + p.vertices;
  assign_large(c.face_vertices, static_cast<std::size_t>(c.faces));
  assign_large(c.face_edges, static_cast<std::size_t>(c.faces));
  assign_large(c.edge_faces, static_cast<std::size_t>(c.edges));
  tbb::parallel_for(tbb::blocked_range<Index>(0, p.faces, 2048), [&](const tbb::blocked_range<Index>& range) {
    std::array<SubTriangle, 4> children;
    for (Index f = range.begin(); f != range.end(); ++f) {
      const auto& v = p.face_vertices[static_cast<std::size_t>(f)];
      const auto& e = p.face_edges[static_cast<std::size_t>(f)];
      split_with_edges(SubTriangle{f, v, e, {}}, p, children);
      for (const SubTriangle& child : children) {
        c.face_vertices[static_cast<std::size_t>(child.face)] = child.vertex;
        c.face_edges[static_cast<std::size_t>(child.face)] = child.edge;
      }
      // The sides of the child's edges: an interior edge's both lie in this
      // face (corner child i and the centre); a half's one, at this face's
      // side of the parent edge. Each is written once.
      for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t next = (i + 1) % 3;
        c.edge_faces[static_cast<std::size_t>(children[i].edge[1])] = {4 * f + static_cast<Index>(i), 4 * f + 3};
        const std::size_t side = p.edge_faces[static_cast<std::size_t>(e[i])][0] == f ? 0 : 1;
        c.edge_faces[static_cast<std::size_t>(children[i].edge[0])][side] = 4 * f + static_cast<Index>(i);
        c.edge_faces[static_cast<std::size_t>(children[next].edge[2])][side] = 4 * f + static_cast<Index>(next);
      }
    }
  });
  // A boundary half's missing side.
  tbb::parallel_for(tbb::blocked_range<Index>(0, p.edges, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index e = range.begin(); e != range.end(); ++e)
      if (p.edge_faces[static_cast<std::size_t>(e)][1] == kInvalidIndex)
        for (const Index h : {p.first[static_cast<std::size_t>(e) + 1] - 2, p.first[static_cast<std::size_t>(e) + 1] - 1})
          c.edge_faces[static_cast<std::size_t>(h)][1] = kInvalidIndex;
  });
  number_child_edges(c);
  return c;
}

TriangleNumbering::TriangleNumbering(TriangleLevel start, int levels) : levels_(levels) {
  faces_ = {start.faces};
  edges_ = {start.edges};
  vertices_ = {start.vertices};
  for (int l = 0; l < levels; ++l) {
    faces_.push_back(4 * faces_.back());
    vertices_.push_back(vertices_.back() + edges_.back());
    edges_.push_back(2 * edges_.back() + 3 * faces_[static_cast<std::size_t>(l)]);
  }
  derived_.push_back(std::move(start));
  for (int depth = 1; depth <= levels - 2; ++depth) {
    TriangleLevel next = child_level(derived_.back());
    derived_.back().keep_counts_only();
    derived_.push_back(std::move(next));
  }
}

}  // namespace subdiv::detail
