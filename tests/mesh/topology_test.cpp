#include "subdiv/mesh/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <ranges>
#include <set>

#include <tbb/task_arena.h>

#include "subdiv/core/error.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// The defining property of an ordered ring: face j lies between edges j and
// j+1, leaving v along e_j and entering it along e_{j+1}.
void expect_ring_invariants(const MeshTopology& t, Index v) {
  const auto corners = t.vertex_corners(v);
  const auto edges = t.vertex_edges(v);
  const std::size_t k = corners.size();
  const bool boundary = t.vertex_kind(v) == VertexKind::boundary;
  ASSERT_EQ(edges.size(), boundary ? k + 1 : k) << "vertex " << v;
  for (std::size_t j = 0; j < k; ++j) {
    EXPECT_EQ(t.corner_vertex(corners[j]), v);
    EXPECT_EQ(t.corner_edge(corners[j]), edges[j]) << "vertex " << v << " face " << j;
    EXPECT_EQ(t.corner_edge(t.corner_prev(corners[j])), edges[(j + 1) % edges.size()]) << "vertex " << v;
  }
  if (boundary) {
    EXPECT_TRUE(t.is_boundary_edge(edges.front()));
    EXPECT_TRUE(t.is_boundary_edge(edges.back()));
  }
}

TEST(MeshTopology, CubeHasTwelveEdgesAndOrderedValenceThreeRings) {
  const PolygonMesh mesh = test::cube();
  const MeshTopology t(mesh);
  EXPECT_EQ(t.vertex_count(), 8);
  EXPECT_EQ(t.face_count(), 6);
  EXPECT_EQ(t.edge_count(), 12);
  EXPECT_TRUE(t.boundary_loops().empty());
  for (Index e = 0; e < t.edge_count(); ++e) {
    EXPECT_EQ(t.edge_face_count(e), 2);
    EXPECT_FALSE(t.is_flipped_edge(e));
    const auto [a, b] = t.edge_vertices(e);
    EXPECT_LT(a, b);
    EXPECT_EQ(t.find_edge(a, b), e);
    EXPECT_EQ(t.find_edge(b, a), e);
  }
  for (Index v = 0; v < 8; ++v) {
    EXPECT_EQ(t.vertex_kind(v), VertexKind::interior);
    EXPECT_EQ(t.valence(v), 3);
    EXPECT_TRUE(t.ring_ordered(v));
    expect_ring_invariants(t, v);
  }
  EXPECT_EQ(t.find_edge(0, 6), kInvalidIndex);  // a diagonal
  EXPECT_EQ(t.find_edge(0, 0), kInvalidIndex);
  EXPECT_EQ(t.find_edge(0, 99), kInvalidIndex);
}

TEST(MeshTopology, RingsRunCounterClockwiseSeenFromOutside) {
  // Interior vertex of a planar grid facing +z: the angles of the ring
  // neighbours must increase.
  const PolygonMesh mesh = test::quad_grid(4, 4);
  const MeshTopology t(mesh);
  const Index centre = 2 * 5 + 2;
  ASSERT_EQ(t.vertex_kind(centre), VertexKind::interior);
  const auto edges = t.vertex_edges(centre);
  ASSERT_EQ(edges.size(), 4u);
  const Vec3 c = mesh.positions[centre];
  auto angle_of = [&](std::size_t j) {
    const Vec3 p = mesh.positions[t.other_vertex(edges[j % edges.size()], centre)];
    return std::atan2(p.y - c.y, p.x - c.x);
  };
  double turned = 0.0;
  for (std::size_t j = 0; j < edges.size(); ++j) {
    double step = angle_of(j + 1) - angle_of(j);
    if (step <= -M_PI) step += 2 * M_PI;
    if (step > M_PI) step -= 2 * M_PI;
    EXPECT_GT(step, 0.0) << "ring step " << j << " turns clockwise";
    turned += step;
  }
  EXPECT_NEAR(turned, 2 * M_PI, 1e-12);
}

