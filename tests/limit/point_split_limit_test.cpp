// Limit positions and normals of the sqrt3 and sqrt2 splits' schemes (sqrt3,
// interpolatory sqrt3, four-eight) from the generic masks, against deep
// refinement: the refined vertex approaches the limit at a geometric rate,
// and the faces around it turn towards the limit normal.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/four_eight.h"
#include "subdiv/rules/interpolatory_sqrt3.h"
#include "subdiv/rules/sqrt3.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

// The area-weighted normal of the faces around vertex v.
Vec3 face_normal_around(const PolygonMesh& mesh, const MeshTopology& t, Index v) {
  Vec3 sum;
  const Vec3 p = mesh.positions[static_cast<std::size_t>(v)];
  for (const Index c : t.vertex_corners(v)) {
    const Vec3 a = mesh.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(c)))] - p;
    const Vec3 b = mesh.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_prev(c)))] - p;
    sum += cross(a, b);
  }
  return sum;
}

struct Case {
  std::string name;
  PolygonMesh mesh;
  const Scheme* scheme;
  int isolation_levels;
  int deepest;          ///< refinement steps of the deepest comparison (even)
  double rate;          ///< |refined - limit| shrinks at least this much per two steps
  double position_end;  ///< and ends below this, relative to the mesh's size
  double normal_end;    ///< the worst face-normal angle at the deepest level (radians)
};

double size_of(const PolygonMesh& mesh) {
  Vec3 lo = mesh.positions.front(), hi = lo;
  for (const Vec3& p : mesh.positions)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  return norm(hi - lo);
}

std::vector<Case> cases() {
  const PolygonMesh cube = test::cube();
  const PolygonMesh l_shape = read_mesh(test::bundled_path("l_shape.obj")).mesh;  // open, a concave corner
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  std::vector<Case> out;
  out.push_back({"sqrt3 cube", triangulate(cube), &sqrt3_scheme(), 2, 8, 0.15, 5e-5, 1e-6});
  out.push_back({"sqrt3 l_shape", triangulate(l_shape), &sqrt3_scheme(), 2, 8, 0.2, 3e-5, 3e-3});
  out.push_back({"four-eight cube", cube, &four_eight_scheme(), 2, 12, 0.3, 1e-4, 1e-10});
  out.push_back({"four-eight spot", spot, &four_eight_scheme(), 2, 10, 0.3, 2e-4, 5e-3});
  return out;
}

LimitResult limit_of(const Case& c) {
  LimitOptions options;
  options.isolation_levels = c.isolation_levels;
  return limit_positions(c.mesh, *c.scheme, options);
}

// Measured (printed): per two steps the distance shrinks by 0.085 (sqrt3
// cube), 0.11 (sqrt3 L, open, a concave corner), 0.25 (four-eight), to
// 1.3e-5, 6.4e-6, 4.7e-5 and 4.8e-5 of the mesh's size; the worst normal
// angles end at 1.5e-8, 7.4e-4, 2e-14 and 1.6e-3 radians.
TEST(PointSplitLimit, PositionsAndNormalsAgreeWithDeepRefinement) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const LimitResult r = limit_of(c);
    EXPECT_EQ(r.approximated, 0);
    ASSERT_EQ(r.positions.size(), static_cast<std::size_t>(c.mesh.vertex_count()));
    const double size = size_of(c.mesh);
    double previous = 0.0;
    for (int steps = 2; steps <= c.deepest; steps += 2) {
      RefineOptions o;
      o.levels = steps;
      const PolygonMesh fine = refine(c.mesh, *c.scheme, o);
      const MeshTopology t(fine);
      const Index first = fine.vertex_count() - c.mesh.vertex_count();  // vertex points come last
      double worst = 0.0, worst_angle = 0.0;
      for (Index v = 0; v < c.mesh.vertex_count(); ++v) {
        const auto i = static_cast<std::size_t>(v);
        worst = std::max(worst, norm(fine.positions[static_cast<std::size_t>(first + v)] - r.positions[i]) / size);
        if (norm(r.normals[i]) > 0.0)
          worst_angle = std::max(worst_angle, angle_between(face_normal_around(fine, t, first + v), r.normals[i]));
      }
      std::printf("  %s: %d steps: max |refined - limit| / size = %.3e, worst normal angle %.3e\n", c.name.c_str(),
                  steps, worst, worst_angle);
      if (steps > 2) {
        EXPECT_LT(worst, c.rate * previous) << steps << " steps";
      }
      previous = worst;
      if (steps == c.deepest) {
        EXPECT_LT(worst, c.position_end);
        EXPECT_LT(worst_angle, c.normal_end);
      }
    }
  }
}

