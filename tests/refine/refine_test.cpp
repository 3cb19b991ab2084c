#include "subdiv/refine/refine.h"
#include "subdiv/refine/hierarchy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
#include "support/refine_options.h"
#include "support/scheme_by_name.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::scheme;

using test::levels;

PolygonMesh creased_cube() {
  PolygonMesh m = test::cube();
  m.tags.creases = {{0, 1, 10.0}, {1, 2, 2.5}, {2, 6, 0.5}};
  m.tags.corners = {{7, 10.0, CornerType::unspecified, std::nullopt}, {4, 0.7, CornerType::unspecified, std::nullopt}};
  return m;
}

// The creased cube with Chaikin creasing: vertex 2 joins semi-sharp edges of
// 2.5 and 0.5, so the halves of 1-2 and 2-6 differ one level down.
PolygonMesh chaikin_creased_cube() {
  PolygonMesh m = creased_cube();
  m.tags.crease_method = CreaseMethod::chaikin;
  m.tags.crease_method_set = true;
  return m;
}

// Meshes that exercise every rule: smooth, boundary, corner, crease,
// semi-sharp (uniform and Chaikin creasing), n-gons and triangles.
std::vector<std::pair<std::string, PolygonMesh>> quad_cases() {
  std::vector<std::pair<std::string, PolygonMesh>> out;
  out.emplace_back("cube", test::cube());
  out.emplace_back("creased cube", creased_cube());
  out.emplace_back("chaikin creased cube", chaikin_creased_cube());
  out.emplace_back("grid", test::quad_grid(3, 2));
  out.emplace_back("spot", read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh);
  return out;
}
std::vector<std::pair<std::string, PolygonMesh>> triangle_cases() {
  std::vector<std::pair<std::string, PolygonMesh>> out;
  out.emplace_back("tetrahedron", test::tetrahedron());
  out.emplace_back("triangulated creased cube", triangulate(creased_cube()));
  out.emplace_back("triangulated chaikin creased cube", triangulate(chaikin_creased_cube()));
  out.emplace_back("triangle grid", test::triangle_grid(3, 3));
  return out;
}
std::vector<std::pair<const Scheme*, std::vector<std::pair<std::string, PolygonMesh>>>> all_cases() {
  return {{&scheme("catmull-clark"), quad_cases()}, {&scheme("bilinear"), quad_cases()},
          {&scheme("loop"), triangle_cases()}, {&scheme("loop-warren"), triangle_cases()},
          {&scheme("linear"), triangle_cases()}};
}