TEST(MeshTopology, GridBoundaryVerticesAndLoop) {
  const PolygonMesh mesh = test::quad_grid(3, 2);
  const MeshTopology t(mesh);
  EXPECT_EQ(t.edge_count(), 3 * 3 + 4 * 2);
  Index boundary = 0, interior = 0;
  for (Index v = 0; v < t.vertex_count(); ++v) {
    ASSERT_TRUE(t.ring_ordered(v)) << v;
    expect_ring_invariants(t, v);
    (t.vertex_kind(v) == VertexKind::boundary ? boundary : interior)++;
  }
  EXPECT_EQ(boundary, 10);
  EXPECT_EQ(interior, 2);
  EXPECT_EQ(t.valence(0), 2);     // grid corner: 1 face, 2 edges
  EXPECT_EQ(t.vertex_face_count(0), 1);
  EXPECT_EQ(t.valence(1), 3);     // boundary edge midpoint: 2 faces
  ASSERT_EQ(t.boundary_loops().size(), 1u);
  const BoundaryLoop& loop = t.boundary_loops()[0];
  EXPECT_TRUE(loop.ordered);
  ASSERT_EQ(loop.vertices.size(), 10u);
  // Consecutive loop vertices are joined by boundary edges, in face order.
  for (std::size_t i = 0; i < loop.vertices.size(); ++i) {
    const Index a = loop.vertices[i], b = loop.vertices[(i + 1) % loop.vertices.size()];
    const Index e = t.find_edge(a, b);
    ASSERT_NE(e, kInvalidIndex);
    ASSERT_TRUE(t.is_boundary_edge(e));
    EXPECT_EQ(t.corner_vertex(t.edge_corners(e)[0]), a);
  }
}

TEST(MeshTopology, TwoBoundaryLoopsOfAnAnnulus) {
  // 3x3 grid with the middle face removed.
  PolygonMesh grid = test::quad_grid(3, 3);
  PolygonMesh mesh;
  mesh.positions = grid.positions;
  for (Index f = 0; f < grid.face_count(); ++f)
    if (f != 4) mesh.add_face(grid.face(f));
  const MeshTopology t(mesh);
  ASSERT_EQ(t.boundary_loops().size(), 2u);
  EXPECT_EQ(t.boundary_loops()[0].vertices.size() + t.boundary_loops()[1].vertices.size(), 12u + 4u);
  for (Index v = 0; v < t.vertex_count(); ++v) expect_ring_invariants(t, v);
}

TEST(MeshTopology, NonManifoldElementsAreRepresented) {
  // Three triangles on one edge.
  const PolygonMesh book = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                                     {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  const MeshTopology t(book);
  const Index e = t.find_edge(0, 1);
  ASSERT_NE(e, kInvalidIndex);
  EXPECT_TRUE(t.is_non_manifold_edge(e));
  EXPECT_EQ(t.vertex_kind(0), VertexKind::non_manifold);
  EXPECT_FALSE(t.ring_ordered(0));
  EXPECT_EQ(t.vertex_kind(2), VertexKind::boundary);

  // Bowtie: two fans at vertex 0.
  const PolygonMesh bowtie = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
  const MeshTopology b(bowtie);
  EXPECT_EQ(b.fan_count(0), 2);
  EXPECT_EQ(b.vertex_kind(0), VertexKind::non_manifold);
  EXPECT_EQ(b.fan_count(1), 1);
}

TEST(MeshTopology, FlippedFaceLeavesRingUnorderedAndEdgeFlagged) {
  const PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}},
                                     {{0, 1, 4, 3}, {1, 4, 5, 2}});
  const MeshTopology t(mesh);
  EXPECT_TRUE(t.is_flipped_edge(t.find_edge(1, 4)));
  EXPECT_FALSE(t.ring_ordered(1));
  EXPECT_FALSE(t.ring_ordered(4));
  EXPECT_TRUE(t.ring_ordered(0));
}

