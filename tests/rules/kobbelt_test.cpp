#include "subdiv/rules/kobbelt.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "support/refine_options.h"
#include "support/stencil_checks.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::levels;

constexpr double kW = 1.0 / 16.0;

double four_point(double a, double b, double c, double d, double w = kW) {
  return (0.5 + w) * (b + c) - w * (a + d);
}

// One step of the four-point curve scheme on an open polyline, with the
// linear extrapolation p(-1) = 2 p(0) - p(1) at both ends.
std::vector<double> four_point_curve(const std::vector<double>& p) {
  const std::size_t m = p.size() - 1;
  auto at = [&](long i) {
    if (i < 0) return 2.0 * p[0] - p[1];
    if (i > static_cast<long>(m)) return 2.0 * p[m] - p[m - 1];
    return p[static_cast<std::size_t>(i)];
  };
  std::vector<double> out;
  for (std::size_t i = 0; i <= m; ++i) {
    out.push_back(p[i]);
    const long j = static_cast<long>(i);
    if (i < m) out.push_back(four_point(at(j - 1), at(j), at(j + 1), at(j + 2)));
  }
  return out;
}

// Heights on the (n + 1) x (m + 1) grid points refined by the tensor product
// of four_point_curve: rows first, then columns.
std::vector<std::vector<double>> tensor_four_point(const std::vector<std::vector<double>>& z) {
  std::vector<std::vector<double>> rows;
  for (const auto& row : z) rows.push_back(four_point_curve(row));  // z[j][i]
  std::vector<std::vector<double>> out(2 * z.size() - 1, std::vector<double>(rows[0].size()));
  for (std::size_t i = 0; i < rows[0].size(); ++i) {
    std::vector<double> column;
    for (const auto& row : rows) column.push_back(row[i]);
    const std::vector<double> refined = four_point_curve(column);
    for (std::size_t j = 0; j < refined.size(); ++j) out[j][i] = refined[j];
  }
  return out;
}

int half_units(double x) { return static_cast<int>(std::lround(2.0 * x)); }

TEST(Kobbelt, VirtualPointWeightsGoldenAndInvariants) {
  EXPECT_DOUBLE_EQ(kobbelt_diagonal_weight(kW), 1.0 / 9.0);
  // n = 3: (q0 + q1 + q2)/3 + (2 r1 - r0 - r2)/27 opposite q0.
  const KobbeltVirtualWeights three = kobbelt_virtual_point_weights(3, 0, kW);
  for (const double e : three.edge_neighbours) EXPECT_NEAR(e, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(three.diagonals[0], -1.0 / 27.0, 1e-15);
  EXPECT_NEAR(three.diagonals[1], 2.0 / 27.0, 1e-15);
  EXPECT_NEAR(three.diagonals[2], -1.0 / 27.0, 1e-15);
  // n = 4: the grid's opposite neighbour and nothing else.
  const KobbeltVirtualWeights four = kobbelt_virtual_point_weights(4, 1, kW);
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(four.edge_neighbours[static_cast<std::size_t>(j)], j == 3 ? 1.0 : 0.0, 1e-15) << j;
    EXPECT_NEAR(four.diagonals[static_cast<std::size_t>(j)], 0.0, 1e-15) << j;
  }
  for (int n = 3; n <= 12; ++n)
    for (int i = 0; i < n; ++i) {
      const KobbeltVirtualWeights w = kobbelt_virtual_point_weights(n, i, kW);
      const KobbeltVirtualWeights w0 = kobbelt_virtual_point_weights(n, 0, kW);
      double sum = 0.0;
      for (int j = 0; j < n; ++j) {
        const auto jj = static_cast<std::size_t>(j);
        sum += w.edge_neighbours[jj] + w.diagonals[jj];
        // Rotation: the weights turn with i.
        const auto back = static_cast<std::size_t>(((j - i) % n + n) % n);
        EXPECT_NEAR(w.edge_neighbours[jj], w0.edge_neighbours[back], 1e-15);
        EXPECT_NEAR(w.diagonals[jj], w0.diagonals[back], 1e-15);
        // Reflection about spoke i: q_j <-> q_{2i-j}, r_j <-> r_{2i-1-j}.
        const auto mirror_q = static_cast<std::size_t>(((2 * i - j) % n + n) % n);
        const auto mirror_r = static_cast<std::size_t>(((2 * i - 1 - j) % n + n) % n);
        EXPECT_NEAR(w.edge_neighbours[jj], w.edge_neighbours[mirror_q], 1e-15);
        EXPECT_NEAR(w.diagonals[jj], w.diagonals[mirror_r], 1e-15);
      }
      EXPECT_NEAR(sum, 1.0, 1e-14) << n << " " << i;
    }
}

