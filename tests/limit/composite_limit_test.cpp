// Limit positions of the composite schemes of the quad split (gcc and
// midpoint of odd degree), through the analysis's masks of a whole level
// (the smoothing steps included):
// - gcc of degree 3 with Catmull-Clark's weights is Catmull-Clark on closed
//   quad meshes, so its limits and normals equal Catmull-Clark's closed
//   forms, an independent route;
// - degrees 3, 5 and 7 against deep refinement: each level's vertex points
//   close on the limits geometrically;
// - limits commute with an affine map of the control points;
// - the dual split's composites (even degree) against deep refinement of
//   their V-faces.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/generalized_catmull_clark.h"
#include "support/gcc_schemes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

PolygonMesh spot() { return read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh; }

// One Catmull-Clark level: all quads, with the input's extraordinary
// vertices and one per non-quad face (spot: valences 3 and 5; the rook: 12).
PolygonMesh quads_of(const PolygonMesh& mesh) {
  RefineOptions once;
  once.levels = 1;
  return refine(mesh, catmull_clark_scheme(), once);
}

TEST(CompositeLimit, GccOfDegreeThreeHasCatmullClarksLimits) {
  // Catmull-Clark's own weights, alpha = 1 - 3/m and beta = 2/m, are gcc's
  // defaults at degree 3; B R is Catmull-Clark on closed quad meshes (on
  // other faces R's face point is no Catmull-Clark vertex).
  const Scheme& gcc = generalized_catmull_clark_scheme();
  for (const auto& [name, mesh] :
       {std::pair{"spot", quads_of(spot())}, std::pair{"cube", test::jittered(test::cube(), 3)},
        std::pair{"rook", quads_of(read_mesh(test::bundled_path("rook.obj")).mesh)}}) {
    SCOPED_TRACE(name);
    LimitOptions options;
    options.normals = true;
    const LimitResult composite = limit_positions(mesh, gcc, options);
    const LimitResult closed = limit_positions(mesh, catmull_clark_scheme(), options);
    EXPECT_EQ(composite.approximated, 0);
    ASSERT_EQ(composite.positions.size(), closed.positions.size());
    const double size = test::radius(mesh);
    for (std::size_t v = 0; v < closed.positions.size(); ++v) {
      EXPECT_EQ(composite.sources[v], LimitSource::generic) << v;
      EXPECT_LT(norm(composite.positions[v] - closed.positions[v]), 1e-11 * size) << "vertex " << v;
      EXPECT_LT(norm(composite.normals[v] - closed.normals[v]), 1e-8) << "vertex " << v;
    }
  }
}

// The vertex points of each level close on the limits by about 1/4 per
// level, the square of the subdominant eigenvalue 1/2 (vertex points are
// numbered last by the quad split, so the input vertices are the last ones
// of every level).
TEST(CompositeLimit, OddDegreesAgreeWithDeepRefinement) {
  const PolygonMesh cube = test::jittered(test::cube(), 5);
  const Scheme schemes[] = {test::midpoint(3), test::midpoint(5), test::gcc(5, 0.5, 0.25), test::midpoint(7)};
  for (const Scheme& scheme : schemes) {
    const auto degree = std::get<DegreeParameters>(scheme.parameters).degree;
    SCOPED_TRACE(std::string(scheme.name) + " degree " + std::to_string(degree));
    const LimitResult limit = limit_positions(cube, scheme);
    EXPECT_EQ(limit.approximated, 0);
    double previous = 0.0;
    for (int levels = 1; levels <= 5; ++levels) {
      RefineOptions o;
      o.levels = levels;
      const PolygonMesh fine = refine(cube, scheme, o);
      const Index first = fine.vertex_count() - cube.vertex_count();
      double worst = 0.0;
      for (Index v = 0; v < cube.vertex_count(); ++v)
        worst = std::max(worst, norm(fine.positions[static_cast<std::size_t>(first + v)] -
                                     limit.positions[static_cast<std::size_t>(v)]));
      if (levels > 1) {
        EXPECT_LT(worst, 0.35 * previous) << "level " << levels;  // 0.22-0.26 measured
      }
      previous = worst;
    }
    EXPECT_LT(previous, 1e-2 * test::radius(cube));
  }
}

