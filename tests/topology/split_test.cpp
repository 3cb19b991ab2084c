#include "subdiv/topology/split.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include <set>

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

// A side joining a vertex to itself is an edge: the quad split splits it
// (child faces without a repeated vertex), the splits without rules for it
// refuse it.
TEST(Split, DegenerateFacesSplitByTheQuadSplitOnly) {
  PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1, 1, 2}});
  const MeshTopology topology(mesh);
  PolygonMesh child;
  const SplitMap map = split_topology(mesh, topology, SplitRule::quad, child);
  EXPECT_EQ(map.child_vertex_count, 1 + 4 + 3);
  for (Index f = 0; f < child.face_count(); ++f) {
    const auto face = child.face(f);
    EXPECT_EQ(std::set<Index>(face.begin(), face.end()).size(), 4u) << "child face " << f;
  }
  // The vertex point of 1 is tagged a corner for good.
  ASSERT_EQ(child.tags.corners.size(), 1u);
  EXPECT_EQ(child.tags.corners[0].vertex, map.vertex_point(1));
  for (const SplitRule rule : {SplitRule::dual, SplitRule::midedge, SplitRule::sqrt2}) {
    PolygonMesh other;
    EXPECT_THROW(split_topology(mesh, topology, rule, other), TopologyError) << to_string(rule);
  }
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

using DerivedTopology = std::optional<MeshTopology> (*)(const MeshTopology& parent, const PolygonMesh& child);
using NamedMeshes = std::vector<std::pair<std::string, PolygonMesh>>;

// Splits each mesh `levels` times with `rule`: every level's topology as
// `derive` makes it from its parent's must equal the generic construction
// from the child's faces, array for array.
void expect_derived_topology_is_the_generic_one(const NamedMeshes& cases, SplitRule rule, DerivedTopology derive,
                                                int levels) {
  for (const auto& [name, mesh] : cases) {
    PolygonMesh parent = mesh;
    std::optional<MeshTopology> topology = MeshTopology(parent);
    for (int level = 0; level < levels; ++level) {
      PolygonMesh child;
      split_topology(parent, *topology, rule, child, {.level = level});
      const std::optional<MeshTopology> derived = derive(*topology, child);
      ASSERT_TRUE(derived.has_value()) << name;
      EXPECT_TRUE(*derived == MeshTopology(child)) << name << " level " << level;
      parent = std::move(child);
      topology = derived;
    }
  }
}

// Parents the derivation does not cover are left to the generic construction.
void expect_no_derived_topology(const PolygonMesh& mesh, SplitRule rule, DerivedTopology derive) {
  const MeshTopology t(mesh);
  PolygonMesh child;
  split_topology(mesh, t, rule, child);
  EXPECT_FALSE(derive(t, child).has_value());
}

PolygonMesh with_isolated_vertex(PolygonMesh mesh) {
  mesh.positions.push_back({9, 9, 9});
  return mesh;
}

TEST(QuadSplit, DerivedTopologyEqualsTheGenericOne) {
  NamedMeshes cases;
  cases.emplace_back("cube", test::cube());
  cases.emplace_back("grid", test::quad_grid(4, 3));
  cases.emplace_back("triangles", test::triangle_grid(3, 2));
  cases.emplace_back("spot", read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh);
  cases.emplace_back("isolated vertex", with_isolated_vertex(test::quad_grid(2, 2)));
  cases.emplace_back("polygons", make_mesh({{0, 0, 0}, {1, 0, 0}, {2, 0.5, 0}, {1, 1, 0}, {0, 1, 0}, {3, 0, 0}},
                                           {{0, 1, 2, 3, 4}, {1, 5, 2}}));
  expect_derived_topology_is_the_generic_one(cases, SplitRule::quad, MeshTopology::from_quad_split, 3);
  const PolygonMesh bowtie = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
  expect_no_derived_topology(bowtie, SplitRule::quad, MeshTopology::from_quad_split);
}

TEST(TriangleSplit, DerivedTopologyEqualsTheGenericOne) {
  NamedMeshes cases;
  cases.emplace_back("tetrahedron", test::tetrahedron());
  cases.emplace_back("grid", test::triangle_grid(4, 3));
  cases.emplace_back("isolated vertex", with_isolated_vertex(test::triangle_grid(2, 2)));
  expect_derived_topology_is_the_generic_one(cases, SplitRule::triangle, MeshTopology::from_triangle_split, 3);
  const NamedMeshes elephant = {{"elephant", read_mesh(test::bundled_path("elephant.obj")).mesh}};
  expect_derived_topology_is_the_generic_one(elephant, SplitRule::triangle, MeshTopology::from_triangle_split, 1);
  // Two triangles on the same three vertices would merge child edges.
  const PolygonMesh pillow = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}});
  expect_no_derived_topology(pillow, SplitRule::triangle, MeshTopology::from_triangle_split);
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

