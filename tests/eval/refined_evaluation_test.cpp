// Approximate evaluation by refinement (LimitEvaluator::by_refinement)
// against independent routes: the bilinear scheme's limit written out, the
// exact evaluator of Catmull-Clark and Loop, and the vertices of deeper
// refinement of the interpolating schemes (which lie on their limit).

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "refine/grid_test_support.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/eval/tessellate.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "support/refine_options.h"
#include "support/scheme_by_name.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using grid_test::diagonal;

using test::scheme;

// Random parameters of a ptex face (triangles: u + v <= 1).
std::vector<std::array<double, 2>> parameters(bool triangles, int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::array<double, 2>> out;
  while (static_cast<int>(out.size()) < count) {
    const double u = unit(random), v = unit(random);
    if (!triangles || u + v <= 1.0) out.push_back({u, v});
  }
  return out;
}

// The bilinear scheme's limit is the control quads' bilinear interpolant:
// one level shows no change, and every point is that interpolant.
TEST(RefinedEvaluation, BilinearIsTheControlQuadsInterpolant) {
  const PolygonMesh mesh = test::jittered(test::quad_grid(3, 2), 5);
  const LimitEvaluator evaluator = LimitEvaluator::by_refinement(mesh, scheme("bilinear"), 1e-9);
  EXPECT_FALSE(evaluator.exact());
  EXPECT_EQ(evaluator.isolation_levels(), 2);  // two levels in a row without change
  EXPECT_LE(evaluator.measured_change(), 1e-15);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto q = mesh.face(f);
    const auto p = [&](int k) { return mesh.positions[static_cast<std::size_t>(q[static_cast<std::size_t>(k)])]; };
    for (const auto& [u, v] : parameters(false, 20, 7u + static_cast<unsigned>(f))) {
      const Vec3 expected = (1 - u) * (1 - v) * p(0) + u * (1 - v) * p(1) + u * v * p(2) + (1 - u) * v * p(3);
      const LimitPoint got = evaluator.evaluate(evaluator.ptex_face_of(f), u, v);
      EXPECT_LE(norm(got.position - expected), 1e-14 * diagonal(mesh));
      const Vec3 du = (1 - v) * (p(1) - p(0)) + v * (p(2) - p(3));
      EXPECT_LE(norm(got.du - du), 1e-13 * diagonal(mesh));
    }
  }
}

// Catmull-Clark and Loop by refinement against their exact evaluators, at
// random parameters of every face, on meshes with extraordinary vertices:
// within the accuracy asked for. Returns the largest normal difference.
double expect_within_accuracy_of_exact(const PolygonMesh& mesh, const char* name, double relative) {
  SCOPED_TRACE(name);
  const Scheme& s = scheme(name);
  const double accuracy = relative * diagonal(mesh);
  const LimitEvaluator exact(mesh, s);
  const LimitEvaluator approximate = LimitEvaluator::by_refinement(mesh, s, accuracy);
  EXPECT_LE(approximate.measured_change(), accuracy);
  EXPECT_EQ(approximate.unresolved_vertices(), 0);
  EXPECT_EQ(approximate.ptex_face_count(), exact.ptex_face_count());
  if (approximate.ptex_face_count() != exact.ptex_face_count()) return 0.0;
  double worst = 0.0, worst_normal = 0.0;
  for (Index f = 0; f < exact.ptex_face_count(); ++f) {
    for (const auto& [u, v] : parameters(exact.triangles(), 8, 11u + static_cast<unsigned>(f))) {
      const LimitPoint a = approximate.evaluate(f, u, v);
      const LimitPoint e = exact.evaluate(f, u, v);
      worst = std::max(worst, norm(a.position - e.position));
      worst_normal = std::max(worst_normal, norm(a.normal - e.normal));
    }
  }
  std::cout << "[ refined  ] " << name << ": " << approximate.isolation_levels() << " levels, measured change "
            << approximate.measured_change() << ", largest distance from the exact surface " << worst << " (accuracy "
            << accuracy << "), normals " << worst_normal << "\n";
  EXPECT_LE(worst, accuracy);
  return worst_normal;
}

