#include "subdiv/topology/split.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/mesh_stats.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

struct Split {
  PolygonMesh child;
  SplitMap map;
};

Split split(const PolygonMesh& mesh, SplitRule rule) {
  Split s;
  s.map = split_topology(mesh, MeshTopology(mesh), rule, s.child);
  return s;
}

TEST(QuadSplit, CountsNumberingAndValidity) {
  const PolygonMesh mesh = test::cube();
  const Split s = split(mesh, SplitRule::quad);
  EXPECT_EQ(s.map.face_points, 0);
  EXPECT_EQ(s.map.edge_points, 6);
  EXPECT_EQ(s.map.vertex_points, 6 + 12);
  EXPECT_EQ(s.map.child_vertex_count, 26);
  EXPECT_EQ(s.child.vertex_count(), 26);
  EXPECT_EQ(s.child.face_count(), 24);
  EXPECT_TRUE(validate(s.child).ok());
  const MeshStats st = compute_stats(s.child, MeshTopology(s.child));
  EXPECT_EQ(st.euler_characteristic, 2);
  EXPECT_EQ(st.quads, 24);
  // Child face of corner 0 of face 0 (vertices 0 3 2 1): [V(0), E(0-3), F(0), E(1-0)].
  const MeshTopology t(mesh);
  const auto q = s.child.face(0);
  EXPECT_EQ(q[0], s.map.vertex_point(0));
  EXPECT_EQ(q[1], s.map.edge_point(t.find_edge(0, 3)));
  EXPECT_EQ(q[2], s.map.face_point(0));
  EXPECT_EQ(q[3], s.map.edge_point(t.find_edge(1, 0)));
  EXPECT_EQ(child_faces(t, SplitRule::quad, 1), std::make_pair(Index{4}, Index{8}));  // face 1 is corners 4-7
}

TEST(QuadSplit, PolygonsBecomeQuadsAndBoundariesStay) {
  PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {2, 0.5, 0}, {1, 1, 0}, {0, 1, 0}, {3, 0, 0}},
                               {{0, 1, 2, 3, 4}, {1, 5, 2}});
  const Split s = split(mesh, SplitRule::quad);
  EXPECT_EQ(s.child.face_count(), 8);
  const MeshTopology ct(s.child);
  EXPECT_EQ(ct.boundary_loops().size(), 1u);
  EXPECT_TRUE(validate(s.child, ct).ok());
  for (Index f = 0; f < s.child.face_count(); ++f) EXPECT_EQ(s.child.face_size(f), 4);
}

TEST(TriangleSplit, CountsOrientationAndCentre) {
  const PolygonMesh mesh = test::tetrahedron();
  const Split s = split(mesh, SplitRule::triangle);
  EXPECT_EQ(s.map.edge_points, 0);
  EXPECT_EQ(s.map.vertex_points, 6);
  EXPECT_EQ(s.child.vertex_count(), 10);
  EXPECT_EQ(s.child.face_count(), 16);
  EXPECT_TRUE(validate(s.child).ok());
  const MeshTopology t(mesh);
  // Child 3 of face 0 (vertices 0 1 2) is the centre triangle of its edge points.
  const auto centre = s.child.face(3);
  EXPECT_EQ(centre[0], s.map.edge_point(t.find_edge(0, 1)));
  EXPECT_EQ(centre[1], s.map.edge_point(t.find_edge(1, 2)));
  EXPECT_EQ(centre[2], s.map.edge_point(t.find_edge(2, 0)));
}

TEST(TriangleSplit, RejectsNonTriangles) {
  PolygonMesh child;
  const PolygonMesh cube = test::cube();
  EXPECT_THROW(split_topology(cube, MeshTopology(cube), SplitRule::triangle, child), TopologyError);
}

TEST(Split, DegenerateFacesAreRejected) {
  PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1, 1, 2}});
  PolygonMesh child;
  EXPECT_THROW(split_topology(mesh, MeshTopology(mesh), SplitRule::quad, child), TopologyError);
}

TEST(Split, TagsPropagateWithSharpnessDecrement) {
  PolygonMesh mesh = test::cube();
  mesh.tags.creases = {{0, 1, 10.0}, {1, 2, 2.5}, {2, 3, 0.5}};
  mesh.tags.corners = {{4, 3.0, CornerType::convex, 1.0}, {5, 1.0, CornerType::unspecified, std::nullopt}};
  mesh.tags.holes = {2};
  mesh.tags.boundary_interpolation = BoundaryInterpolation::edge_only;
  const Split s = split(mesh, SplitRule::quad);
  const Tags& t = s.child.tags;
  ASSERT_EQ(t.creases.size(), 4u);  // the 0.5 crease is gone one level down
  const MeshTopology topo(mesh);
  EXPECT_EQ(t.creases[0], (CreaseTag{s.map.vertex_point(0), s.map.edge_point(topo.find_edge(0, 1)), 10.0}));
  EXPECT_EQ(t.creases[1], (CreaseTag{s.map.edge_point(topo.find_edge(0, 1)), s.map.vertex_point(1), 10.0}));
  EXPECT_EQ(t.creases[2].sharpness, 1.5);
  ASSERT_EQ(t.corners.size(), 1u);
  EXPECT_EQ(t.corners[0].vertex, s.map.vertex_point(4));
  EXPECT_EQ(t.corners[0].sharpness, 2.0);
  EXPECT_EQ(t.corners[0].type, CornerType::convex);
  EXPECT_EQ(t.holes, (std::vector<Index>{8, 9, 10, 11}));  // the four quads of face 2
  EXPECT_EQ(t.boundary_interpolation, BoundaryInterpolation::edge_only);
  EXPECT_TRUE(validate(s.child).ok());
}