// Golden weights on the regular grid: edge point -1/16, 9/16, 9/16, -1/16
// along its line; face point their tensor product (81/256 at the quad's
// corners, -9/256 next to them, 1/256 diagonally out).
TEST(Kobbelt, RegularGridWeightsGolden) {
  const int n = 8;
  const PolygonMesh grid = test::quad_grid(n, n);
  const MeshTopology t(grid);
  const StencilTable table = refine_stencil_table(grid, kobbelt_scheme(), levels(1));
  auto vertex_at = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  ASSERT_EQ(grid.positions[static_cast<std::size_t>(vertex_at(3, 5))].x, 3.0);
  ASSERT_EQ(grid.positions[static_cast<std::size_t>(vertex_at(3, 5))].y, 5.0);
  const double one[4] = {-1.0 / 16.0, 9.0 / 16.0, 9.0 / 16.0, -1.0 / 16.0};
  // The face with lower left corner (3, 3).
  Index face = kInvalidIndex;
  for (Index f = 0; f < grid.face_count(); ++f) {
    double x = 0.0, y = 0.0;
    for (const Index v : grid.face(f)) x += grid.positions[v].x, y += grid.positions[v].y;
    if (x == 14.0 && y == 14.0) face = f;
  }
  ASSERT_NE(face, kInvalidIndex);
  const auto face_row = test::merged_row(table, face);
  EXPECT_EQ(face_row.size(), 16u);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) EXPECT_NEAR(face_row.at(vertex_at(2 + a, 2 + b)), one[a] * one[b], 1e-15);
  const Index edge = t.find_edge(vertex_at(3, 4), vertex_at(4, 4));
  const auto edge_row = test::merged_row(table, grid.face_count() + edge);
  EXPECT_EQ(edge_row.size(), 4u);
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(edge_row.at(vertex_at(2 + a, 4)), one[a], 1e-15);
  const auto vertex_row = test::merged_row(table, grid.face_count() + t.edge_count() + vertex_at(4, 4));
  ASSERT_EQ(vertex_row.size(), 1u);
  EXPECT_EQ(vertex_row.at(vertex_at(4, 4)), 1.0);
}

// Independent route: on an open grid the scheme is the tensor product of
// four-point curves with the linear end condition, boundary and corners
// included; two levels, random heights.
TEST(Kobbelt, OpenRegularGridIsTheTensorProductOfFourPointCurves) {
  const int n = 7, m = 5;
  const PolygonMesh grid = test::with_random_heights(test::quad_grid(n, m), 11);
  std::vector<std::vector<double>> z(m + 1, std::vector<double>(n + 1));
  for (const Vec3& p : grid.positions) z[static_cast<std::size_t>(p.y)][static_cast<std::size_t>(p.x)] = p.z;
  const auto expected = tensor_four_point(tensor_four_point(z));
  const PolygonMesh twice = refine(grid, kobbelt_scheme(), levels(2));
  ASSERT_EQ(twice.positions.size(), expected.size() * expected[0].size());
  for (const Vec3& p : twice.positions) {
    const int i = half_units(2.0 * p.x), j = half_units(2.0 * p.y);  // quarter units
    ASSERT_NEAR(p.x, i / 4.0, 1e-13);  // linear functions are reproduced
    ASSERT_NEAR(p.y, j / 4.0, 1e-13);
    EXPECT_NEAR(p.z, expected[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)], 1e-13) << i << " " << j;
  }
}

