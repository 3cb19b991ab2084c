#include "subdiv/rules/doo_sabin.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "subdiv/analysis/analyze.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "support/bsplines.h"
#include "support/stencil_rows.h"
#include "support/refine_options.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

constexpr double kPi = std::numbers::pi;

using test::levels;

// One k-gon, vertices on the unit circle.
PolygonMesh polygon(int k) {
  PolygonMesh mesh;
  std::vector<Index> face;
  for (int i = 0; i < k; ++i) {
    mesh.positions.push_back({std::cos(2 * kPi * i / k), std::sin(2 * kPi * i / k), 0.0});
    face.push_back(i);
  }
  mesh.add_face(face);
  return mesh;
}

TEST(DooSabin, WeightsGolden) {
  // k = 4: the biquadratic B-spline's tensor-product Chaikin mask.
  const double quad[] = {9.0 / 16, 3.0 / 16, 1.0 / 16, 3.0 / 16};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(doo_sabin_weight(4, i), quad[i], 1e-16) << i;
  // k = 3: 1/4 + 5/12 = 2/3; (3 + 2 cos 120) / 12 = 1/6.
  EXPECT_NEAR(doo_sabin_weight(3, 0), 2.0 / 3, 2e-16);
  EXPECT_NEAR(doo_sabin_weight(3, 1), 1.0 / 6, 2e-16);
  EXPECT_NEAR(doo_sabin_weight(3, 2), 1.0 / 6, 2e-16);
  for (int k = 3; k <= 24; ++k) {
    double sum = 0.0;
    for (int i = 0; i < k; ++i) {
      sum += doo_sabin_weight(k, i);
      EXPECT_NEAR(doo_sabin_weight(k, i), doo_sabin_weight(k, (k - i) % k), 1e-15) << k << " " << i;
    }
    EXPECT_NEAR(sum, 1.0, 1e-15) << k;
  }
}

// The map from a face's vertices to its child face's corners, read off the
// recorded stencils of a real refinement, is circulant; its eigenvalues are
// the mask's discrete Fourier transform: 1, then 1/2 twice, then 1/4 for
// every other frequency, whatever k (the survey, section 5, and Doo and
// Sabin 1978). Computed here with a dense eigensolver, not from the formula.
TEST(DooSabin, FaceSpectrumIsTheMasksFourierTransform) {
  for (int k = 3; k <= 16; ++k) {
    const PolygonMesh mesh = polygon(k);
    const std::vector<StencilTable> tables = refine_stencils(mesh, doo_sabin_scheme(), levels(1));
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(k, k);
    for (int i = 0; i < k; ++i)  // child vertex i = the corner point of corner i
      for (const auto& [v, w] : test::merged_row(tables[0], i)) S(i, v) += w;
    Eigen::VectorXd eigenvalues = Eigen::EigenSolver<Eigen::MatrixXd>(S).eigenvalues().real();
    std::sort(eigenvalues.begin(), eigenvalues.end(), std::greater<>());
    EXPECT_NEAR(eigenvalues[0], 1.0, 1e-13) << k;
    EXPECT_NEAR(eigenvalues[1], 0.5, 1e-13) << k;
    EXPECT_NEAR(eigenvalues[2], 0.5, 1e-13) << k;
    for (int i = 3; i < k; ++i) EXPECT_NEAR(eigenvalues[i], 0.25, 1e-13) << k << " " << i;
  }
}

TEST(DooSabin, StencilRowsSumToOneAndTheFastPathAgrees) {
  PolygonMesh mesh = test::quad_grid(3, 2);
  mesh.add_face({1, 0, 12});  // a triangle and a pentagon on the boundary
  mesh.positions.push_back({0.5, -1.0, 0.3});
  mesh.positions.push_back({4.0, 0.0, 0.2});
  mesh.positions.push_back({4.0, 2.5, -0.1});
  mesh.add_face({11, 7, 3, 13, 14});
  mesh.positions[5].z = 0.4;
  const std::vector<StencilTable> tables = refine_stencils(mesh, doo_sabin_scheme(), levels(2));
  for (const StencilTable& table : tables)
    for (Index r = 0; r < table.row_count(); ++r) {
      double sum = 0.0;
      for (const auto& [v, w] : test::merged_row(table, r)) sum += w;
      EXPECT_NEAR(sum, 1.0, 1e-15) << r;
    }
  const PolygonMesh fast = refine(mesh, doo_sabin_scheme(), levels(2));
  std::vector<Vec3> level1(static_cast<std::size_t>(tables[0].row_count())), level2;
  tables[0].apply(mesh.positions, level1);
  level2.resize(static_cast<std::size_t>(tables[1].row_count()));
  tables[1].apply(level1, level2);
  ASSERT_EQ(level2.size(), fast.positions.size());
  for (std::size_t i = 0; i < level2.size(); ++i) EXPECT_NEAR(norm(level2[i] - fast.positions[i]), 0.0, 1e-14) << i;
}