TEST(Split, FaceVaryingDataIsLinearWithinFaces) {
  PolygonMesh mesh = test::quad_grid(2, 1);
  // Two UV islands: the shared edge has different UVs on each side (a seam).
  mesh.face_varying_channels.push_back(
      {"uv", 2, {0, 0, 1, 0, 1, 1, 0, 1, 5, 0, 6, 0, 6, 1, 5, 1}, {0, 1, 2, 3, 4, 5, 6, 7}});
  const Split s = split(mesh, SplitRule::quad);
  const FaceVaryingChannel& uv = s.child.face_varying_channels.at(0);
  ASSERT_EQ(uv.indices.size(), s.child.face_indices.size());
  EXPECT_NO_THROW(check_indices(s.child));
  // Child face 0 = corner 0 of face 0: uv (0,0), edge midpoint (0.5,0), centre (0.5,0.5), (0,0.5).
  auto value = [&](Index corner) {
    const auto i = static_cast<std::size_t>(uv.indices[static_cast<std::size_t>(corner)]) * 2;
    return std::pair<double, double>(uv.values[i], uv.values[i + 1]);
  };
  EXPECT_EQ(value(0), (std::pair<double, double>(0, 0)));
  EXPECT_EQ(value(1), (std::pair<double, double>(0.5, 0)));
  EXPECT_EQ(value(2), (std::pair<double, double>(0.5, 0.5)));
  EXPECT_EQ(value(3), (std::pair<double, double>(0, 0.5)));
  // The second island keeps its own values across the seam.
  EXPECT_EQ(value(4 * 4 + 2), (std::pair<double, double>(5.5, 0.5)));
}

}  // namespace
}  // namespace subdiv

namespace subdiv {
namespace {

// The derived topology of a quad-split level equals the generic construction
// from the child's faces, array for array, level after level.
TEST(QuadSplit, DerivedTopologyEqualsTheGenericOne) {
  std::vector<std::pair<std::string, PolygonMesh>> cases;
  cases.emplace_back("cube", test::cube());
  cases.emplace_back("grid", test::quad_grid(4, 3));
  cases.emplace_back("triangles", test::triangle_grid(3, 2));
  cases.emplace_back("spot", read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh);
  PolygonMesh with_isolated = test::quad_grid(2, 2);
  with_isolated.positions.push_back({9, 9, 9});
  cases.emplace_back("isolated vertex", with_isolated);
  PolygonMesh polygons = make_mesh({{0, 0, 0}, {1, 0, 0}, {2, 0.5, 0}, {1, 1, 0}, {0, 1, 0}, {3, 0, 0}},
                                   {{0, 1, 2, 3, 4}, {1, 5, 2}});
  cases.emplace_back("polygons", polygons);
  for (const auto& [name, mesh] : cases) {
    PolygonMesh parent = mesh;
    std::optional<MeshTopology> topology = MeshTopology(parent);
    for (int level = 1; level <= 3; ++level) {
      PolygonMesh child;
      split_topology(parent, *topology, SplitRule::quad, child);
      const std::optional<MeshTopology> derived = MeshTopology::from_quad_split(*topology, child);
      ASSERT_TRUE(derived.has_value()) << name;
      const MeshTopology generic(child);
      EXPECT_TRUE(*derived == generic) << name << " level " << level;
      parent = std::move(child);
      topology = derived;
    }
  }
  // Non-manifold parents are left to the generic construction.
  const PolygonMesh bowtie = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
  PolygonMesh child;
  const MeshTopology t(bowtie);
  split_topology(bowtie, t, SplitRule::quad, child);
  EXPECT_FALSE(MeshTopology::from_quad_split(t, child).has_value());
}

}  // namespace
}  // namespace subdiv

