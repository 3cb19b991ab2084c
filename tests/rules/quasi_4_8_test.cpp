// Quasi 4-8 smoothing (Velho, Algorithm 2): the in-place passes against the
// recorded stencils, the stencils of Figure 4 on the regular 4-8 grid,
// invariants, tags and boundaries.

#include "subdiv/rules/quasi_4_8.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "subdiv/core/error.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"
#include "support/four_eight_meshes.h"

namespace subdiv {
namespace {

using test::ngon_fan;

RefineOptions steps(int n) {
  RefineOptions options;
  options.levels = n;
  return options;
}

// Quasi 4-8 with this boundary treatment (a family parameter).
Scheme quasi(Quasi48Boundary boundary) {
  Scheme s = quasi_4_8_scheme();
  std::get<Quasi48Parameters>(s.parameters).boundary = boundary;
  return s;
}

// A closed-ish test mesh with irregular valences and a boundary: the
// perturbed 9-gon, lifted off the plane.
PolygonMesh bumpy_ngon() {
  PolygonMesh mesh = ngon_fan(9, 0.2, 11);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i].z = 0.1 * std::sin(3.0 * double(i));
  return mesh;
}

TEST(QuasiFourEight, Registered) {
  const Scheme* s = find_scheme("quasi-4-8");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->split, SplitRule::quasi_4_8);
  EXPECT_EQ(s->traits.period, 2);
  EXPECT_TRUE(s->traits.needs_triangles);
  EXPECT_DOUBLE_EQ(arity(s->split), std::sqrt(2.0));
}

// "Note that this cascade convolution makes it possible to execute all the
// computations in-place": the fast path (in place, pass 1 then pass 2) and
// the composed stencil rows give the same positions.
TEST(QuasiFourEight, InPlacePassesEqualStencils) {
  for (const Quasi48Boundary b : {Quasi48Boundary::fixed, Quasi48Boundary::smoothed}) {
    const PolygonMesh mesh = bumpy_ngon();
    const PolygonMesh fast = refine(mesh, quasi(b), steps(5));
    PolygonMesh recorded;
    const std::vector<StencilTable> tables = refine_stencils(mesh, quasi(b), steps(5), &recorded);
    ASSERT_EQ(tables.size(), 5u);
    ASSERT_EQ(fast.face_indices, recorded.face_indices);
    for (Index v = 0; v < fast.vertex_count(); ++v)
      EXPECT_LT(norm(fast.positions[v] - recorded.positions[v]), 1e-13) << "vertex " << v;
    // Through the composed table from the control mesh, too.
    const StencilTable total = refine_stencil_table(mesh, quasi(b), steps(5));
    std::vector<Vec3> p(static_cast<std::size_t>(total.row_count()));
    total.apply(mesh.positions, p);
    for (Index v = 0; v < fast.vertex_count(); ++v) EXPECT_LT(norm(fast.positions[v] - p[v]), 1e-12);
    for (const StencilTable& t : tables)
      for (Index r = 0; r < t.row_count(); ++r) {
        double sum = 0.0;
        for (const double w : t.row_weights(r)) sum += w;
        EXPECT_NEAR(sum, 1.0, 1e-14) << "row " << r;  // affine invariance
      }
  }
}

