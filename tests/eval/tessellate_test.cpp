// Tessellations and closest points of the limit surface: watertight,
// closed where the control mesh is, on the surface (control vertices at
// their closed-form limits), and nearest points that find the surface point
// a query was offset from.

#include "subdiv/eval/tessellate.h"
#include "subdiv/eval/closest_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "refine/grid_test_support.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/validation.h"
#include "support/refine_options.h"
#include "support/scheme_by_name.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using grid_test::diagonal;

using test::scheme;

// The double pyramid, jittered.
PolygonMesh bipyramid(int n, unsigned seed) { return test::jittered(test::bipyramid(n), seed); }

// Closed, watertight (every edge has two faces: a point made twice would
// leave two boundary edges), of the expected size, the control vertices at
// their limits, unit normals.
void expect_closed_tessellation(const PolygonMesh& control, const char* name, int rate) {
  SCOPED_TRACE(std::string(name) + " at rate " + std::to_string(rate));
  const LimitEvaluator evaluator(control, scheme(name));
  const PolygonMesh t = tessellate(control, evaluator, rate);
  ASSERT_TRUE(validate(t).ok()) << validate(t).first_error();
  const MeshTopology topology(t);
  for (Index e = 0; e < topology.edge_count(); ++e) ASSERT_EQ(topology.edge_face_count(e), 2) << "edge " << e;
  EXPECT_EQ(t.vertex_count() - topology.edge_count() + t.face_count(), 2);  // a sphere, as the control meshes
  const MeshTopology c(control);
  std::int64_t faces = 0;
  for (Index f = 0; f < c.face_count(); ++f)
    faces += c.face_size(f) == (evaluator.triangles() ? 3 : 4) ? std::int64_t{rate} * rate
                                                               : std::int64_t{c.face_size(f)} * (rate / 2) * (rate / 2);
  EXPECT_EQ(t.face_count(), faces);
  const LimitResult limits = limit_positions(control, scheme(name));
  for (Index v = 0; v < control.vertex_count(); ++v)
    ASSERT_LE(norm(t.positions[static_cast<std::size_t>(v)] - limits.positions[static_cast<std::size_t>(v)]),
              1e-12 * diagonal(control));
  const FaceVaryingChannel& normals = t.face_varying_channels.at(0);
  ASSERT_EQ(normals.name, "normal");
  for (Index i = 0; i < normals.value_count(); ++i) {
    const auto k = 3 * static_cast<std::size_t>(i);
    ASSERT_NEAR(norm({normals.values[k], normals.values[k + 1], normals.values[k + 2]}), 1.0, 1e-12);
  }
}

// An open mesh: watertight inside (every interior edge of two faces), its
// boundary made of `rate` edges per control boundary edge, the control
// vertices at their limits.
TEST(Tessellate, OpenMeshesKeepTheirBoundary) {
  for (const char* name : {"catmull-clark", "loop"}) {
    SCOPED_TRACE(name);
    const bool loop = std::string(name) == "loop";
    const PolygonMesh control = test::jittered(loop ? test::triangle_grid(3, 2) : test::quad_grid(3, 2), 7);
    const LimitEvaluator evaluator(control, scheme(name));
    constexpr int kRate = 4;
    const PolygonMesh t = tessellate(control, evaluator, kRate);
    ASSERT_TRUE(validate(t).ok()) << validate(t).first_error();
    const MeshTopology topology(t), c(control);
    Index boundary = 0, control_boundary = 0;
    for (Index e = 0; e < topology.edge_count(); ++e) boundary += topology.edge_face_count(e) == 1 ? 1 : 0;
    for (Index e = 0; e < c.edge_count(); ++e) control_boundary += c.edge_face_count(e) == 1 ? 1 : 0;
    EXPECT_EQ(boundary, kRate * control_boundary);
    EXPECT_EQ(t.face_count(), control.face_count() * kRate * kRate);
    const LimitResult limits = limit_positions(control, scheme(name));
    for (Index v = 0; v < control.vertex_count(); ++v)
      ASSERT_LE(norm(t.positions[static_cast<std::size_t>(v)] - limits.positions[static_cast<std::size_t>(v)]),
                1e-12 * diagonal(control));
  }
}

