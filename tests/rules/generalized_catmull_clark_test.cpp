// Generalized Catmull-Clark and midpoint schemes (Chen and Prautzsch 2012):
// Catmull-Clark and Doo-Sabin reproduced, M_n = A^(n-1) R against an
// independent face-centre dual, uniform B-splines of degree n on regular
// grids, the boundary behaviour, bad parameters.

#include "subdiv/rules/generalized_catmull_clark.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/doo_sabin.h"
#include "support/bsplines.h"
#include "support/gcc_schemes.h"
#include "support/refine_options.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::gcc;
using test::levels;
using test::midpoint;

// A closed n x m quad torus.
PolygonMesh torus(int n, int m) {
  PolygonMesh mesh;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      mesh.positions.push_back({(2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v) + 0.1 * i});
    }
  auto id = [&](int i, int j) { return static_cast<Index>((j % m) * n + (i % n)); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) mesh.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return mesh;
}

// A cube with one corner cut off (a triangle and three pentagons): valences 3 and faces of 3, 4, 5 sides.
PolygonMesh cut_cube() {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1},
                    {1, 0.6, 1}, {1, 1, 0.6}, {0.6, 1, 1}};
  mesh.add_face({0, 3, 2, 1});
  mesh.add_face({4, 5, 7, 9, 6});
  mesh.add_face({0, 1, 5, 4});
  mesh.add_face({1, 2, 8, 7, 5});
  mesh.add_face({2, 3, 6, 9, 8});
  mesh.add_face({3, 0, 4, 6});
  mesh.add_face({7, 8, 9});
  return mesh;
}

void expect_same_tables(const StencilTable& a, const StencilTable& b, double tolerance) {
  ASSERT_EQ(a.row_count(), b.row_count());
  ASSERT_EQ(a.source_count(), b.source_count());
  for (Index r = 0; r < a.row_count(); ++r) {
    const auto ra = test::merged_row(a, r), rb = test::merged_row(b, r);
    for (Index v = 0; v < a.source_count(); ++v) {
      const double wa = ra.contains(v) ? ra.at(v) : 0.0, wb = rb.contains(v) ? rb.at(v) : 0.0;
      ASSERT_NEAR(wa, wb, tolerance) << "row " << r << " vertex " << v;
    }
  }
}

// The paper's A on a closed mesh, written independently of the engine:
// a vertex per face (its centroid), a face per vertex (its faces in ring order).
PolygonMesh face_centre_dual(const PolygonMesh& mesh) {
  const MeshTopology t(mesh);
  PolygonMesh out;
  for (Index f = 0; f < t.face_count(); ++f) {
    Vec3 c;
    for (const Index v : t.face_vertices(f)) c += mesh.positions[static_cast<std::size_t>(v)];
    out.positions.push_back((1.0 / t.face_size(f)) * c);
  }
  for (Index v = 0; v < t.vertex_count(); ++v) {
    std::vector<Index> face;
    for (const Index c : t.vertex_corners(v)) face.push_back(t.corner_face(c));
    out.add_face(face);
  }
  return out;
}

TEST(GeneralizedCatmullClark, DefaultIsCatmullClarkOnQuadMeshes) {
  // M_3-bar with alpha(m) = 1 - 3/m, beta(m) = 2/m (alpha(4) = 1/4, beta(4) = 1/2):
  // the stencils of our Catmull-Clark, two levels, valences 3, 4 and 5.
  for (const PolygonMesh& mesh : {test::cube(), torus(5, 4)}) {
    const StencilTable a = refine_stencil_table(mesh, generalized_catmull_clark_scheme(), levels(2));
    const StencilTable b = refine_stencil_table(mesh, catmull_clark_scheme(), levels(2));
    expect_same_tables(a, b, 1e-14);
  }
  // The same from per-valence values: constant 1/4, 1/2, and Catmull-Clark's at valence 3.
  Scheme listed = gcc(3, 0.25, 0.5);
  std::get<DegreeParameters>(listed.parameters).smoothing[0].valences = {{3, 0.0, 2.0 / 3.0}};
  expect_same_tables(refine_stencil_table(test::cube(), listed, levels(2)),
                     refine_stencil_table(test::cube(), catmull_clark_scheme(), levels(2)), 1e-14);
}