// The four-point rule reproduces cubics: away from the boundary the refined
// grid samples a bicubic exactly.
TEST(Kobbelt, ReproducesBicubicsOnRegularGrids) {
  const int n = 10;
  PolygonMesh grid = test::quad_grid(n, n);
  auto f = [](double x, double y) { return 0.01 * (x * x * x - 2.0 * x * x * y * y + y * y * y * x) - 0.3 * x * y + y; };
  for (Vec3& p : grid.positions) p.z = f(p.x, p.y);
  const PolygonMesh child = refine(grid, kobbelt_scheme(), levels(1));
  int checked = 0;
  for (const Vec3& p : child.positions) {
    if (p.x < 2 || p.x > n - 2 || p.y < 2 || p.y > n - 2) continue;
    EXPECT_NEAR(p.z, f(p.x, p.y), 1e-12) << p.x << " " << p.y;
    ++checked;
  }
  EXPECT_EQ(checked, 13 * 13);  // the half-integer points of [2, 8]^2
}

// The property the virtual points are made for (kobbelt.cpp): next to an
// extraordinary vertex, inside or on the boundary (its sector of k faces),
// and at a corner, a face point is the four-point rule over new edge points
// along either pair of opposite edges, with the same result. A line that
// ends at the boundary continues as 2 E(e) - E(g).
void expect_face_points_agree(const Scheme& scheme, const Configuration& configuration, bool crease_along_x = false) {
  const double w = std::get<TensionParameters>(scheme.parameters).tension;
  const RingMesh ring = ring_mesh(SplitRule::quad, configuration, 4);
  PolygonMesh mesh = ring.mesh;
  if (crease_along_x) {  // a crease through the centre along the layout's x axis
    const MeshTopology layout(mesh);
    for (Index e = 0; e < layout.edge_count(); ++e) {
      const auto [a, b] = layout.edge_vertices(e);
      if (std::abs(mesh.positions[a].y) < 1e-9 && std::abs(mesh.positions[b].y) < 1e-9) mesh.tags.creases.push_back({a, b});
    }
  }
  std::mt19937 random(static_cast<unsigned>(configuration.k));
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (Vec3& p : mesh.positions) p += Vec3{jitter(random), jitter(random), 5.0 * jitter(random)};
  const MeshTopology t(mesh);
  const PolygonMesh child = refine(mesh, scheme, levels(1));
  auto edge_point = [&](Index e) { return child.positions[static_cast<std::size_t>(mesh.face_count() + e)]; };
  auto creased = [&](Index e) {
    const auto [a, b] = t.edge_vertices(e);
    for (const CreaseTag& tag : mesh.tags.creases)
      if ((tag.v0 == a && tag.v1 == b) || (tag.v0 == b && tag.v1 == a)) return true;
    return false;
  };
  // The new point beyond corner c's edge point on the line towards the
  // opposite edge (corner g) and away from it.
  auto beyond = [&](Index c, Index g) {
    const Index across = t.corner_across(c);
    if (across == kInvalidIndex || creased(t.corner_edge(c))) return 2.0 * edge_point(t.corner_edge(c)) - edge_point(t.corner_edge(g));
    return edge_point(t.corner_edge(t.corner_next(t.corner_next(across))));
  };
  auto line = [&](Index c, Index g) {
    const Vec3 a = beyond(c, g), b = edge_point(t.corner_edge(c)), cc = edge_point(t.corner_edge(g)), d = beyond(g, c);
    return Vec3{four_point(a.x, b.x, cc.x, d.x, w), four_point(a.y, b.y, cc.y, d.y, w),
                four_point(a.z, b.z, cc.z, d.z, w)};
  };
  ASSERT_EQ(static_cast<int>(t.vertex_corners(ring.centre).size()), configuration.k);
  for (const Index c : t.vertex_corners(ring.centre)) {
    const Index f = t.corner_face(c), first = t.face_first_corner(f);
    const Vec3 one = line(first, first + 2), other = line(first + 1, first + 3);
    EXPECT_NEAR(norm(one - other), 0.0, 1e-12) << "k " << configuration.k << " w " << w;
    EXPECT_NEAR(norm(child.positions[static_cast<std::size_t>(f)] - 0.5 * (one + other)), 0.0, 1e-12);
  }
}