TEST(MeshTopology, DegenerateFacesDoNotBreakIt) {
  PolygonMesh mesh;
  mesh.positions.resize(4);
  mesh.add_face({0, 1, 1, 2});  // consecutive repeat: a zero-length edge
  mesh.add_face({2, 3});        // a two-gon
  mesh.add_face({3});
  mesh.add_face(std::vector<Index>{});
  const MeshTopology t(mesh);
  EXPECT_TRUE(t.has_coincident_edges());
  EXPECT_FALSE(t.edges_keyed());
  // The zero-length side is an edge of its own, listed twice at its vertex.
  const Index self = t.corner_edge(1);
  EXPECT_EQ(t.edge_vertices(self), (std::array<Index, 2>{1, 1}));
  EXPECT_EQ(t.edge_face_count(self), 1);
  EXPECT_EQ(std::ranges::count(t.vertex_edges(1), self), 2);
  EXPECT_EQ(t.find_edge(1, 1), kInvalidIndex);
  // The two-gon runs (2, 3) twice: its second side is a second edge.
  EXPECT_NE(t.corner_edge(4), t.corner_edge(5));
  EXPECT_EQ(t.edge_vertices(t.corner_edge(4)), t.edge_vertices(t.corner_edge(5)));
  EXPECT_EQ(t.find_edge(2, 3), t.corner_edge(4));  // the first of them
  EXPECT_EQ(t.edge_vertices(t.corner_edge(6)), (std::array<Index, 2>{3, 3}));  // the one-gon's self edge
  EXPECT_EQ(t.vertex_kind(1), VertexKind::non_manifold);
  EXPECT_TRUE(t.on_coincident_edge(1));
  EXPECT_TRUE(t.on_coincident_edge(2));
  EXPECT_FALSE(t.on_coincident_edge(0));
}

// OpenSubdiv's Vtr::Level::completeTopologyFromFaceVertices, restated: faces
// in order, each side joining the first edge between its two vertices
// unless that edge's last side is in the same face, or the side joins a
// vertex to itself; then it starts an edge. Returns each edge's corners.
std::set<std::vector<Index>> edges_as_opensubdiv_makes_them(const PolygonMesh& mesh) {
  std::vector<std::pair<std::array<Index, 2>, std::vector<Index>>> edges;  // (ends, corners) in creation order
  Index c = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 0; i < face.size(); ++i, ++c) {
      const Index a = face[i], b = face[(i + 1) % face.size()];
      const std::array<Index, 2> ends{std::min(a, b), std::max(a, b)};
      auto it = std::find_if(edges.begin(), edges.end(), [&](const auto& e) { return e.first == ends; });
      const bool own = a == b || (it != edges.end() && mesh.face_offsets[static_cast<std::size_t>(f)] <= it->second.back());
      if (it == edges.end() || own) edges.push_back({ends, {c}});
      else it->second.push_back(c);
    }
  }
  std::set<std::vector<Index>> out;
  for (const auto& e : edges) out.insert(e.second);
  return out;
}

TEST(MeshTopology, RepeatedVerticesMakeEdgesAsOpenSubdivDoes) {
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 300; ++trial) {
    const int nv = 2 + static_cast<int>(rng() % 6);
    PolygonMesh mesh;
    mesh.positions.resize(static_cast<std::size_t>(nv));
    const int nf = 1 + static_cast<int>(rng() % 8);
    for (int f = 0; f < nf; ++f) {
      std::vector<Index> face(3 + rng() % 3);
      for (Index& v : face) v = static_cast<Index>(rng() % static_cast<unsigned>(nv));
      mesh.add_face(face);
    }
    const MeshTopology t(mesh);
    std::set<std::vector<Index>> ours;
    for (Index e = 0; e < t.edge_count(); ++e) {
      const auto corners = t.edge_corners(e);
      ours.insert(std::vector<Index>(corners.begin(), corners.end()));
      for (const Index c : corners) {
        EXPECT_EQ(t.corner_edge(c), e);
        const Index a = t.corner_vertex(c), b = t.corner_vertex(t.corner_next(c));
        EXPECT_EQ(t.edge_vertices(e), (std::array<Index, 2>{std::min(a, b), std::max(a, b)}));
      }
      if (e > 0) {
        EXPECT_LE(t.edge_vertices(e - 1), t.edge_vertices(e));  // numbered in (min, max) order
      }
    }
    EXPECT_EQ(ours, edges_as_opensubdiv_makes_them(mesh)) << "trial " << trial;
  }
}