// The sqrt3 split's derived topology, on closed meshes; open meshes (whose
// trisecting steps it does not cover) get none.
TEST(DerivedTopology, Sqrt3SplitMatchesTheGenericBuild) {
  NamedMeshes cases;
  cases.emplace_back("tetrahedron", test::tetrahedron());
  cases.emplace_back("cube", triangulate(test::cube()));
  cases.emplace_back("torus", torus_mesh(48, 32, true));
  cases.emplace_back("isolated vertex", with_isolated_vertex(test::tetrahedron()));
  expect_derived_topology_is_the_generic_one(cases, SplitRule::sqrt3, MeshTopology::from_sqrt3_split, 4);
  expect_no_derived_topology(test::triangle_grid(3, 2), SplitRule::sqrt3, MeshTopology::from_sqrt3_split);
}

// The sqrt2 split's, on closed polygon meshes (the cube's quads, a mix of
// triangles and quads); open meshes get none.
TEST(DerivedTopology, Sqrt2SplitMatchesTheGenericBuild) {
  NamedMeshes cases;
  cases.emplace_back("cube", test::cube());
  cases.emplace_back("tetrahedron", test::tetrahedron());
  cases.emplace_back("torus", torus_mesh(48, 32, false));
  cases.emplace_back("isolated vertex", with_isolated_vertex(test::cube()));
  expect_derived_topology_is_the_generic_one(cases, SplitRule::sqrt2, MeshTopology::from_sqrt2_split, 4);
  expect_no_derived_topology(test::quad_grid(3, 2), SplitRule::sqrt2, MeshTopology::from_sqrt2_split);
}

// The sqrt2 and sqrt3 splits give each child vertex one value: a face
// point its face's mean, a boundary point (sqrt3's trisecting steps) 2/3 and
// 1/3 of its edge's ends, an old vertex its own. The data is seamless (one
// value per vertex: uv = (x, y)), so each vertex's value is well defined.
TEST(Split, FaceVaryingDataOfThePointSplits) {
  for (const SplitRule rule : {SplitRule::sqrt2, SplitRule::sqrt3}) {
    PolygonMesh mesh = rule == SplitRule::sqrt2 ? test::quad_grid(2, 2) : test::triangle_grid(2, 2);
    FaceVaryingChannel uv{"uv", 2, {}, {}};
    for (const Vec3& p : mesh.positions) uv.values.insert(uv.values.end(), {p.x, p.y});
    uv.indices = mesh.face_indices;
    mesh.face_varying_channels.push_back(uv);
    // sqrt3: a step without boundary points first, so that the trisecting
    // step (with them) gets a triangle per boundary edge.
    for (int level = 0; level < (rule == SplitRule::sqrt3 ? 2 : 1); ++level) {
      const MeshTopology t(mesh);
      const FaceVaryingChannel& in = mesh.face_varying_channels.at(0);
      std::vector<Vec3> value(static_cast<std::size_t>(mesh.vertex_count()));
      for (std::size_t c = 0; c < in.indices.size(); ++c) {
        const auto at = 2 * static_cast<std::size_t>(in.indices[c]);
        value[static_cast<std::size_t>(mesh.face_indices[c])] = {in.values[at], in.values[at + 1], 0.0};
      }
      Split s;
      s.map = split_topology(mesh, t, rule, s.child, {.level = level});
      std::vector<Vec3> expected(static_cast<std::size_t>(s.map.child_vertex_count));
      for (Index i = 0; i < s.map.edge_points; ++i) {
        const Index f = s.map.point_face(i);
        for (const Index v : mesh.face(f)) expected[static_cast<std::size_t>(i)] += (1.0 / t.face_size(f)) * value[v];
      }
      for (std::size_t r = 0; r < s.map.boundary_edges.size(); ++r) {
        const auto [a, b] = t.edge_vertices(s.map.boundary_edges[r]);
        expected[static_cast<std::size_t>(s.map.edge_points) + 2 * r] = (2.0 / 3.0) * value[a] + (1.0 / 3.0) * value[b];
        expected[static_cast<std::size_t>(s.map.edge_points) + 2 * r + 1] = (1.0 / 3.0) * value[a] + (2.0 / 3.0) * value[b];
      }
      for (Index v = 0; v < mesh.vertex_count(); ++v) expected[static_cast<std::size_t>(s.map.vertex_point(v))] = value[v];
      EXPECT_EQ(s.map.boundary_edges.empty(), rule == SplitRule::sqrt2 || level == 0);
      const FaceVaryingChannel& out = s.child.face_varying_channels.at(0);
      ASSERT_EQ(out.indices, s.child.face_indices);
      for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(out.values[2 * i], expected[i].x, 1e-14) << to_string(rule) << " level " << level << " vertex " << i;
        EXPECT_NEAR(out.values[2 * i + 1], expected[i].y, 1e-14) << to_string(rule) << " level " << level << " vertex " << i;
      }
      mesh = std::move(s.child);
    }
  }
}

}  // namespace
}  // namespace subdiv