TEST(Kobbelt, FacePointsNextToExtraordinaryVerticesAgreeInBothDirections) {
  for (const double w : {kW, 0.1}) {
    Scheme scheme = kobbelt_scheme();
    std::get<TensionParameters>(scheme.parameters).tension = w;
    for (const int k : {3, 5, 6, 8}) expect_face_points_agree(scheme, {Configuration::Kind::interior, k});
    for (const int k : {2, 3, 4, 6}) expect_face_points_agree(scheme, {Configuration::Kind::boundary, k});
    for (const int k : {6, 8}) expect_face_points_agree(scheme, {Configuration::Kind::interior, k}, true);
    for (const int k : {2, 3, 5})
      for (const CornerType type : {CornerType::convex, CornerType::concave})
        expect_face_points_agree(scheme, {Configuration::Kind::corner, k, type});
  }
}

TEST(Kobbelt, InterpolatesRowsSumToOneAndAffineInvariance) {
  const PolygonMesh mesh = test::jittered(test::cube(), 5);  // valence 3 everywhere
  test::expect_stencils_are_the_fast_path(mesh, kobbelt_scheme(), 3, 1e-13);
  // Old vertices stay: the control points come last at every level.
  const PolygonMesh one = refine(mesh, kobbelt_scheme(), levels(1));
  const auto first_old = static_cast<std::size_t>(one.vertex_count() - mesh.vertex_count());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) EXPECT_EQ(one.positions[first_old + v], mesh.positions[v]);
  test::expect_refinement_commutes_with_an_affine_map(mesh, kobbelt_scheme(), 3, 1e-12);
}

// A boundary (and a crease) is the four-point curve of its own polygon: the
// interior does not move it.
TEST(Kobbelt, BoundaryAndCreaseCurvesDependOnlyOnTheirPolygons) {
  const int n = 6;
  PolygonMesh grid = test::quad_grid(n, n);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> height(-1.0, 1.0);
  for (Vec3& p : grid.positions) p.z = height(random);
  for (Index i = 0; i < n; ++i) grid.tags.creases.push_back({3 * (n + 1) + i, 3 * (n + 1) + i + 1});  // the row y = 3
  PolygonMesh shaken = grid;
  for (Vec3& p : shaken.positions)
    if (p.x > 0 && p.x < n && p.y > 0 && p.y < n && p.y != 3) p.z += height(random);
  const PolygonMesh a = refine(grid, kobbelt_scheme(), levels(2)), b = refine(shaken, kobbelt_scheme(), levels(2));
  std::vector<double> crease_row;
  for (Index i = 0; i <= n; ++i) crease_row.push_back(grid.positions[static_cast<std::size_t>(3 * (n + 1) + i)].z);
  const std::vector<double> crease_curve = four_point_curve(four_point_curve(crease_row));
  int on_boundary = 0, on_crease = 0;
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    const Vec3 p = a.positions[v];
    const bool boundary = p.x == 0 || p.x == n || p.y == 0 || p.y == n;
    if (boundary || p.y == 3) {
      EXPECT_EQ(p.z, b.positions[v].z) << p.x << " " << p.y;
      on_boundary += boundary ? 1 : 0;
    }
    if (p.y == 3) {
      EXPECT_NEAR(p.z, crease_curve[static_cast<std::size_t>(half_units(2.0 * p.x))], 1e-13) << p.x;
      ++on_crease;
    }
  }
  EXPECT_EQ(on_boundary, 4 * 4 * n);
  EXPECT_EQ(on_crease, 4 * n + 1);
}