TEST(CompositeLimit, CommutesWithAnAffineMap) {
  auto map = [](Vec3 p) { return Vec3{p.x - 2.0 * p.z + 1.0, 3.0 * p.y, p.x + p.y + p.z}; };
  const PolygonMesh mesh = spot();
  PolygonMesh moved = mesh;
  for (Vec3& p : moved.positions) p = map(p);
  const Scheme scheme = test::midpoint(5);
  const LimitResult a = limit_positions(mesh, scheme), b = limit_positions(moved, scheme);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  EXPECT_EQ(a.approximated, 0);
  for (std::size_t v = 0; v < a.positions.size(); ++v)
    EXPECT_LT(norm(map(a.positions[v]) - b.positions[v]), 1e-11 * test::radius(moved)) << "vertex " << v;
}

// Even degrees end with A, a dual split: a vertex's limit is its V-face's
// (dual_limit.h), read over as many rings as the analysis's matrix spans.
// The V-face of vertex v is child face F + E + v of a closed mesh whose
// vertices all have one, and each later level keeps its descendant at the
// same index (a face's F-face child has its number), whose centroid closes
// on the limit. Degree 6 reads three rings: the route refines further (the
// isolation levels) until the cube's V-faces are apart.
TEST(CompositeLimit, EvenDegreesAgreeWithDeepRefinement) {
  const PolygonMesh cube = test::jittered(test::cube(), 11);
  const Index v_faces = cube.face_count() + 12;  // faces + edges of the cube
  const Scheme schemes[] = {test::midpoint(2), test::midpoint(4), test::gcc(4, 0.5, 0.25), test::midpoint(6)};
  for (const Scheme& scheme : schemes) {
    const auto degree = std::get<DegreeParameters>(scheme.parameters).degree;
    SCOPED_TRACE(std::string(scheme.name) + " degree " + std::to_string(degree));
    ASSERT_FALSE(limit_unavailable(scheme).has_value());
    const LimitResult limit = limit_positions(cube, scheme);
    EXPECT_EQ(limit.approximated, 0);
    double previous = 0.0;
    for (int levels = 2; levels <= 6; ++levels) {
      RefineOptions o;
      o.levels = levels;
      const PolygonMesh fine = refine(cube, scheme, o);
      double worst = 0.0;
      for (Index v = 0; v < cube.vertex_count(); ++v) {
        Vec3 centroid;
        const auto face = fine.face(v_faces + v);
        for (const Index u : face) centroid += fine.positions[static_cast<std::size_t>(u)];
        centroid = (1.0 / static_cast<double>(face.size())) * centroid;
        worst = std::max(worst, norm(centroid - limit.positions[static_cast<std::size_t>(v)]));
      }
      // Degree 2 (A R: every face's F-face keeps its centroid, as
      // Doo-Sabin's) is exact at every level; degrees 4 and 6 close by 1/4
      // per level (measured 0.25).
      if (levels > 2 && worst > 1e-14) {
        EXPECT_LT(worst, 0.35 * previous) << "level " << levels;
      }
      previous = worst;
    }
  }
}

// Without a boundary curve (gcc, midpoint) boundary vertices stay
// unresolved, counted, instead of refusing the whole mesh.
TEST(CompositeLimit, EvenDegreesLeaveOpenBoundariesUnresolved) {
  const PolygonMesh grid = test::quad_grid(3, 3);
  const LimitResult r = limit_positions(grid, test::midpoint(4));
  EXPECT_EQ(r.approximated, 12);  // the grid's boundary vertices
}

}  // namespace
}  // namespace subdiv