// The limit normals are unit at every vertex but the L's concave corner,
// which the standard rules flip (no tangent plane): at its convex corners
// too, from the corner configuration's pair 1/3 (the boundary curves'
// eigenvalue over sqrt3's two steps). The deep-refinement test checks
// their direction.
TEST(PointSplitLimit, NormalsAreUnitWhereThereIsATangentPlane) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const LimitResult r = limit_of(c);
    Index concave = kInvalidIndex;
    for (const CornerTag& corner : c.mesh.tags.corners)
      if (corner.type == CornerType::concave) concave = corner.vertex;
    for (Index v = 0; v < c.mesh.vertex_count(); ++v) {
      const double length = norm(r.normals[static_cast<std::size_t>(v)]);
      EXPECT_NEAR(length, v == concave ? 0.0 : 1.0, 1e-12) << "vertex " << v;
    }
  }
}

// Interpolatory sqrt3 keeps its vertices: their limits are the control
// points (the analysis's limit mask is the centre alone), and the faces
// around each vertex turn towards its limit normal (measured worst angles
// 6.6e-3, 5.6e-4, 4.8e-5, 4.0e-6 after 2, 4, 6, 8 steps).
TEST(PointSplitLimit, InterpolatorySqrt3LimitsAreTheControlPoints) {
  PolygonMesh mesh = triangulate(test::cube());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) mesh.positions[i].z += 0.05 * static_cast<double>(i % 3);
  const LimitResult r = limit_positions(mesh, interpolatory_sqrt3_scheme());
  EXPECT_EQ(r.approximated, 0);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_EQ(r.sources[static_cast<std::size_t>(v)], LimitSource::generic);
    EXPECT_EQ(norm(r.positions[static_cast<std::size_t>(v)] - mesh.positions[v]), 0.0) << v;
    EXPECT_NEAR(norm(r.normals[static_cast<std::size_t>(v)]), 1.0, 1e-12) << v;
  }
  double previous = 0.0;
  for (int steps = 2; steps <= 8; steps += 2) {
    RefineOptions o;
    o.levels = steps;
    const PolygonMesh fine = refine(mesh, interpolatory_sqrt3_scheme(), o);
    const MeshTopology t(fine);
    const Index first = fine.vertex_count() - mesh.vertex_count();
    double worst = 0.0;
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      worst = std::max(worst, angle_between(face_normal_around(fine, t, first + v), r.normals[static_cast<std::size_t>(v)]));
    std::printf("  interpolatory sqrt3: %d steps: worst normal angle %.3e\n", steps, worst);
    if (steps > 2) {
      EXPECT_LT(worst, 0.3 * previous) << steps << " steps";
    }
    previous = worst;
  }
  EXPECT_LT(previous, 2e-5);
}

// The topology match is enough for these splits' rules: the limits after
// 2 isolation levels, where other extraordinary vertices sit in the masks'
// outer rings (on the elephant's triangles every old vertex and face point
// is extraordinary for four-eight), equal those after 3 (four-eight, six
// steps) or 4 (the sqrt3 schemes), where every neighbourhood is regular
// but its centre. Every vertex matches at both.
TEST(PointSplitLimit, IsolationLevelsDoNotChangeTheLimit) {
  const PolygonMesh elephant = read_mesh(test::bundled_path("elephant.obj")).mesh;
  const double size = size_of(elephant);
  for (const auto& [scheme, deeper] : {std::pair{&four_eight_scheme(), 3}, std::pair{&sqrt3_scheme(), 4},
                                       std::pair{&interpolatory_sqrt3_scheme(), 4}}) {
    SCOPED_TRACE(std::string(scheme->name));
    LimitOptions options;
    options.isolation_levels = 2;
    const LimitResult near = limit_positions(elephant, *scheme, options);
    options.isolation_levels = deeper;
    const LimitResult far = limit_positions(elephant, *scheme, options);
    EXPECT_EQ(near.approximated, 0);
    EXPECT_EQ(far.approximated, 0);
    for (std::size_t v = 0; v < near.positions.size(); ++v) {
      EXPECT_LT(norm(near.positions[v] - far.positions[v]), 1e-13 * size) << "vertex " << v;
      EXPECT_LT(norm(near.normals[v] - far.normals[v]), 1e-10) << "vertex " << v;
    }
  }
}

// Isolation: four-eight counts binary levels (two steps each), sqrt3 an
// even number of steps.
TEST(PointSplitLimit, IsolationLevelsPerSplit) {
  LimitOptions options;
  options.isolation_levels = 1;
  EXPECT_EQ(limit_positions(test::cube(), four_eight_scheme(), options).levels_refined, 2);
  EXPECT_EQ(limit_positions(triangulate(test::cube()), sqrt3_scheme(), options).levels_refined, 2);
  options.isolation_levels = 3;
  EXPECT_EQ(limit_positions(test::cube(), four_eight_scheme(), options).levels_refined, 6);
  EXPECT_EQ(limit_positions(triangulate(test::cube()), sqrt3_scheme(), options).levels_refined, 4);
}

}  // namespace
}  // namespace subdiv