TEST(GeneralizedCatmullClark, VertexPointsAreCatmullClarksOnAnyMesh) {
  // Next to non-quads B R differs from Catmull-Clark at edge points (its
  // face centres are smoothed as vertices of R's mesh), but its old vertices
  // and face centres are Catmull-Clark's: alpha(m) = 1 - 3/m keeps a face
  // centre of any size at the centroid.
  const PolygonMesh mesh = cut_cube();
  const StencilTable a = refine_stencil_table(mesh, generalized_catmull_clark_scheme(), levels(1));
  const StencilTable b = refine_stencil_table(mesh, catmull_clark_scheme(), levels(1));
  const MeshTopology t(mesh);
  const Index nf = t.face_count(), ne = t.edge_count();
  for (Index r = 0; r < a.row_count(); ++r) {
    if (r >= nf && r < nf + ne) continue;  // edge points
    const auto ra = test::merged_row(a, r), rb = test::merged_row(b, r);
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      EXPECT_NEAR(ra.contains(v) ? ra.at(v) : 0.0, rb.contains(v) ? rb.at(v) : 0.0, 1e-14) << r << " " << v;
  }
}

TEST(GeneralizedCatmullClark, MidpointDegreeTwoIsDooSabinOnQuadMeshes) {
  // One level on the cube and the grid (their child meshes have triangles,
  // at the cube's vertices and the grid's corners), two on the torus.
  for (const auto& [mesh, n] : {std::pair{test::cube(), 1}, {test::quad_grid(4, 3), 1}, {torus(5, 4), 2}}) {
    const StencilTable a = refine_stencil_table(mesh, midpoint(2), levels(n));
    const StencilTable b = refine_stencil_table(mesh, doo_sabin_scheme(), levels(n));
    expect_same_tables(a, b, 1e-14);
  }
}

TEST(GeneralizedCatmullClark, MidpointDegreeThreeGoldenWeights) {
  // M_3 = B_{1/4,1/2} R is Catmull-Clark-type with alpha~ = 1/4 + 1/4 + 1/16
  // = 9/16, beta~ = 1/4 + 1/8 = 3/8, gamma~ = 1/16 at every valence: at a
  // cube corner (m = 3) 9/16 on the vertex, 1/8 on each neighbour, 1/48 on
  // each opposite vertex.
  const PolygonMesh cube = test::cube();
  const MeshTopology t(cube);
  const StencilTable table = refine_stencil_table(cube, midpoint(3), levels(1));
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const auto row = test::merged_row(table, t.face_count() + t.edge_count() + v);
    EXPECT_NEAR(row.at(v), 9.0 / 16, 1e-15);
    for (const Index e : t.vertex_edges(v)) EXPECT_NEAR(row.at(t.other_vertex(e, v)), 1.0 / 8, 1e-15);
    for (const Index c : t.vertex_corners(v))
      EXPECT_NEAR(row.at(t.corner_vertex(t.corner_next(t.corner_next(c)))), 1.0 / 48, 1e-15);
    EXPECT_EQ(row.size(), 7u);
  }
}