// Child counts: a vertex per corner and two per boundary edge; a face per
// face, edge and vertex. Every child vertex has valence 4 (3 on the
// boundary), the child is valid and consistently oriented, and the Euler
// characteristic is kept.
TEST(DooSabin, DualSplitTopology) {
  for (const PolygonMesh& mesh : {test::cube(), test::tetrahedron(), test::quad_grid(3, 2), polygon(5)}) {
    const MeshTopology t(mesh);
    Index boundary_edges = 0;
    for (Index e = 0; e < t.edge_count(); ++e) boundary_edges += t.is_boundary_edge(e);
    const PolygonMesh child = refine(mesh, doo_sabin_scheme(), levels(1));
    EXPECT_EQ(child.vertex_count(), mesh.corner_count() + 2 * boundary_edges);
    EXPECT_EQ(child.face_count(), mesh.face_count() + t.edge_count() + mesh.vertex_count());
    const MeshTopology ct(child);
    EXPECT_TRUE(validate(child, ct).ok());
    for (Index v = 0; v < ct.vertex_count(); ++v)
      EXPECT_EQ(ct.valence(v), ct.vertex_kind(v) == VertexKind::boundary ? 3 : 4) << v;
    EXPECT_EQ(child.vertex_count() - ct.edge_count() + child.face_count(),
              mesh.vertex_count() - t.edge_count() + mesh.face_count());
  }
}

// The biquadratic spline with control points at the mesh's (x, y) lattice of
// spacing h and heights z, at (u, v).
double biquadratic(const PolygonMesh& net, double h, double u, double v) {
  double s = 0.0;
  for (const Vec3& p : net.positions) s += p.z * test::quadratic_bspline((u - p.x) / h) * test::quadratic_bspline((v - p.y) / h);
  return s;
}

// On a regular grid Doo-Sabin is the biquadratic B-spline: each step is
// knot insertion, so the refined control net (whose x, y are its own lattice,
// by linear precision) defines the same spline as the coarse one. The spline
// is evaluated independently from its basis functions.
TEST(DooSabin, RegularGridReproducesTheBiquadraticBSpline) {
  PolygonMesh net = test::quad_grid(10, 10);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> height(-1.0, 1.0);
  for (Vec3& p : net.positions) p.z = height(random);
  const PolygonMesh refined = refine(net, doo_sabin_scheme(), levels(3));
  const double h = 1.0 / 8;
  // Child lattice: spacing h, offset h/2 from the coarse lattice, away from
  // the boundary (whose points follow the boundary curve).
  for (const Vec3& p : refined.positions) {
    if (std::min({p.x, p.y, 10.0 - p.x, 10.0 - p.y}) < 1.5) continue;
    const double i = (p.x - h / 2) / h, j = (p.y - h / 2) / h;
    ASSERT_NEAR(i, std::round(i), 1e-12);
    ASSERT_NEAR(j, std::round(j), 1e-12);
  }
  double worst = 0.0;
  std::uniform_real_distribution<double> inside(3.0, 7.0);  // away from the boundary rules' reach
  for (int n = 0; n < 200; ++n) {
    const double u = inside(random), v = inside(random);
    worst = std::max(worst, std::fabs(biquadratic(refined, h, u, v) - biquadratic(net, 1.0, u, v)));
  }
  EXPECT_LT(worst, 1e-13);
}

// Chaikin's corner cutting of a closed polygon, written out here.
std::vector<Vec3> chaikin(const std::vector<Vec3>& polygon) {
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[(i + 1) % polygon.size()];
    out.push_back(0.75 * a + 0.25 * b);
    out.push_back(0.25 * a + 0.75 * b);
  }
  return out;
}