// Figure 4 (its picture is lost; the weights follow from Algorithm 2 and
// are checked here against the lattice, not against the code's topology):
// on the regular 4-8 grid, after either kind of binary step, a new vertex
// is 1/4 on each of its four neighbours and an old vertex 5/8 on itself,
// 1/16 on the four nearest old vertices and 1/32 on the next four, a
// filter reaching past the old vertex's own 1-neighbours (valence-4 ones).
TEST(QuasiFourEight, StencilsOfFigure4OnTheRegularGrid) {
  const PolygonMesh grid = test::four_eight_grid(8);
  const std::vector<StencilTable> tables = refine_stencils(grid, quasi_4_8_scheme(), steps(2));
  PolygonMesh level1;
  refine_stencils(grid, quasi_4_8_scheme(), steps(1), &level1);
  // Step 1's sources are the grid (spacing h = 1); step 2's are level 1's,
  // the grid and the square centres (spacing h = sqrt(2) / 2).
  const std::vector<Vec3> sources[2] = {grid.positions, level1.positions};
  const double spacing[2] = {1.0, std::sqrt(0.5)};
  const auto inside = [](Vec3 p) { return p.x >= 2 && p.x <= 6 && p.y >= 2 && p.y <= 6; };
  int checked_new = 0, checked_old = 0;
  for (int step = 0; step < 2; ++step) {
    const StencilTable& t = tables[static_cast<std::size_t>(step)];
    const std::vector<Vec3>& src = sources[step];
    const double h = spacing[step];
    const Index old_count = static_cast<Index>(src.size());
    for (Index r = 0; r < t.row_count(); ++r) {
      const auto vs = t.row_vertices(r);
      const auto ws = t.row_weights(r);
      if (r >= old_count) {
        // A new vertex: its four sources lie at h / sqrt(2) around their
        // mean (a square centre, then an edge midpoint).
        Vec3 at;
        for (std::size_t j = 0; j < vs.size(); ++j)
          at += (1.0 / double(vs.size())) * src[static_cast<std::size_t>(vs[j])];
        if (!inside(at)) continue;  // boundary midpoints have two sources
        ASSERT_EQ(vs.size(), 4u) << "row " << r;
        for (std::size_t j = 0; j < 4; ++j) {
          EXPECT_DOUBLE_EQ(ws[j], 0.25);
          EXPECT_NEAR(norm(src[static_cast<std::size_t>(vs[j])] - at), h / std::sqrt(2.0), 1e-12);
        }
        ++checked_new;
        continue;
      }
      const Vec3 at = src[static_cast<std::size_t>(r)];
      if (!inside(at)) continue;
      ASSERT_EQ(vs.size(), 9u) << "row " << r;
      for (std::size_t j = 0; j < 9; ++j) {
        const double d = norm(src[static_cast<std::size_t>(vs[j])] - at);
        if (d < 1e-12)
          EXPECT_DOUBLE_EQ(ws[j], 5.0 / 8.0);
        else if (std::abs(d - h) < 1e-12)
          EXPECT_DOUBLE_EQ(ws[j], 1.0 / 16.0);
        else if (std::abs(d - h * std::sqrt(2.0)) < 1e-12)
          EXPECT_DOUBLE_EQ(ws[j], 1.0 / 32.0);
        else
          ADD_FAILURE() << "weight at distance " << d << " from row " << r;
      }
      ++checked_old;
    }
  }
  EXPECT_GT(checked_new, 20);
  EXPECT_GT(checked_old, 20);
}

// A similarity (rotation, scale, translation) keeps every length ratio, so
// the same edges split, and the smoothing is affine.
TEST(QuasiFourEight, SimilarityInvariant) {
  const PolygonMesh mesh = bumpy_ngon();
  PolygonMesh moved = mesh;
  const double c = std::cos(0.7), s = std::sin(0.7);
  const auto map = [&](Vec3 p) {
    return Vec3{2.5 * (c * p.x - s * p.y) + 1, 2.5 * (s * p.x + c * p.y) - 3, 2.5 * p.z + 4};
  };
  for (Vec3& p : moved.positions) p = map(p);
  const PolygonMesh a = refine(mesh, quasi_4_8_scheme(), steps(6));
  const PolygonMesh b = refine(moved, quasi_4_8_scheme(), steps(6));
  ASSERT_EQ(a.face_indices, b.face_indices);
  for (Index v = 0; v < a.vertex_count(); ++v) EXPECT_LT(norm(map(a.positions[v]) - b.positions[v]), 1e-11);
}

// Section 4.3: tagged vertices and edges are not smoothed.
TEST(QuasiFourEight, TaggedVerticesAndEdgesAreNotSmoothed) {
  PolygonMesh mesh = bumpy_ngon();
  mesh.tags.corners.push_back({0, kInfiniteSharpness, CornerType::unspecified, std::nullopt});  // the centre
  mesh.tags.creases.push_back({3, 4, 10.0});                                                    // a rim edge
  mesh.tags.creases.push_back({0, 6, 1.0});                                                     // a spoke
  const PolygonMesh out = refine(mesh, quasi(Quasi48Boundary::smoothed), steps(4));
  EXPECT_EQ(out.positions[0], mesh.positions[0]);
  for (const Index v : {3, 4, 6}) EXPECT_EQ(out.positions[v], mesh.positions[v]) << "vertex " << v;
  // The tagged edges' descendants: tagged segments on the original edges.
  int on_rim = 0, on_spoke = 0;
  for (const CreaseTag& t : out.tags.creases)
    for (const Index v : {t.v0, t.v1}) {
      const Vec3 p = out.positions[v];
      const auto on = [&](Index a, Index b) {
        const Vec3 d = mesh.positions[b] - mesh.positions[a];
        const double u = dot(p - mesh.positions[a], d) / dot(d, d);
        return u > -1e-12 && u < 1 + 1e-12 && norm(mesh.positions[a] + u * d - p) < 1e-12;
      };
      on_rim += on(3, 4);
      on_spoke += on(0, 6);
      EXPECT_TRUE(on(3, 4) || on(0, 6)) << "tagged vertex " << v << " left its edge";
    }
  EXPECT_GT(on_rim, 2);
  EXPECT_GT(on_spoke, 2);
}