// Positions within the accuracy; normals (interpolated limit normals, the
// interpolant's own beside creases) closer at least by half for ten times
// the accuracy.
TEST(RefinedEvaluation, CatmullClarkAndLoopAreWithinTheAccuracyOfTheExactSurface) {
  const std::vector<std::pair<PolygonMesh, const char*>> cases = {
      {test::jittered(test::cube(), 3), "catmull-clark"},
      {test::jittered(test::creased_cube(), 4), "catmull-clark"},
      {test::jittered(test::bipyramid(5), 6), "loop"},
      {test::jittered(test::triangle_grid(3, 3), 8), "loop"}};
  for (const auto& [mesh, name] : cases) {
    const double coarse = expect_within_accuracy_of_exact(mesh, name, 1e-2);
    const double fine = expect_within_accuracy_of_exact(mesh, name, 1e-3);
    EXPECT_LT(fine, coarse / 2) << name;
  }
}

// The interpolating schemes' refined vertices are limit points: at the
// dyadic parameters one level below the evaluator's, the evaluator is
// within the accuracy of them; at the control vertices it is exact.
void expect_within_accuracy_of_deeper_vertices(const PolygonMesh& mesh, const char* name) {
  SCOPED_TRACE(name);
  const Scheme& s = scheme(name);
  const double accuracy = 1e-2 * diagonal(mesh);
  const LimitEvaluator evaluator = LimitEvaluator::by_refinement(mesh, s, accuracy);
  const bool triangles = evaluator.triangles();
  const int levels = evaluator.isolation_levels() + 1;
  const double n = std::ldexp(1.0, levels);
  double worst = 0.0;
  int checked = 0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    // The control face's corners are at ptex corners: exact.
    const auto corners = mesh.face(f);
    const double corner_uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const double triangle_uv[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const double* uv = triangles ? triangle_uv[k] : corner_uv[k];
      const LimitPoint p = evaluator.evaluate(evaluator.ptex_face_of(f), uv[0], uv[1]);
      EXPECT_LE(norm(p.position - mesh.positions[static_cast<std::size_t>(corners[k])]), 1e-14 * diagonal(mesh));
    }
  }
  // Every vertex of the deeper level is on the limit: compare at its ptex
  // parameter, found by refining the ptex corner parameters along (the
  // splits keep face-varying values linear within faces).
  PolygonMesh start = mesh;
  FaceVaryingChannel ptex{"ptex", 2, {}, {}};
  std::vector<Index> face_ptex;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const std::vector<std::array<double, 2>> uv =
        triangles ? std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {0, 1}}
                  : std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& [u, v] : uv) {
      ptex.values.push_back(u);
      ptex.values.push_back(v);
      ptex.indices.push_back(static_cast<Index>(ptex.indices.size()));
    }
  }
  start.face_varying_channels = {ptex};
  const PolygonMesh refined = refine(start, s, test::levels(levels));
  const FaceVaryingChannel& channel = refined.face_varying_channels.at(0);
  // Face g of level L descends from control face g / 4^L: both splits
  // number a face's children together (the quad split by the parent's
  // corners, four per quad).
  const auto per_face = static_cast<Index>(std::llround(n * n));
  for (Index g = 0; g < refined.face_count(); ++g) {
    const Index f = g / per_face;
    const auto corners = refined.face(g);
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const Index value =
          channel.indices[static_cast<std::size_t>(refined.face_offsets[static_cast<std::size_t>(g)]) + k];
      const double u = channel.values[2 * static_cast<std::size_t>(value)];
      const double v = channel.values[2 * static_cast<std::size_t>(value) + 1];
      const LimitPoint p = evaluator.evaluate(evaluator.ptex_face_of(f), u, v);
      worst = std::max(worst, norm(p.position - refined.positions[static_cast<std::size_t>(corners[k])]));
      ++checked;
    }
  }
  std::cout << "[ refined  ] " << name << ": " << evaluator.isolation_levels() << " levels, measured change "
            << evaluator.measured_change() << ", largest distance from level-" << levels << " vertices " << worst
            << " (accuracy " << accuracy << ")\n";
  EXPECT_GT(checked, 100);
  EXPECT_LE(worst, accuracy);
}