namespace subdiv {
namespace {

TEST(TriangleSplit, DerivedTopologyEqualsTheGenericOne) {
  std::vector<std::pair<std::string, PolygonMesh>> cases;
  cases.emplace_back("tetrahedron", test::tetrahedron());
  cases.emplace_back("grid", test::triangle_grid(4, 3));
  cases.emplace_back("elephant", read_mesh(test::bundled_path("elephant.obj")).mesh);
  PolygonMesh with_isolated = test::triangle_grid(2, 2);
  with_isolated.positions.push_back({9, 9, 9});
  cases.emplace_back("isolated vertex", with_isolated);
  for (const auto& [name, mesh] : cases) {
    PolygonMesh parent = mesh;
    std::optional<MeshTopology> topology = MeshTopology(parent);
    for (int level = 1; level <= (name == "elephant" ? 1 : 3); ++level) {
      PolygonMesh child;
      split_topology(parent, *topology, SplitRule::triangle, child);
      const std::optional<MeshTopology> derived = MeshTopology::from_triangle_split(*topology, child);
      ASSERT_TRUE(derived.has_value()) << name;
      EXPECT_TRUE(*derived == MeshTopology(child)) << name << " level " << level;
      parent = std::move(child);
      topology = derived;
    }
  }
  // Two triangles on the same three vertices would merge child edges.
  const PolygonMesh pillow = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}});
  PolygonMesh child;
  const MeshTopology t(pillow);
  split_topology(pillow, t, SplitRule::triangle, child);
  EXPECT_FALSE(MeshTopology::from_triangle_split(t, child).has_value());
}

// A closed m x n quad torus (or each quad split into two triangles), big
// enough that the derived topologies' parallel loops run in several blocks.
PolygonMesh torus_mesh(int m, int n, bool triangles) {
  std::vector<Vec3> p;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) {
      const double u = 2.0 * std::numbers::pi * i / m, v = 2.0 * std::numbers::pi * j / n;
      p.push_back({(3.0 + std::cos(v)) * std::cos(u), (3.0 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  const auto at = [m, n](int i, int j) { return static_cast<Index>((i % m) + m * (j % n)); };
  std::vector<std::vector<Index>> faces;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) {
      const Index a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (triangles) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, c, d});
      }
    }
  return make_mesh(std::move(p), faces);
}

// The sqrt3 split's derived topology equals the one built from the child's
// faces, level after level, on closed meshes; open meshes (whose trisecting
// steps it does not cover) get none.
TEST(DerivedTopology, Sqrt3SplitMatchesTheGenericBuild) {
  std::vector<std::pair<std::string, PolygonMesh>> cases;
  cases.emplace_back("tetrahedron", test::tetrahedron());
  cases.emplace_back("cube", triangulate(test::cube()));
  cases.emplace_back("torus", torus_mesh(48, 32, true));
  PolygonMesh with_isolated = test::tetrahedron();
  with_isolated.positions.push_back({9, 9, 9});
  cases.emplace_back("isolated vertex", with_isolated);
  for (const auto& [name, mesh] : cases) {
    PolygonMesh parent = mesh;
    std::optional<MeshTopology> topology = MeshTopology(parent);
    for (int level = 0; level < 4; ++level) {
      PolygonMesh child;
      split_topology(parent, *topology, SplitRule::sqrt3, child, {}, level);
      const std::optional<MeshTopology> derived = MeshTopology::from_sqrt3_split(*topology, child);
      ASSERT_TRUE(derived.has_value()) << name;
      EXPECT_TRUE(*derived == MeshTopology(child)) << name << " level " << level;
      parent = std::move(child);
      topology = derived;
    }
  }
  const PolygonMesh open = test::triangle_grid(3, 2);
  const MeshTopology t(open);
  PolygonMesh child;
  split_topology(open, t, SplitRule::sqrt3, child);
  EXPECT_FALSE(MeshTopology::from_sqrt3_split(t, child).has_value());
}

// The same for the sqrt2 split, on closed polygon meshes (the cube's quads,
// a mix of triangles and quads).
TEST(DerivedTopology, Sqrt2SplitMatchesTheGenericBuild) {
  std::vector<std::pair<std::string, PolygonMesh>> cases;
  cases.emplace_back("cube", test::cube());
  cases.emplace_back("tetrahedron", test::tetrahedron());
  cases.emplace_back("torus", torus_mesh(48, 32, false));
  PolygonMesh with_isolated = test::cube();
  with_isolated.positions.push_back({9, 9, 9});
  cases.emplace_back("isolated vertex", with_isolated);
  for (const auto& [name, mesh] : cases) {
    PolygonMesh parent = mesh;
    std::optional<MeshTopology> topology = MeshTopology(parent);
    for (int level = 0; level < 4; ++level) {
      PolygonMesh child;
      split_topology(parent, *topology, SplitRule::sqrt2, child);
      const std::optional<MeshTopology> derived = MeshTopology::from_sqrt2_split(*topology, child);
      ASSERT_TRUE(derived.has_value()) << name;
      EXPECT_TRUE(*derived == MeshTopology(child)) << name << " level " << level;
      parent = std::move(child);
      topology = derived;
    }
  }
  const PolygonMesh open = test::quad_grid(3, 2);
  const MeshTopology t(open);
  PolygonMesh child;
  split_topology(open, t, SplitRule::sqrt2, child);
  EXPECT_FALSE(MeshTopology::from_sqrt2_split(t, child).has_value());
}

}  // namespace
}  // namespace subdiv