double scale_of(const PolygonMesh& m) {
  double s = 0;
  for (const Vec3& p : m.positions) s = std::max({s, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  return std::max(s, 1.0);
}

TEST(Refine, EveryStencilRowSumsToOne) {
  for (const auto& [s, cases] : all_cases())
    for (const auto& [name, mesh] : cases) {
      RefineOptions o;
      o.levels = 2;
      for (const StencilTable& t : refine_stencils(mesh, *s, o))
        for (Index r = 0; r < t.row_count(); ++r) {
          const auto w = t.row_weights(r);
          EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-14) << s->name << " " << name << " row " << r;
        }
    }
}

TEST(Refine, StencilPathReproducesTheFastPath) {
  for (const auto& [s, cases] : all_cases())
    for (const auto& [name, mesh] : cases) {
      RefineOptions o;
      o.levels = 3;
      const PolygonMesh fast = refine(mesh, *s, o);
      PolygonMesh via_tables;
      const auto tables = refine_stencils(mesh, *s, o, &via_tables);
      ASSERT_EQ(tables.size(), 3u);
      // Level by level the tables hold the same masks; where a mask weights a
      // new face point (Catmull-Clark), the table holds that face point's
      // weights instead, so the two agree to rounding, not bit for bit.
      ASSERT_EQ(via_tables.positions.size(), fast.positions.size());
      for (std::size_t i = 0; i < fast.positions.size(); ++i)
        ASSERT_LT(norm(via_tables.positions[i] - fast.positions[i]), 1e-14 * scale_of(mesh))
            << s->name << " " << name << " " << i;
      EXPECT_EQ(via_tables.face_indices, fast.face_indices);
      // Composed into one coarse -> level-3 table: the same up to rounding.
      const StencilTable total = compose(tables);
      std::vector<Vec3> direct(static_cast<std::size_t>(total.row_count()));
      total.apply(mesh.positions, direct);
      for (std::size_t i = 0; i < direct.size(); ++i)
        ASSERT_LT(norm(direct[i] - fast.positions[i]), 1e-13 * scale_of(mesh)) << s->name << " " << name << " " << i;
      // Built composed level by level: the same rows up to rounding.
      const StencilTable built = refine_stencil_table(mesh, *s, o);
      ASSERT_EQ(built.row_count(), total.row_count());
      ASSERT_EQ(built.source_count(), mesh.vertex_count());
      for (Index r = 0; r < built.row_count(); ++r) {
        ASSERT_TRUE(std::equal(built.row_vertices(r).begin(), built.row_vertices(r).end(),
                               total.row_vertices(r).begin(), total.row_vertices(r).end()))
            << s->name << " " << name << " row " << r;
        for (std::size_t j = 0; j < built.row_weights(r).size(); ++j)
          ASSERT_NEAR(built.row_weights(r)[j], total.row_weights(r)[j], 1e-15) << s->name << " " << name << " row " << r;
      }
    }
}

TEST(Refine, ResultsDoNotDependOnTheThreadCount) {
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  RefineOptions one, two;
  one.levels = two.levels = 4;
  one.threads = 1;
  two.threads = 2;
  EXPECT_EQ(refine(spot, scheme("catmull-clark"), one).positions, refine(spot, scheme("catmull-clark"), two).positions);
  const PolygonMesh elephant = read_mesh(test::bundled_path("elephant.obj")).mesh;
  one.levels = two.levels = 2;
  EXPECT_EQ(refine(elephant, scheme("loop"), one).positions, refine(elephant, scheme("loop"), two).positions);
}

TEST(Refine, AffineInvariance) {
  // A x + b commutes with refinement because every mask's weights sum to 1.
  const double a[3][3] = {{0.8, -0.3, 0.1}, {0.2, 1.1, -0.4}, {0.05, 0.3, 0.9}};
  const Vec3 b{3, -2, 0.5};
  auto map = [&](Vec3 p) {
    return Vec3{a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z, a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z,
                a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z} + b;
  };
  for (const auto& [s, cases] : all_cases())
    for (const auto& [name, mesh] : cases) {
      PolygonMesh moved = mesh;
      for (Vec3& p : moved.positions) p = map(p);
      RefineOptions o;
      o.levels = 2;
      const PolygonMesh r1 = refine(mesh, *s, o), r2 = refine(moved, *s, o);
      for (std::size_t i = 0; i < r1.positions.size(); ++i)
        ASSERT_LT(norm(map(r1.positions[i]) - r2.positions[i]), 1e-12 * scale_of(moved)) << s->name << " " << name;
    }
}

TEST(Refine, InvariantUnderRenumberingVerticesAndRotatingFaces) {
  std::mt19937 rng(7);
  for (const auto& [s, cases] : all_cases())
    for (const auto& [name, mesh] : cases) {
      std::vector<Index> perm(static_cast<std::size_t>(mesh.vertex_count()));
      std::iota(perm.begin(), perm.end(), 0);
      std::shuffle(perm.begin(), perm.end(), rng);
      PolygonMesh renumbered = mesh;
      for (Index v = 0; v < mesh.vertex_count(); ++v) renumbered.positions[static_cast<std::size_t>(perm[v])] = mesh.positions[v];
      renumbered.face_indices.clear();
      renumbered.face_offsets = {0};
      for (Index f = 0; f < mesh.face_count(); ++f) {  // also start every face at another corner
        const auto face = mesh.face(f);
        std::vector<Index> rotated;
        for (std::size_t i = 0; i < face.size(); ++i) rotated.push_back(perm[face[(i + 1) % face.size()]]);
        renumbered.add_face(rotated);
      }
      for (auto& c : renumbered.tags.creases) c = {perm[c.v0], perm[c.v1], c.sharpness};
      for (auto& c : renumbered.tags.corners) c.vertex = perm[c.vertex];

      RefineOptions o;
      o.levels = 1;
      const PolygonMesh r1 = refine(mesh, *s, o), r2 = refine(renumbered, *s, o);
      const MeshTopology t1(mesh), t2(renumbered);
      const Index e1 = s->split == SplitRule::quad ? mesh.face_count() : 0;
      const Index v1 = e1 + t1.edge_count();
      for (Index v = 0; v < mesh.vertex_count(); ++v)  // vertex points
        ASSERT_LT(norm(r1.positions[v1 + v] - r2.positions[v1 + perm[v]]), 1e-14 * scale_of(mesh)) << s->name << " " << name;
      for (Index e = 0; e < t1.edge_count(); ++e) {  // edge points
        const auto [a, b] = t1.edge_vertices(e);
        const Index e2 = t2.find_edge(perm[a], perm[b]);
        ASSERT_LT(norm(r1.positions[e1 + e] - r2.positions[e1 + e2]), 1e-14 * scale_of(mesh)) << s->name << " " << name;
      }
    }
}

TEST(Refine, VertexChannelsFollowThePositionMasks) {
  PolygonMesh mesh = creased_cube();
  VertexChannel copy{"copy", 3, {}};
  for (const Vec3& p : mesh.positions) copy.values.insert(copy.values.end(), {p.x, p.y, p.z});
  mesh.vertex_channels.push_back(copy);
  RefineOptions o;
  o.levels = 2;
  const PolygonMesh r = refine(mesh, scheme("catmull-clark"), o);
  ASSERT_EQ(r.vertex_channels.size(), 1u);
  for (Index v = 0; v < r.vertex_count(); ++v)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(r.vertex_channels[0].values[static_cast<std::size_t>(v) * 3 + static_cast<std::size_t>(i)], r.positions[v][i]);
}

TEST(Refine, LevelsAreCompleteValidMeshes) {
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  RefineOptions o;
  o.levels = 2;
  int seen = 0;
  o.on_level = [&](int level, const PolygonMesh& m) {
    ++seen;
    EXPECT_EQ(level, seen);
    EXPECT_TRUE(validate(m).ok());
    EXPECT_NE(m.find_face_varying_channel("uv"), nullptr);
  };
  const PolygonMesh r = refine(spot, scheme("catmull-clark"), o);
  EXPECT_EQ(seen, 2);
  EXPECT_EQ(r.face_count(), 2928);  // 180 faces, 732 quads after one step, x4
  EXPECT_EQ(refine(spot, scheme("catmull-clark"), levels(0)).positions, spot.positions);
}

TEST(Refine, RejectsWhatItCannotRefine) {
  try {
    refine(test::cube(), scheme("loop"));
    FAIL();
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("loop needs a triangle mesh, but face 0 has 4 vertices"), std::string::npos);
  }
  PolygonMesh bowtie = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
  try {
    refine(bowtie, scheme("loop"));
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("RuleOptions::allow_non_manifold"), std::string::npos) << e.what();
  }
  RefineOptions allow;
  allow.allow_non_manifold = true;
  const PolygonMesh r = refine(bowtie, scheme("loop"), allow);
  EXPECT_EQ(r.positions[6 + 0], bowtie.positions[0]);  // the non-manifold vertex is a corner: kept
  PolygonMesh none = test::cube();
  none.tags.boundary_interpolation = BoundaryInterpolation::none;
  EXPECT_THROW(refine(none, scheme("catmull-clark")), InvalidInputError);
  EXPECT_THROW(refine(test::cube(), scheme("catmull-clark"), levels(-1)), InvalidInputError);
}