TEST(GeneralizedCatmullClark, VertexChannelsFollowThePositions) {
  // Every step carries vertex channels through the same masks.
  PolygonMesh mesh = cut_cube();
  VertexChannel copy{"copy", 3, {}};
  for (const Vec3& p : mesh.positions) copy.values.insert(copy.values.end(), {p.x, p.y, p.z});
  mesh.vertex_channels.push_back(copy);
  for (int n = 2; n <= 5; ++n) {
    const PolygonMesh fine = refine(mesh, gcc(n, 0.3, 0.4), levels(2));
    ASSERT_EQ(fine.vertex_channels.size(), 1u);
    for (Index v = 0; v < fine.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(fine.vertex_channels[0].values[3 * static_cast<std::size_t>(v) + static_cast<std::size_t>(c)],
                    c == 0 ? fine.positions[static_cast<std::size_t>(v)].x
                    : c == 1 ? fine.positions[static_cast<std::size_t>(v)].y
                             : fine.positions[static_cast<std::size_t>(v)].z,
                    1e-14);
  }
}

TEST(GeneralizedCatmullClark, MidpointIsRepeatedAveraging) {
  // M_n = A^(n-1) R on any closed mesh: B_{1/4,1/2} = A^2 at every valence.
  for (const PolygonMesh& mesh : {test::cube(), cut_cube(), test::tetrahedron()}) {
    PolygonMesh expected = refine(mesh, bilinear_scheme(), levels(1));
    for (int n = 2; n <= 6; ++n) {
      expected = face_centre_dual(expected);
      const PolygonMesh got = refine(mesh, midpoint(n), levels(1));
      ASSERT_EQ(got.vertex_count(), expected.vertex_count()) << "n = " << n;
      for (Index v = 0; v < got.vertex_count(); ++v)
        EXPECT_LT(norm(got.positions[static_cast<std::size_t>(v)] - expected.positions[static_cast<std::size_t>(v)]),
                  1e-14)
            << "n = " << n << " vertex " << v;
    }
  }
}

TEST(GeneralizedCatmullClark, MidpointReproducesUniformBSplines) {
  // On a regular grid M_n is the tensor-product B-spline of degree n: the
  // function sum_p z_p B_n(2^L (x - x_p)) B_n(2^L (y - y_p)) over the
  // level-L control points p is the same at every level (interior points
  // sit on the refined grid by linear precision; those the boundary
  // touched lie near it, outside the supports sampled here).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  PolygonMesh grid = test::quad_grid(16, 16);
  for (Vec3& p : grid.positions) p.z = unit(random);
  auto spline = [](const PolygonMesh& mesh, int n, int level, double x, double y) {
    const double s = std::ldexp(1.0, level);
    double sum = 0.0;
    for (const Vec3& p : mesh.positions)
      sum += p.z * test::centred_bspline(n, s * (x - p.x)) * test::centred_bspline(n, s * (y - p.y));
    return sum;
  };
  for (int n = 2; n <= 6; ++n) {
    const PolygonMesh fine = refine(grid, midpoint(n), levels(2));
    for (double x = 7.0; x <= 9.0; x += 0.37)
      for (double y = 7.1; y <= 9.0; y += 0.41)
        EXPECT_NEAR(spline(fine, n, 2, x, y), spline(grid, n, 0, x, y), 1e-12) << "n = " << n << " at " << x << ", " << y;
  }
  // The B-spline formula against the closed forms it generalises.
  for (double x = -2.5; x <= 2.5; x += 0.1) {
    EXPECT_NEAR(test::centred_bspline(2, x), test::quadratic_bspline(x), 1e-14);
    EXPECT_NEAR(test::centred_bspline(3, x), test::cubic_bspline(x), 1e-14);
  }
}

TEST(GeneralizedCatmullClark, DegreesTwoToNineRefine) {
  const PolygonMesh mesh = cut_cube();
  const MeshTopology t(mesh);
  for (int n = 2; n <= 9; ++n) {
    for (const Scheme& scheme : {midpoint(n), gcc(n, 0.3, 0.4)}) {
      std::vector<StencilTable> tables;
      PolygonMesh evaluated;
      tables = refine_stencils(mesh, scheme, levels(2), &evaluated);
      const PolygonMesh fast = refine(mesh, scheme, levels(2));
      // One level: the quad split's counts for odd n, the dual split's for even n.
      const PolygonMesh one = refine(mesh, scheme, levels(1));
      if (n % 2 == 1) {
        EXPECT_EQ(one.vertex_count(), t.face_count() + t.edge_count() + t.vertex_count());
        EXPECT_EQ(one.face_count(), t.corner_count());
      } else {
        EXPECT_EQ(one.vertex_count(), t.corner_count());
        EXPECT_EQ(one.face_count(), t.face_count() + t.edge_count() + t.vertex_count());
      }
      ASSERT_EQ(fast.vertex_count(), evaluated.vertex_count());
      for (Index v = 0; v < fast.vertex_count(); ++v)
        EXPECT_LT(norm(fast.positions[static_cast<std::size_t>(v)] - evaluated.positions[static_cast<std::size_t>(v)]),
                  1e-13);
      // Affine invariance: every row sums to 1, weights are convex.
      for (const StencilTable& table : tables)
        for (Index r = 0; r < table.row_count(); ++r) {
          double sum = 0.0;
          for (const double w : table.row_weights(r)) {
            sum += w;
            EXPECT_GE(w, 0.0);
          }
          EXPECT_NEAR(sum, 1.0, 1e-14) << "n = " << n << " row " << r;
        }
    }
  }
}

TEST(GeneralizedCatmullClark, PerStepWeights) {
  // B_2 B_1 R with two different operators: the same as applying them one by one.
  Scheme two = generalized_catmull_clark_scheme();
  set_degree(two, 5);
  SmoothingWeights b1, b2;
  b1.alpha = 0.1, b1.beta = 0.6;
  b2.alpha = 0.4, b2.beta = 0.35;  // gamma = 0.25: edge and opposite weights differ
  std::get<DegreeParameters>(two.parameters).smoothing = {b1, b2};
  const PolygonMesh got = refine(test::cube(), two, levels(1));
  Scheme first = gcc(3, 0.1, 0.6);
  const PolygonMesh after_first = refine(test::cube(), first, levels(1));
  // B_2 applied by hand to B_1 R of the cube, the Figure 1.3 weights.
  const MeshTopology t(after_first);
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const int m = t.valence(v);
    Vec3 expected = b2.alpha * after_first.positions[static_cast<std::size_t>(v)];
    for (const Index e : t.vertex_edges(v))
      expected += (b2.beta / m) * after_first.positions[static_cast<std::size_t>(t.other_vertex(e, v))];
    for (const Index c : t.vertex_corners(v))
      expected += ((1.0 - b2.alpha - b2.beta) / m) *
                  after_first.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(t.corner_next(c))))];
    EXPECT_LT(norm(got.positions[static_cast<std::size_t>(v)] - expected), 1e-14) << v;
  }
  // The order matters: B_1 B_2 R is another mesh.
  std::get<DegreeParameters>(two.parameters).smoothing = {b2, b1};
  const PolygonMesh swapped = refine(test::cube(), two, levels(1));
  double largest = 0.0;
  for (Index v = 0; v < got.vertex_count(); ++v)
    largest = std::max(largest, norm(got.positions[static_cast<std::size_t>(v)] - swapped.positions[static_cast<std::size_t>(v)]));
  EXPECT_GT(largest, 1e-3);
}

