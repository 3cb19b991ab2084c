#include "subdiv/rules/four_eight.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "subdiv/analysis/analyze.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "support/refine_options.h"
#include "support/stencil_checks.h"
#include "support/stencil_rows.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::levels;

// The dyadic mask of the four-direction box spline with every direction
// doubled, from its symbol 4 prod_d ((1 + z^d) / 2)^2 over d = (1,0), (0,1),
// (1,1), (1,-1) (fine-lattice units), centred: a(g) weights coarse point alpha
// in the fine point q (coarse units) with g = 2 q - 2 alpha.
std::map<std::pair<int, int>, double> box_spline_mask() {
  std::map<std::pair<int, int>, double> p{{{0, 0}, 4.0}};
  const int directions[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  for (const auto& d : directions)
    for (int twice = 0; twice < 2; ++twice) {
      std::map<std::pair<int, int>, double> next;
      for (const auto& [g, w] : p) {
        next[g] += 0.5 * w;
        next[{g.first + d[0], g.second + d[1]}] += 0.5 * w;
      }
      p = std::move(next);
    }
  std::map<std::pair<int, int>, double> centred;  // the centre is the sum of the directions, (3, 1)
  for (const auto& [g, w] : p) centred[{g.first - 3, g.second - 1}] = w;
  return centred;
}

Scheme open_four_eight() {
  Scheme s = four_eight_scheme();
  s.traits.needs_closed_mesh = false;
  return s;
}

TEST(FourEight, SplitMakesAQuadPerEdge) {
  const PolygonMesh cube = test::cube();
  const MeshTopology t(cube);
  const PolygonMesh child = refine(cube, four_eight_scheme(), levels(1));
  EXPECT_EQ(child.vertex_count(), cube.vertex_count() + cube.face_count());
  EXPECT_EQ(child.face_count(), t.edge_count());
  const MeshTopology ct(child);
  EXPECT_TRUE(validate(child, ct).ok());
  for (Index f = 0; f < child.face_count(); ++f) EXPECT_EQ(child.face_size(f), 4);
  for (Index f = 0; f < cube.face_count(); ++f) EXPECT_EQ(ct.valence(f), 4);  // face points
  for (Index v = 0; v < cube.vertex_count(); ++v) EXPECT_EQ(ct.valence(cube.face_count() + v), t.valence(v));
  // Two steps: the quad split's topology (V + E + F vertices, 4F faces).
  const PolygonMesh twice = refine(cube, four_eight_scheme(), levels(2));
  EXPECT_EQ(twice.vertex_count(), cube.vertex_count() + t.edge_count() + cube.face_count());
  EXPECT_EQ(twice.face_count(), 4 * cube.face_count());
}

// Golden weights: face point 1/4 each; vertex point 1/2 and 1/(2k).
TEST(FourEight, WeightsGolden) {
  const PolygonMesh cube = test::cube();
  const StencilTable table = refine_stencil_table(cube, four_eight_scheme(), levels(1));
  for (Index f = 0; f < cube.face_count(); ++f) {
    const auto row = test::merged_row(table, f);
    ASSERT_EQ(row.size(), 4u);
    for (const Index v : cube.face(f)) EXPECT_EQ(row.at(v), 0.25);
  }
  const MeshTopology t(cube);
  for (Index v = 0; v < cube.vertex_count(); ++v) {
    const auto row = test::merged_row(table, cube.face_count() + v);
    ASSERT_EQ(row.size(), 4u);  // valence 3
    EXPECT_EQ(row.at(v), 0.5);
    for (const Index e : t.vertex_edges(v)) EXPECT_NEAR(row.at(t.other_vertex(e, v)), 1.0 / 6.0, 1e-15);
  }
}

// Independent route: two steps on a regular quad grid are one dyadic step of
// the doubled four-direction box spline (C4), compared with its mask
// computed from the symbol.
TEST(FourEight, TwoStepsOnARegularGridAreTheC4BoxSpline) {
  const int n = 14;
  const PolygonMesh grid = test::with_random_heights(test::quad_grid(n, n), 3);
  const PolygonMesh twice = refine(grid, open_four_eight(), levels(2));
  const auto mask = box_spline_mask();
  double sum = 0.0;
  for (const auto& [g, w] : mask) sum += w;
  EXPECT_NEAR(sum, 4.0, 1e-14);
  int checked = 0;
  for (const Vec3& q : twice.positions) {
    if (q.x < 5 || q.x > n - 5 || q.y < 5 || q.y > n - 5) continue;  // away from the grid's boundary
    const int qi = static_cast<int>(std::lround(2 * q.x)), qj = static_cast<int>(std::lround(2 * q.y));
    ASSERT_NEAR(q.x, 0.5 * qi, 1e-12);  // linear functions are reproduced
    ASSERT_NEAR(q.y, 0.5 * qj, 1e-12);
    double expected = 0.0;
    for (Index v = 0; v < grid.vertex_count(); ++v) {
      const int ai = static_cast<int>(std::lround(grid.positions[v].x)), aj = static_cast<int>(std::lround(grid.positions[v].y));
      const auto it = mask.find({qi - 2 * ai, qj - 2 * aj});
      if (it != mask.end()) expected += it->second * grid.positions[v].z;
    }
    EXPECT_NEAR(q.z, expected, 1e-13) << q.x << " " << q.y;
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// Stencil rows sum to one, the fast path agrees with the stencils, and
// refinement commutes with affine maps.
TEST(FourEight, RowsSumToOneAndAffineInvariance) {
  const PolygonMesh mesh = test::jittered(test::cube(), 5);
  test::expect_stencils_are_the_fast_path(mesh, four_eight_scheme(), 3, 1e-14);
  test::expect_refinement_commutes_with_an_affine_map(mesh, four_eight_scheme(), 3, 1e-12);
}

// The analysis over two steps (period 2). Regular (k = 4): the matrix is the
// box spline's, entry for entry (S(a, b) = a(p_a - 2 p_b) on the layout
// points), with subdominant eigenvalue 1/2; C1 at valences 3..12.
TEST(FourEight, AnalysisRegularIsTheBoxSplineAndC1Elsewhere) {
  const ConfigurationAnalysis regular = analyze(four_eight_scheme(), {Configuration::Kind::interior, 4, CornerType::convex});
  ASSERT_TRUE(regular.matrix.invariant) << regular.matrix.invariance_note;
  const auto mask = box_spline_mask();
  const LocalSubdivisionMatrix& m = regular.wide_matrix;
  for (Eigen::Index a = 0; a < m.S.rows(); ++a)
    for (Eigen::Index b = 0; b < m.S.cols(); ++b) {
      const Vec3 pa = m.layout[static_cast<std::size_t>(a)], pb = m.layout[static_cast<std::size_t>(b)];
      const auto it = mask.find({static_cast<int>(std::lround(pa.x - 2 * pb.x)), static_cast<int>(std::lround(pa.y - 2 * pb.y))});
      EXPECT_NEAR(m.S(a, b), it == mask.end() ? 0.0 : it->second, 1e-14) << a << " " << b;
    }
  EXPECT_NEAR(regular.leading[1].real(), 0.5, 1e-12);
  EXPECT_NEAR(regular.leading[2].real(), 0.5, 1e-12);
  EXPECT_NEAR(std::abs(regular.leading[3]), 0.25, 1e-12);
  for (int k = 3; k <= 12; ++k) {
    const ConfigurationAnalysis a = analyze(four_eight_scheme(), {Configuration::Kind::interior, k, CornerType::convex});
    ASSERT_TRUE(a.matrix.invariant) << k;
    EXPECT_EQ(a.matrix.period, 2);
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << k << ": " << a.reason;
  }
}

// Four-eight one sqrt2 step at a time, never two at once.
Scheme single_steps() {
  Scheme s = four_eight_scheme();
  s.fast_path.two_steps = nullptr;
  return s;
}

// A closed mesh with pentagons and quads (valence 3 everywhere).
PolygonMesh pentagonal_prism() {
  std::vector<Vec3> points;
  for (const double z : {0.0, 1.0})
    for (int i = 0; i < 5; ++i)
      points.push_back({std::cos(2 * std::numbers::pi * i / 5), std::sin(2 * std::numbers::pi * i / 5), z});
  std::vector<std::vector<Index>> faces = {{0, 4, 3, 2, 1}, {5, 6, 7, 8, 9}};
  for (Index i = 0; i < 5; ++i) faces.push_back({i, (i + 1) % 5, 5 + (i + 1) % 5, 5 + i});
  return make_mesh(points, faces);
}

PolygonMesh spot() { return read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh; }

// Closed meshes without face-varying channels (Spot's texture coordinates
// dropped); the cube has a vertex no face uses.
std::vector<std::pair<std::string, PolygonMesh>> closed_meshes() {
  PolygonMesh untextured = spot();
  untextured.face_varying_channels.clear();
  PolygonMesh cube = test::jittered(test::cube(), 11);
  cube.positions.push_back({3.0, 2.0, 1.0});
  return {{"cube", cube},
          {"tetrahedron", test::jittered(test::tetrahedron(), 12)},
          {"pentagonal prism", test::jittered(pentagonal_prism(), 13)},
          {"spot", untextured}};
}

// The faces as cycles starting at their smallest vertex, sorted.
std::vector<std::vector<Index>> face_cycles(const PolygonMesh& mesh, const std::vector<Index>& relabel) {
  std::vector<std::vector<Index>> cycles;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    std::vector<Index> c;
    for (const Index v : mesh.face(f)) c.push_back(relabel.empty() ? v : relabel[static_cast<std::size_t>(v)]);
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    cycles.push_back(std::move(c));
  }
  std::sort(cycles.begin(), cycles.end());
  return cycles;
}

// Two steps at once (the quad split, four_eight_two_steps_scheme) make the
// same surface as two single steps: the same points, renumbered from the
// steps' [edge | face | vertex points] to the quad split's [face | edge |
// vertex points], and the same faces. A vertex channel follows the
// positions.
TEST(FourEight, TwoStepsAtOnceAreTwoSingleSteps) {
  for (auto [name, mesh] : closed_meshes()) {
    VertexChannel xz{"xz", 2, {}};
    for (const Vec3& p : mesh.positions) xz.values.insert(xz.values.end(), {p.x, p.z});
    mesh.vertex_channels.push_back(xz);
    const MeshTopology t(mesh);
    const Index nf = t.face_count(), ne = t.edge_count(), nv = t.vertex_count();
    const PolygonMesh steps = refine(mesh, single_steps(), levels(2));
    const PolygonMesh once = refine(mesh, four_eight_scheme(), levels(2));
    ASSERT_EQ(once.vertex_count(), nf + ne + nv) << name;
    ASSERT_EQ(steps.vertex_count(), nf + ne + nv) << name;
    std::vector<Index> relabel(static_cast<std::size_t>(nf + ne + nv));  // steps' vertex -> once's
    for (Index e = 0; e < ne; ++e) relabel[static_cast<std::size_t>(e)] = nf + e;
    for (Index f = 0; f < nf; ++f) relabel[static_cast<std::size_t>(ne + f)] = f;
    for (Index v = 0; v < nv; ++v) relabel[static_cast<std::size_t>(ne + nf + v)] = nf + ne + v;
    const double size = norm(mesh.positions[0]) + 1.0;
    for (Index i = 0; i < steps.vertex_count(); ++i) {
      const auto j = static_cast<std::size_t>(relabel[static_cast<std::size_t>(i)]);
      const Vec3 p = once.positions[j];
      EXPECT_NEAR(norm(steps.positions[static_cast<std::size_t>(i)] - p), 0.0, 1e-14 * size) << name << " " << i;
      EXPECT_NEAR(once.vertex_channels[0].values[2 * j], p.x, 1e-14 * size) << name << " " << i;
      EXPECT_NEAR(once.vertex_channels[0].values[2 * j + 1], p.z, 1e-14 * size) << name << " " << i;
    }
    EXPECT_EQ(face_cycles(steps, relabel), face_cycles(once, {})) << name;
  }
}

// An odd count ends with one step, and pairs and steps reach the same
// points (compared without their order).
TEST(FourEight, OddLevelsEndWithOneStep) {
  const PolygonMesh cube = test::jittered(test::cube(), 21);
  const PolygonMesh steps = refine(cube, single_steps(), levels(5));
  const PolygonMesh mixed = refine(cube, four_eight_scheme(), levels(5));
  ASSERT_EQ(mixed.vertex_count(), steps.vertex_count());
  ASSERT_EQ(mixed.face_count(), steps.face_count());
  for (const Vec3& p : steps.positions) {
    double nearest = 1e300;
    for (const Vec3& q : mixed.positions) nearest = std::min(nearest, norm(p - q));
    EXPECT_LT(nearest, 1e-14);
  }
}

// Face-varying values follow the sqrt2 split's own rule, so a mesh that
// carries them is refined one step at a time.
TEST(FourEight, FaceVaryingChannelsKeepSingleSteps) {
  const PolygonMesh textured = spot();
  ASSERT_FALSE(textured.face_varying_channels.empty());
  const PolygonMesh steps = refine(textured, single_steps(), levels(4));
  const PolygonMesh refined = refine(textured, four_eight_scheme(), levels(4));
  EXPECT_EQ(refined.positions, steps.positions);
  EXPECT_EQ(refined.face_indices, steps.face_indices);
  EXPECT_EQ(refined.face_varying_channels[0].values, steps.face_varying_channels[0].values);
}

// The two-step masks: stencils equal the two-pass fast path, and the
// analysis of the quad-split scheme finds four-eight's own two-step spectrum
// (an independent route: four-eight's matrix composes two sqrt2 steps on
// its own ring), C1 at valences 3..12.
TEST(FourEight, TwoStepMasksAreTheFastPathAndTheTwoStepMatrix) {
  for (const auto& [name, mesh] : closed_meshes())
    test::expect_stencils_are_the_fast_path(mesh, four_eight_two_steps_scheme(), 2, 1e-14, 1e-13);
  for (int k = 3; k <= 12; ++k) {
    const Configuration c{Configuration::Kind::interior, k, CornerType::convex};
    const ConfigurationAnalysis pair = analyze(four_eight_two_steps_scheme(), c);
    const ConfigurationAnalysis steps = analyze(four_eight_scheme(), c);
    ASSERT_TRUE(pair.matrix.invariant) << k << ": " << pair.matrix.invariance_note;
    EXPECT_EQ(pair.matrix.period, 1);
    EXPECT_EQ(pair.verdict, SmoothnessVerdict::c1) << k << ": " << pair.reason;
    ASSERT_GE(pair.leading.size(), 4u);
    ASSERT_GE(steps.leading.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(std::abs(pair.leading[i]), std::abs(steps.leading[i]), 1e-12) << k << " " << i;
  }
}

TEST(FourEight, RefusesOpenMeshesAndSharpFeatures) {
  try {
    refine(test::quad_grid(2, 2), four_eight_scheme(), levels(1));
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("four-eight needs a closed mesh"), std::string::npos) << e.what();
  }
  PolygonMesh cube = test::cube();
  cube.tags.creases.push_back({0, 1, 1.0});
  EXPECT_THROW(refine(cube, four_eight_scheme(), levels(1)), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