// The analysis: regular k = 4 has the tensor four-point spectrum 1, 1/2,
// 1/2, 1/4; the virtual points give C1 at the extraordinary valences, and at
// boundary sectors of 1..3 faces. From 4 faces on they do not: at 4 the
// eigenvalue 1/2 (the boundary curve's) is triple, beyond the characteristic
// map is not regular.
TEST(Kobbelt, AnalysisSpectrumAndC1) {
  const ConfigurationAnalysis regular = analyze(kobbelt_scheme(), {Configuration::Kind::interior, 4});
  ASSERT_TRUE(regular.matrix.invariant) << regular.matrix.invariance_note;
  EXPECT_NEAR(regular.leading[0].real(), 1.0, 1e-12);
  EXPECT_NEAR(regular.leading[1].real(), 0.5, 1e-12);
  EXPECT_NEAR(regular.leading[2].real(), 0.5, 1e-12);
  EXPECT_NEAR(std::abs(regular.leading[3]), 0.25, 1e-12);
  for (int k = 3; k <= 12; ++k) {
    const ConfigurationAnalysis a = analyze(kobbelt_scheme(), {Configuration::Kind::interior, k});
    ASSERT_TRUE(a.matrix.invariant) << k;
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
    ASSERT_TRUE(a.limit_mask.has_value());
    EXPECT_NEAR((*a.limit_mask)(0), 1.0, 1e-9) << k;  // interpolating: the limit is the control point
  }
  for (int k = 1; k <= 3; ++k) {
    const ConfigurationAnalysis a = analyze(kobbelt_scheme(), {Configuration::Kind::boundary, k});
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
  }
  const ConfigurationAnalysis four = analyze(kobbelt_scheme(), {Configuration::Kind::boundary, 4});
  EXPECT_FALSE(four.eigenvalue_condition);
  EXPECT_NEAR(four.leading[2].real(), 0.5, 1e-12);
  EXPECT_NEAR(std::abs(four.leading[3]), 0.5, 1e-12);
  const ConfigurationAnalysis six = analyze(kobbelt_scheme(), {Configuration::Kind::boundary, 6});
  EXPECT_NE(six.verdict, SmoothnessVerdict::c1);
}

// Limit positions are the control points; limit normals (the analysis's
// tangent masks) agree with the refined surface: the faces around each
// vertex turn towards its normal as the levels go on, on the cube
// (valence 3) and the open L (boundary, corners). Measured worst angles at
// levels 2..5: 2.2e-3 to 3.6e-4 (cube, about 0.55 a level), 2.7e-3 to
// 4.3e-5 (the L, 0.25 a level).
TEST(Kobbelt, LimitNormalsAgreeWithTheRefinedSurface) {
  PolygonMesh cube = test::cube();
  for (std::size_t i = 0; i < cube.positions.size(); ++i) cube.positions[i].z += 0.1 * static_cast<double>(i % 3);
  const PolygonMesh l_shape = read_mesh(test::bundled_path("l_shape.obj")).mesh;
  for (const PolygonMesh* mesh : {static_cast<const PolygonMesh*>(&cube), &l_shape}) {
    const LimitResult r = limit_positions(*mesh, kobbelt_scheme());
    double previous = 0.0;
    for (int levels = 2; levels <= 5; ++levels) {
      const PolygonMesh fine = refine(*mesh, kobbelt_scheme(), test::levels(levels));
      const MeshTopology t(fine);
      const Index first = fine.vertex_count() - mesh->vertex_count();
      double worst = 0.0;
      for (Index v = 0; v < mesh->vertex_count(); ++v) {
        const auto i = static_cast<std::size_t>(v);
        EXPECT_EQ(r.positions[i], mesh->positions[v]);
        if (norm(r.normals[i]) == 0.0) continue;
        Vec3 around;
        const Vec3 p = fine.positions[static_cast<std::size_t>(first + v)];
        for (const Index c : t.vertex_corners(first + v))
          around += cross(fine.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(c)))] - p,
                          fine.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_prev(c)))] - p);
        worst = std::max(worst, std::atan2(norm(cross(around, r.normals[i])), dot(around, r.normals[i])));
      }
      std::printf("  kobbelt %d vertices, %d levels: worst normal angle %.3e\n", mesh->vertex_count(), levels, worst);
      if (levels > 2) {
        EXPECT_LT(worst, 0.7 * previous) << levels << " levels";
      }
      previous = worst;
    }
    EXPECT_LT(previous, 1e-3);
  }
}

TEST(Kobbelt, RefusesMeshesWithOtherThanQuads) {
  try {
    refine(test::tetrahedron(), kobbelt_scheme(), levels(1));
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("kobbelt needs a quad mesh, but face 0 has 3 vertices"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace subdiv