// A face repeating a vertex (quad (2, 6, 5, 5)) refines as OpenSubdiv
// refines it where non-manifold input is allowed, for the schemes that say
// so; the others refuse it, naming the face.
TEST(Refine, FacesRepeatingAVertexRefineAsOpenSubdivWhereAllowed) {
  const PolygonMesh mesh = make_mesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0.5}, {3, 0, 0}},
                                     {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 6, 5, 5}});
  try {
    refine(mesh, scheme("catmull-clark"));
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("face 2 uses a vertex more than once (RuleOptions::allow_non_manifold refines "
                                         "it as OpenSubdiv does)"),
              std::string::npos)
        << e.what();
  }
  RefineOptions allow;
  allow.allow_non_manifold = true;
  EXPECT_THROW(refine(mesh, scheme("kobbelt"), allow), ValidationError);
  const PolygonMesh one = refine(mesh, scheme("catmull-clark"), allow);
  // 3 face points, 10 edge points (the side from 5 to 5 is an edge), 7 vertex points.
  EXPECT_EQ(one.vertex_count(), 20);
  EXPECT_EQ(one.face_count(), 12);
  // Vertex 5 is a corner, and the zero-length edge's point is at it too.
  EXPECT_EQ(std::ranges::count(one.positions, mesh.positions[5]), 2);
  ASSERT_EQ(one.tags.corners.size(), 1u);  // it stays a corner
  EXPECT_EQ(one.tags.corners[0].vertex, 3 + 10 + 5);
  // Two levels at once keep the halves of that edge apart: a slit, each
  // half a boundary edge with its own point at vertex 5's position, and the
  // first level's point between them a crease vertex there too. A level
  // written out and refined again joins the halves into one smooth edge.
  allow.levels = 2;
  const PolygonMesh two = refine(mesh, scheme("catmull-clark"), allow);
  const PolygonMesh again = refine(one, scheme("catmull-clark"), levels(1));
  EXPECT_EQ(two.face_count(), again.face_count());
  EXPECT_EQ(two.vertex_count(), again.vertex_count() + 1);
  EXPECT_EQ(std::ranges::count(two.positions, mesh.positions[5]), 4);
  EXPECT_LT(std::ranges::count(again.positions, mesh.positions[5]), 4);
}