TEST(MeshTopology, KeysKeepEdgesBetweenTheSameVerticesApart) {
  // A strip of two quads sharing edge (1, 4), then the same faces with keys
  // that make the shared side two edges (a slit).
  PolygonMesh mesh;
  mesh.positions.resize(6);
  mesh.add_face({0, 1, 4, 3});
  mesh.add_face({1, 2, 5, 4});
  const MeshTopology joined(mesh);
  EXPECT_FALSE(joined.has_coincident_edges());
  EXPECT_EQ(joined.edge_count(), 7);
  // Sides: face 0: 0-1, 1-4, 4-3, 3-0; face 1: 1-2, 2-5, 5-4, 4-1.
  const std::vector<Index> same = {10, 11, 12, 13, 14, 15, 16, 11};
  const MeshTopology keyed(mesh, same);
  EXPECT_FALSE(keyed.has_coincident_edges());
  ASSERT_EQ(keyed.edge_count(), joined.edge_count());
  for (Index c = 0; c < mesh.corner_count(); ++c) EXPECT_EQ(keyed.corner_edge(c), joined.corner_edge(c));
  for (Index v = 0; v < 6; ++v) EXPECT_EQ(keyed.vertex_kind(v), joined.vertex_kind(v));
  const std::vector<Index> apart = {10, 11, 12, 13, 14, 15, 16, 17};
  const MeshTopology slit(mesh, apart);
  EXPECT_TRUE(slit.edges_keyed());
  EXPECT_TRUE(slit.has_coincident_edges());
  EXPECT_EQ(slit.edge_count(), 8);
  EXPECT_NE(slit.corner_edge(1), slit.corner_edge(7));
  EXPECT_TRUE(slit.is_boundary_edge(slit.corner_edge(1)));
  EXPECT_TRUE(slit.is_boundary_edge(slit.corner_edge(7)));
  EXPECT_TRUE(slit.on_coincident_edge(1));
  EXPECT_FALSE(slit.on_coincident_edge(0));
  EXPECT_THROW(MeshTopology(mesh, std::vector<Index>(3, 0)), InvalidInputError);
}

TEST(MeshTopology, IsolatedVertices) {
  PolygonMesh mesh = test::cube();
  mesh.positions.push_back({5, 5, 5});
  const MeshTopology t(mesh);
  EXPECT_EQ(t.vertex_kind(8), VertexKind::isolated);
  EXPECT_EQ(t.valence(8), 0);
  EXPECT_EQ(t.fan_count(8), 0);
}

TEST(MeshTopology, RejectsOutOfRangeIndices) {
  PolygonMesh mesh = test::cube();
  mesh.face_indices[0] = 42;
  EXPECT_THROW(MeshTopology{mesh}, InvalidInputError);
}

// Independent route: edges, incidence and fans computed by brute force with
// std::map / BFS on random (often non-manifold) meshes must agree.
// Its counting sorts split the vertices among the threads: every relation
// must come out the same with one thread, two, or more parts than cores.
TEST(MeshTopology, SameForAnyThreadCount) {
  std::mt19937 rng(7);
  PolygonMesh mesh = test::jittered(test::triangle_grid(40, 30), 3);
  std::vector<std::vector<Index>> faces;  // in a shuffled order
  for (Index f = 0; f < mesh.face_count(); ++f) faces.emplace_back(mesh.face(f).begin(), mesh.face(f).end());
  std::shuffle(faces.begin(), faces.end(), rng);
  mesh.face_offsets = {0};
  mesh.face_indices.clear();
  for (const auto& face : faces) mesh.add_face(face);
  auto build = [&](int threads) {
    std::optional<MeshTopology> t;
    tbb::task_arena(threads).execute([&] { t.emplace(mesh); });
    return std::move(*t);
  };
  const MeshTopology one = build(1);
  for (const int threads : {2, 8}) {
    const MeshTopology other = build(threads);
    ASSERT_EQ(other.edge_count(), one.edge_count());
    for (Index c = 0; c < one.corner_count(); ++c) ASSERT_EQ(other.corner_edge(c), one.corner_edge(c)) << threads;
    for (Index e = 0; e < one.edge_count(); ++e) {
      ASSERT_EQ(other.edge_vertices(e), one.edge_vertices(e)) << threads;
      ASSERT_TRUE(std::ranges::equal(other.edge_corners(e), one.edge_corners(e))) << threads << " threads, edge " << e;
    }
    for (Index v = 0; v < one.vertex_count(); ++v) {
      ASSERT_TRUE(std::ranges::equal(other.vertex_corners(v), one.vertex_corners(v))) << threads << ", vertex " << v;
      ASSERT_TRUE(std::ranges::equal(other.vertex_edges(v), one.vertex_edges(v))) << threads << ", vertex " << v;
      ASSERT_EQ(other.vertex_kind(v), one.vertex_kind(v));
    }
  }
}