TEST(RefinedEvaluation, InterpolatingSchemesAreWithinTheAccuracyOfDeeperVertices) {
  expect_within_accuracy_of_deeper_vertices(test::jittered(test::bipyramid(5), 21), "butterfly");
  // On the regular tetrahedron the Butterfly's first edge points are the
  // midpoints (no change at level 1), the next level's are not.
  expect_within_accuracy_of_deeper_vertices(test::tetrahedron(), "butterfly");
  expect_within_accuracy_of_deeper_vertices(test::jittered(test::bipyramid(7), 22), "modified-butterfly");
  expect_within_accuracy_of_deeper_vertices(test::jittered(test::cube(), 23), "kobbelt");
}

// A tessellation by refinement is watertight: a closed mesh stays closed.
TEST(RefinedEvaluation, TessellationsOfClosedMeshesStayClosed) {
  for (const char* name : {"kobbelt", "butterfly"}) {
    SCOPED_TRACE(name);
    const PolygonMesh mesh = test::jittered(std::string(name) == "kobbelt" ? test::cube() : test::bipyramid(4), 31);
    const LimitEvaluator evaluator = LimitEvaluator::by_refinement(mesh, scheme(name), 1e-2 * diagonal(mesh));
    const PolygonMesh t = tessellate(mesh, evaluator, 5);
    const MeshTopology topology(t);
    for (Index e = 0; e < topology.edge_count(); ++e) ASSERT_EQ(topology.edge_face_count(e), 2) << "edge " << e;
  }
}

// Outside the exact scope, Catmull-Clark still evaluates by refinement: a
// crease of sharpness 6 and an interior vertex of valence 2. At the control
// vertices (ptex corners) the evaluator gives their limit positions.
TEST(RefinedEvaluation, CatmullClarkOutsideTheExactScopeMatchesVertexLimits) {
  PolygonMesh mesh = test::jittered(test::creased_cube(), 41);
  for (CreaseTag& c : mesh.tags.creases) c.sharpness = 6.0;
  const Scheme& s = scheme("catmull-clark");
  ASSERT_TRUE(LimitEvaluator::exact_evaluation_unavailable(mesh, s).has_value());
  EXPECT_THROW(LimitEvaluator(mesh, s), InvalidInputError);
  const LimitEvaluator evaluator = LimitEvaluator::by_refinement(mesh, s, 1e-3 * diagonal(mesh));
  const LimitResult limits = limit_positions(mesh, s);
  ASSERT_EQ(limits.approximated, 0);
  const double corner_uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (Index f = 0; f < mesh.face_count(); ++f)
    for (std::size_t k = 0; k < 4; ++k) {
      const LimitPoint p = evaluator.evaluate(evaluator.ptex_face_of(f), corner_uv[k][0], corner_uv[k][1]);
      EXPECT_LE(norm(p.position - limits.positions[static_cast<std::size_t>(mesh.face(f)[k])]), 1e-12 * diagonal(mesh));
    }
}

TEST(RefinedEvaluation, RefusesWhatItCannotDo) {
  const PolygonMesh cube = test::cube();
  const PolygonMesh tetrahedron = test::tetrahedron();
  // Splits whose faces are not divided into sub-faces, and composite schemes.
  for (const char* name : {"doo-sabin", "sqrt3", "four-eight", "midedge"}) {
    SCOPED_TRACE(name);
    const PolygonMesh& mesh = std::string(name) == "sqrt3" ? tetrahedron : cube;
    EXPECT_THROW(LimitEvaluator::by_refinement(mesh, scheme(name), 1e-3), InvalidInputError);
  }
  EXPECT_THROW(LimitEvaluator::by_refinement(cube, scheme("catmull-clark"), 0.0), InvalidInputError);
  EXPECT_THROW(LimitEvaluator::by_refinement(cube, scheme("catmull-clark"), std::nan("")), InvalidInputError);
  // Not reached within the levels allowed: the message says what was measured.
  try {
    (void)LimitEvaluator::by_refinement(cube, scheme("catmull-clark"), 1e-12, {}, 2);
    FAIL() << "expected a refusal";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("not reached within 2 levels"), std::string::npos) << e.what();
  }
  PolygonMesh holed = cube;
  holed.tags.holes = {0};
  EXPECT_THROW(LimitEvaluator::by_refinement(holed, scheme("catmull-clark"), 1e-3), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