TEST(GeneralizedCatmullClark, OddDegreesKeepTheBoundaryPolygon) {
  // Boundary vertices are not smoothed and R puts edge midpoints: every
  // boundary vertex of every level lies on the control mesh's outline.
  const PolygonMesh grid = test::quad_grid(4, 3);
  for (int n : {3, 5, 7}) {
    const PolygonMesh fine = refine(grid, gcc(n, 0.2, 0.5), levels(3));
    const MeshTopology t(fine);
    int boundary = 0;
    for (Index v = 0; v < t.vertex_count(); ++v) {
      if (t.vertex_kind(v) != VertexKind::boundary) continue;
      ++boundary;
      const Vec3 p = fine.positions[static_cast<std::size_t>(v)];
      const bool on_outline = std::fabs(p.x) < 1e-14 || std::fabs(p.x - 4) < 1e-14 || std::fabs(p.y) < 1e-14 ||
                              std::fabs(p.y - 3) < 1e-14;
      EXPECT_TRUE(on_outline) << "n = " << n << ": " << p.x << ", " << p.y;
    }
    EXPECT_EQ(boundary, 2 * (4 + 3) * 8);
  }
}

TEST(GeneralizedCatmullClark, EvenDegreesCutTheBoundaryByChaikin) {
  // The boundary points of A are 3/4 a + 1/4 b on every boundary edge (a, b):
  // after one level the outline is the Chaikin polygon of the control outline.
  PolygonMesh grid = test::quad_grid(3, 2);
  for (Vec3& p : grid.positions) p.z = p.x * p.y;
  const MeshTopology t(grid);
  for (int n : {2, 4, 6}) {
    const PolygonMesh fine = refine(grid, gcc(n, 0.3, 0.3), levels(1));
    const MeshTopology ft(fine);
    std::vector<Vec3> expected;
    for (Index e = 0; e < t.edge_count(); ++e) {
      if (!t.is_boundary_edge(e)) continue;
      const auto [a, b] = t.edge_vertices(e);
      const Vec3 pa = grid.positions[static_cast<std::size_t>(a)], pb = grid.positions[static_cast<std::size_t>(b)];
      expected.push_back(0.75 * pa + 0.25 * pb);
      expected.push_back(0.25 * pa + 0.75 * pb);
    }
    int boundary = 0;
    for (Index v = 0; v < ft.vertex_count(); ++v) {
      if (ft.vertex_kind(v) != VertexKind::boundary) continue;
      ++boundary;
      double nearest = 1e9;
      for (const Vec3& q : expected) nearest = std::min(nearest, norm(fine.positions[static_cast<std::size_t>(v)] - q));
      EXPECT_LT(nearest, 1e-14) << "n = " << n << " vertex " << v;
    }
    EXPECT_EQ(boundary, static_cast<int>(expected.size()));
  }
}

TEST(GeneralizedCatmullClark, BadParametersAreRefused) {
  const PolygonMesh cube = test::cube();
  Scheme s = midpoint_scheme();
  EXPECT_THROW(set_degree(s, 1), InvalidInputError);
  Scheme cc = catmull_clark_scheme();
  EXPECT_THROW(set_degree(cc, 3), InvalidInputError);
  EXPECT_THROW(refine(cube, gcc(3, 0.6, 0.5), levels(1)), InvalidInputError);   // alpha + beta > 1
  EXPECT_THROW(refine(cube, gcc(3, -0.1, 0.5), levels(1)), InvalidInputError);  // alpha < 0
  Scheme three = gcc(7, 0.25, 0.5);
  std::get<DegreeParameters>(three.parameters).smoothing.push_back(std::get<DegreeParameters>(three.parameters).smoothing[0]);  // 2 sets for r = 3
  EXPECT_THROW(refine(cube, three, levels(1)), InvalidInputError);
  Scheme mismatched = midpoint_scheme();
  std::get<DegreeParameters>(mismatched.parameters).degree = 4;  // without set_degree: the split still says quad
  EXPECT_THROW(refine(cube, mismatched, levels(1)), InvalidInputError);
  PolygonMesh creased = cube;
  creased.tags.creases.push_back({0, 1, 2.0});
  EXPECT_THROW(refine(creased, midpoint(3), levels(1)), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