// The boundary of the child is Chaikin's refinement of the parent's boundary
// polygon, level after level, so the boundary limit is its quadratic
// B-spline; the interior does not reach it.
TEST(DooSabin, BoundaryIsChaikinsCurve) {
  const PolygonMesh mesh = test::with_random_heights(test::quad_grid(3, 3), 3);
  std::vector<Vec3> expected;
  const MeshTopology coarse(mesh);
  for (const Index v : coarse.boundary_loops().at(0).vertices) expected.push_back(mesh.positions[v]);
  const PolygonMesh refined = refine(mesh, doo_sabin_scheme(), levels(3));
  for (int l = 0; l < 3; ++l) expected = chaikin(expected);
  const MeshTopology t(refined);
  ASSERT_EQ(t.boundary_loops().size(), 1u);
  const auto& loop = t.boundary_loops()[0].vertices;
  ASSERT_EQ(loop.size(), expected.size());
  for (const Vec3& p : expected) {  // the same polygon, compared without assuming where it starts
    double nearest = 1e300;
    for (const Index v : loop) nearest = std::min(nearest, norm(p - refined.positions[v]));
    EXPECT_LT(nearest, 1e-14);
  }
}

TEST(DooSabin, AffineInvarianceAndVertexChannels) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"heat", 1, {0, 1, 2, 3, 4, 5, 6, 7}});
  PolygonMesh moved = mesh;
  for (Vec3& p : moved.positions) p = Vec3{2 * p.x - p.y + 1, p.y + 3 * p.z, -p.z + 0.5};
  const PolygonMesh a = refine(mesh, doo_sabin_scheme(), levels(2));
  const PolygonMesh b = refine(moved, doo_sabin_scheme(), levels(2));
  for (std::size_t i = 0; i < a.positions.size(); ++i) {
    const Vec3& p = a.positions[i];
    EXPECT_NEAR(norm(Vec3{2 * p.x - p.y + 1, p.y + 3 * p.z, -p.z + 0.5} - b.positions[i]), 0.0, 1e-14);
  }
  ASSERT_EQ(a.vertex_channels.size(), 1u);
  EXPECT_EQ(a.vertex_channels[0].values.size(), a.positions.size());
}

TEST(DooSabin, RefusesSharpFeaturesWithTheirLine) {
  PolygonMesh mesh = test::cube();
  mesh.tags.creases.push_back({0, 1, 2.0});
  SourceLines lines;
  lines.path = "cube.obj";
  lines.crease_lines = {17};
  try {
    refine(mesh, doo_sabin_scheme(), levels(1), &lines);
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("cube.obj:17: doo-sabin has no crease rules"), std::string::npos) << e.what();
  }
  mesh.tags.creases.clear();
  mesh.tags.holes.push_back(2);
  EXPECT_THROW(refine(mesh, doo_sabin_scheme(), levels(1)), InvalidInputError);
}

// The analysis at an extraordinary face of k sides, read off the real
// rules: the neighbourhood of the k-gon and its ring of faces (4k vertices)
// is invariant, the spectrum leads with 1, 1/2, 1/2, 1/4, and Reif's
// criterion holds (the survey: Doo-Sabin is C1).
TEST(DooSabin, AnalysisAtExtraordinaryFacesIsC1) {
  for (int k = 3; k <= 12; ++k) {
    const ConfigurationAnalysis a = analyze(doo_sabin_scheme(), {Configuration::Kind::interior, k, CornerType::convex});
    ASSERT_TRUE(a.matrix.invariant) << k << ": " << a.matrix.invariance_note;
    EXPECT_EQ(a.matrix.rings, 1) << k;
    EXPECT_EQ(a.matrix.S.rows(), 4 * k) << k;
    ASSERT_EQ(a.leading.size(), 4u);
    const double expected[] = {1.0, 0.5, 0.5, 0.25};
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(a.leading[static_cast<std::size_t>(i)].real(), expected[i], 1e-12) << k << " " << i;
      EXPECT_NEAR(a.leading[static_cast<std::size_t>(i)].imag(), 0.0, 1e-12) << k << " " << i;
    }
    EXPECT_TRUE(a.eigenvalue_condition) << k << ": " << a.reason;
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
    // The limit mask is affine (sums to 1) and shared alike by the k-gon's
    // vertices (the rotation maps it to itself).
    ASSERT_TRUE(a.limit_mask.has_value());
    EXPECT_NEAR(a.limit_mask->sum(), 1.0, 1e-12) << k;
    for (int i = 1; i < k; ++i) EXPECT_NEAR((*a.limit_mask)[i], (*a.limit_mask)[0], 1e-12) << k << " " << i;
  }
}

// Boundary configurations have no dual layout: refused with a clear error.
TEST(DooSabin, AnalysisRefusesBoundaryFaces) {
  EXPECT_THROW(analyze(doo_sabin_scheme(), {Configuration::Kind::boundary, 3, CornerType::convex}), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