// Section 4.1: boundary vertices do not move (fixed); smoothed, a boundary
// vertex with both boundary edges split takes the cubic B-spline rule.
TEST(QuasiFourEight, Boundaries) {
  const PolygonMesh square = ngon_fan(4);
  const PolygonMesh fixed = refine(square, quasi_4_8_scheme(), steps(1));
  for (Index v = 1; v <= 4; ++v) EXPECT_EQ(fixed.positions[v], square.positions[v]);
  const PolygonMesh smooth = refine(square, quasi(Quasi48Boundary::smoothed), steps(1));
  for (Index v = 1; v <= 4; ++v) {
    const Vec3 prev = square.positions[v == 1 ? 4 : v - 1], next = square.positions[v == 4 ? 1 : v + 1];
    const Vec3 expected = 0.75 * square.positions[v] + 0.125 * (prev + next);
    EXPECT_LT(norm(smooth.positions[v] - expected), 1e-15) << "vertex " << v;
  }
  // The split points of boundary edges stay at the midpoints in both.
  for (Index v = 5; v < fixed.vertex_count(); ++v) EXPECT_EQ(fixed.positions[v], smooth.positions[v]);
  // The interior: the centre's k = 4 new neighbours are the rim midpoints.
  EXPECT_LT(norm(fixed.positions[0]), 1e-15);
}

// Figure 11: a triangulated box with two open sides. (b) boundary tagged
// (fixed): the open rims stay; (c) boundary smoothed and one longitudinal
// interior edge tagged: the rims move, except the tagged edge's ends.
TEST(QuasiFourEight, OpenBoxFigure11) {
  // A square tube along z: rims at z = 0 and z = 2, 4 vertices each, plus a
  // middle ring at z = 1; each quad side cut by a diagonal.
  std::vector<Vec3> p;
  for (int k = 0; k < 3; ++k)
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) p.push_back({x, y, double(k)});
  std::vector<std::vector<Index>> faces;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 4; ++i) {
      const Index a = 4 * k + i, b = 4 * k + (i + 1) % 4, c = a + 4, d = b + 4;
      faces.push_back({a, b, d});
      faces.push_back({a, d, c});
    }
  const PolygonMesh box = make_mesh(p, faces);
  const PolygonMesh fixed = refine(box, quasi_4_8_scheme(), steps(4));
  for (const Index v : {0, 1, 2, 3, 8, 9, 10, 11}) EXPECT_EQ(fixed.positions[v], box.positions[v]) << v;
  PolygonMesh tagged = box;
  tagged.tags.creases.push_back({0, 4, kInfiniteSharpness});  // the longitudinal edge 0-4-8
  tagged.tags.creases.push_back({4, 8, kInfiniteSharpness});
  const PolygonMesh smooth = refine(tagged, quasi(Quasi48Boundary::smoothed), steps(4));
  for (const Index v : {0, 4, 8}) EXPECT_EQ(smooth.positions[v], box.positions[v]) << v;
  for (const Index v : {1, 2, 3, 9, 10, 11}) EXPECT_GT(norm(smooth.positions[v] - box.positions[v]), 1e-3) << v;
}

TEST(QuasiFourEight, VertexChannelsFollowPositions) {
  PolygonMesh mesh = bumpy_ngon();
  VertexChannel xyz{"xyz", 3, {}};
  for (const Vec3& p : mesh.positions) xyz.values.insert(xyz.values.end(), {p.x, p.y, p.z});
  mesh.vertex_channels.push_back(xyz);
  const PolygonMesh out = refine(mesh, quasi_4_8_scheme(), steps(3));
  ASSERT_EQ(out.vertex_channels.size(), 1u);
  for (Index v = 0; v < out.vertex_count(); ++v) {
    const double* c = out.vertex_channels[0].values.data() + 3 * v;
    EXPECT_LT(norm(Vec3{c[0], c[1], c[2]} - out.positions[v]), 1e-14);
  }
}

TEST(QuasiFourEight, RefusesWhatItHasNoRulesFor) {
  EXPECT_THROW(refine(test::four_eight_grid(1), quasi_4_8_scheme(), steps(-1)), InvalidInputError);
  PolygonMesh quad = make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
  EXPECT_THROW(refine(quad, quasi_4_8_scheme(), steps(1)), InvalidInputError);
  PolygonMesh holed = ngon_fan(5);
  holed.tags.holes.push_back(0);
  EXPECT_THROW(refine(holed, quasi_4_8_scheme(), steps(1)), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