TEST(Tessellate, ClosedMeshesGiveClosedWatertightTessellations) {
  for (int rate : {1, 2, 5}) expect_closed_tessellation(test::jittered(test::cube(), 2), "catmull-clark", rate);
  for (int rate : {2, 4, 6}) expect_closed_tessellation(bipyramid(5, 3), "catmull-clark", rate);  // n-gons
  for (int rate : {1, 3, 4}) expect_closed_tessellation(bipyramid(7, 4), "loop", rate);
  expect_closed_tessellation(test::tetrahedron(), "loop", 3);  // valence 3 everywhere
}

TEST(Tessellate, RefusesBadRates) {
  const PolygonMesh triangles = bipyramid(5, 1);
  const LimitEvaluator evaluator(triangles, scheme("catmull-clark"));
  EXPECT_THROW(tessellate(triangles, evaluator, 3), InvalidInputError);  // odd, with n-gons
  EXPECT_THROW(tessellate(triangles, evaluator, 0), InvalidInputError);
  EXPECT_THROW(tessellate(triangles, evaluator, 5000), InvalidInputError);
  EXPECT_THROW(tessellate(test::cube(), evaluator, 2), InvalidInputError);  // another mesh
}

TEST(ClosestPoints, FindTheSurfacePointAQueryWasOffsetFrom) {
  for (const char* name : {"catmull-clark", "loop"}) {
    SCOPED_TRACE(name);
    const bool loop = std::string(name) == "loop";
    const PolygonMesh control = loop ? bipyramid(6, 5) : test::jittered(test::cube(), 6);
    const LimitEvaluator evaluator(control, scheme(name));
    const double size = diagonal(control);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.05, 0.45);
    std::vector<LimitPoint> on_surface;
    std::vector<Vec3> queries;
    for (Index face = 0; face < evaluator.ptex_face_count(); ++face) {
      const LimitPoint p = evaluator.evaluate(face, unit(random), unit(random));
      on_surface.push_back(p);
      queries.push_back(p.position + (1e-3 * size) * p.normal);  // just outside
      on_surface.push_back(p);
      queries.push_back(p.position);  // on the surface
    }
    const std::vector<ClosestPoint> nearest = closest_points(control, evaluator, queries);
    ASSERT_EQ(nearest.size(), queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const double offset = norm(queries[i] - on_surface[i].position);
      EXPECT_LE(norm(nearest[i].position - on_surface[i].position), 1e-7 * size) << "query " << i;
      EXPECT_NEAR(nearest[i].distance, offset, 1e-9 * size) << "query " << i;
      const LimitPoint again = evaluator.evaluate(nearest[i].location.face, nearest[i].location.u, nearest[i].location.v);
      EXPECT_EQ(again.position, nearest[i].position);
    }
  }
}

TEST(ClosestPoints, FarPointsAndBadInput) {
  const PolygonMesh cube = test::cube();
  const LimitEvaluator evaluator(cube, scheme("catmull-clark"));
  // Far along a diagonal: the limit of the cube's corner (a vertex of valence 3).
  const std::vector<Vec3> far = {{50, 50, 50}};
  const LimitResult limits = limit_positions(cube, scheme("catmull-clark"));
  Index corner = 0;
  for (Index v = 0; v < cube.vertex_count(); ++v)
    if (cube.positions[static_cast<std::size_t>(v)] == Vec3{1, 1, 1}) corner = v;
  const ClosestPoint c = closest_points(cube, evaluator, far).at(0);
  EXPECT_LE(norm(c.position - limits.positions[static_cast<std::size_t>(corner)]), 1e-6);
  const std::vector<Vec3> bad = {{0, 0, std::numeric_limits<double>::infinity()}};
  EXPECT_THROW(closest_points(cube, evaluator, bad), InvalidInputError);
  EXPECT_THROW(closest_points(cube, evaluator, far, 3), InvalidInputError);
  EXPECT_TRUE(closest_points(cube, evaluator, {}).empty());
}

}  // namespace
}  // namespace subdiv