// Finite input near the double range: Kobbelt's negative weights grow
// heights that alternate in sign (the four-point rule gives (1 + 4w) times
// them), so the result would be infinite and is refused; Catmull-Clark's
// weights are positive and stay in range.
TEST(Refine, RefusesAResultThatOverflowsTheDoubleRange) {
  PolygonMesh huge = test::quad_grid(8, 8);
  for (Index v = 0; v < huge.vertex_count(); ++v) {
    Vec3& p = huge.positions[static_cast<std::size_t>(v)];
    p.z = (static_cast<int>(p.x + p.y) % 2 == 0 ? 1.5e308 : -1.5e308);
  }
  ASSERT_TRUE(validate(huge).ok());
  for (const bool grids : {true, false}) {
    RefineOptions options = levels(2);
    options.regular_grids = grids;
    try {
      refine(huge, scheme("kobbelt"), options);
      FAIL() << "kobbelt returned infinite coordinates";
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("kobbelt overflowed the double range: vertex "), std::string::npos)
          << e.what();
    }
    EXPECT_THROW(refine_hierarchy(huge, scheme("kobbelt"), options), InvalidInputError);
    const PolygonMesh smooth = refine(huge, scheme("catmull-clark"), options);
    EXPECT_TRUE(validate(smooth).ok());
  }
}

TEST(Refine, EmptyMeshGivesEmptyResultsForEveryScheme) {
  // Found by the Python module's property test: the grid paths divided by
  // the face count (SIGFPE) when the stencil table of an empty mesh was built.
  const PolygonMesh empty;
  for (const Scheme* scheme : all_schemes()) {
    for (const bool grids : {true, false}) {
      RefineOptions options;
      options.levels = 2;
      options.regular_grids = grids;
      try {
        EXPECT_EQ(refine(empty, *scheme, options).face_count(), 0) << scheme->name;
        EXPECT_EQ(refine_stencil_table(empty, *scheme, options).row_count(), 0) << scheme->name;
      } catch (const Error&) {
        // A typed refusal is an answer too; a crash is not.
      }
    }
  }
}

TEST(Refine, RefusesDoubledTrianglesWhereTheSplitCannotIndexTheResult) {
  // Found by fuzz_pipeline: two triangles on the same three vertices (a
  // closed mesh of two faces) are valid, but the triangle, sqrt3 and quasi
  // 4-8 splits made non-manifold meshes of them without a word; they refuse
  // them unless non-manifold input is allowed.
  const PolygonMesh pillow = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{1, 0, 2}, {0, 1, 2}});
  ASSERT_TRUE(validate(pillow).ok());
  for (const char* name : {"loop", "linear", "modified-butterfly", "sqrt3", "interpolatory-sqrt3", "quasi-4-8"}) {
    SCOPED_TRACE(name);
    try {
      refine(pillow, scheme(name));
      FAIL();
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("faces 0 and 1 are triangles on the same three vertices"), std::string::npos)
          << e.what();
    }
  }
  // The splits that add a point per face keep them apart: a valid result.
  for (const char* name : {"catmull-clark", "doo-sabin", "four-eight"}) {
    SCOPED_TRACE(name);
    EXPECT_TRUE(validate(refine(pillow, scheme(name), levels(2))).ok());
  }
  // Allowed non-manifold input, Loop keeps the two edges inside the pair
  // apart (as OpenSubdiv does; opensubdiv_coincident_edges_test.cpp), so
  // two levels at once differ from two levels one after the other, whose
  // second sees one edge with four faces there.
  RefineOptions allow;
  allow.allow_non_manifold = true;
  const PolygonMesh once = refine(pillow, scheme("loop"), allow);
  allow.levels = 2;
  const PolygonMesh at_once = refine(pillow, scheme("loop"), allow);
  allow.levels = 1;
  allow.start_level = 1;
  const PolygonMesh in_turn = refine(once, scheme("loop"), allow);
  EXPECT_EQ(at_once.face_count(), in_turn.face_count());
  EXPECT_GT(at_once.vertex_count(), in_turn.vertex_count());
  // Two triangles sharing one edge, or two of three vertices, are ordinary.
  const PolygonMesh pair = make_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {2, 1, 3}});
  EXPECT_TRUE(validate(refine(pair, scheme("loop"), levels(2))).ok());
}

}  // namespace
}  // namespace subdiv