TEST(MeshTopology, AgreesWithBruteForceOnRandomMeshes) {
  std::mt19937 rng(12345);
  for (int trial = 0; trial < 200; ++trial) {
    const int nv = 3 + static_cast<int>(rng() % 12);
    PolygonMesh mesh;
    mesh.positions.resize(static_cast<std::size_t>(nv));
    const int nf = 1 + static_cast<int>(rng() % 20);
    for (int f = 0; f < nf; ++f) {
      std::vector<Index> face;
      const int size = std::min(nv, 3 + static_cast<int>(rng() % 3));
      std::set<Index> used;
      while (static_cast<int>(face.size()) < size) {
        const Index v = static_cast<Index>(rng() % static_cast<unsigned>(nv));
        if (used.insert(v).second) face.push_back(v);
      }
      mesh.add_face(face);
    }
    const MeshTopology t(mesh);

    std::map<std::pair<Index, Index>, std::vector<Index>> edges;  // -> corners
    for (Index c = 0; c < mesh.corner_count(); ++c) {
      const Index a = t.corner_vertex(c), b = t.corner_vertex(t.corner_next(c));
      edges[{std::min(a, b), std::max(a, b)}].push_back(c);
    }
    ASSERT_EQ(t.edge_count(), static_cast<Index>(edges.size()));
    Index e = 0;
    for (const auto& [key, corners] : edges) {
      EXPECT_EQ(t.edge_vertices(e)[0], key.first);
      EXPECT_EQ(t.edge_vertices(e)[1], key.second);
      const auto got = t.edge_corners(e);
      EXPECT_EQ(std::vector<Index>(got.begin(), got.end()), corners);
      ++e;
    }
    for (Index v = 0; v < nv; ++v) {
      // Brute-force fans: BFS over the faces at v, linked by shared edges at v.
      std::vector<Index> faces;
      for (Index f = 0; f < mesh.face_count(); ++f)
        for (const Index x : mesh.face(f))
          if (x == v) faces.push_back(f);
      auto edges_at_v = [&](Index f) {
        std::set<Index> out;
        const auto face = mesh.face(f);
        for (std::size_t i = 0; i < face.size(); ++i)
          if (face[i] == v) {
            out.insert(face[(i + 1) % face.size()]);
            out.insert(face[(i + face.size() - 1) % face.size()]);
          }
        return out;
      };
      std::vector<int> seen(faces.size(), 0);
      int fans = 0;
      for (std::size_t s = 0; s < faces.size(); ++s) {
        if (seen[s]) continue;
        ++fans;
        std::vector<std::size_t> stack{s};
        seen[s] = 1;
        while (!stack.empty()) {
          const std::size_t i = stack.back();
          stack.pop_back();
          const auto mine = edges_at_v(faces[i]);
          for (std::size_t j = 0; j < faces.size(); ++j) {
            if (seen[j]) continue;
            const auto theirs = edges_at_v(faces[j]);
            for (const Index x : mine)
              if (theirs.count(x)) { seen[j] = 1; stack.push_back(j); break; }
          }
        }
      }
      EXPECT_EQ(t.fan_count(v), fans) << "trial " << trial << " vertex " << v;
      if (t.ring_ordered(v)) expect_ring_invariants(t, v);
    }
  }
}

}  // namespace
}  // namespace subdiv
