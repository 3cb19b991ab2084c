// Limit positions through the analysis masks, against the closed forms of
// Catmull-Clark and Loop applied by hand, the boundary curve's 1/6 2/3 1/6,
// and deep refinement.

#include <gtest/gtest.h>

#include <cmath>

#include "subdiv/analysis/limit.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// The closed-form limit of an interior vertex on an all-quad (Catmull-Clark,
// n^2 : 4 : 1 over n (n + 5)) or all-triangle (Loop, beta_limit) level.
Vec3 closed_form_limit(const PolygonMesh& m, const MeshTopology& t, Index v, bool quads) {
  const int n = t.valence(v);
  Vec3 edge_sum, far_sum;
  for (const Index e : t.vertex_edges(v)) edge_sum += m.positions[static_cast<std::size_t>(t.other_vertex(e, v))];
  if (quads) {
    for (const Index c : t.vertex_corners(v))
      far_sum += m.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(t.corner_next(c))))];
    return (1.0 / (n * (n + 5.0))) * (n * n * m.positions[static_cast<std::size_t>(v)] + 4.0 * edge_sum + far_sum);
  }
  const double beta = loop_beta(n), beta_limit = 8.0 * beta / (3.0 + 8.0 * n * beta);
  return (1.0 - n * beta_limit) * m.positions[static_cast<std::size_t>(v)] + beta_limit * edge_sum;
}

TEST(Limit, MatchesTheClosedFormsAfterIsolation) {
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  const PolygonMesh tetra = test::tetrahedron();
  for (const auto& [scheme, mesh] : {std::pair{&catmull_clark_scheme(), spot}, std::pair{&loop_scheme(), tetra}}) {
    LimitOptions options;
    options.isolation_levels = 2;
    const LimitResult r = limit_positions(mesh, *scheme, options);
    EXPECT_EQ(r.approximated, 0);
    // The same vertices two levels down, by hand.
    RefineOptions two;
    two.levels = 2;
    const PolygonMesh fine = refine(mesh, *scheme, two);
    const MeshTopology t(fine);
    const Index first = fine.vertex_count() - mesh.vertex_count();  // vertex points come last, twice
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      EXPECT_LT(norm(r.positions[static_cast<std::size_t>(v)] - closed_form_limit(fine, t, first + v, scheme == &catmull_clark_scheme())),
                1e-12 * test::radius(mesh))
          << scheme->name << " vertex " << v;
  }
}

TEST(Limit, DeepRefinementConverges) {
  // |limit - refined position| shrinks with each level.
  const PolygonMesh cube = test::cube();
  const LimitResult r = limit_positions(cube, catmull_clark_scheme());
  double previous = 1e9;
  for (int levels = 1; levels <= 6; ++levels) {
    RefineOptions o;
    o.levels = levels;
    const PolygonMesh fine = refine(cube, catmull_clark_scheme(), o);
    const Index first = fine.vertex_count() - cube.vertex_count();
    double worst = 0;
    for (Index v = 0; v < cube.vertex_count(); ++v)
      worst = std::max(worst, norm(fine.positions[static_cast<std::size_t>(first + v)] - r.positions[static_cast<std::size_t>(v)]));
    EXPECT_LT(worst, 0.7 * previous) << "level " << levels;
    previous = worst;
  }
  EXPECT_LT(previous, 1e-2);
}

TEST(Limit, BoundaryVerticesFollowTheCubicBSplineCurve) {
  PolygonMesh grid = test::quad_grid(4, 4);
  for (Vec3& p : grid.positions) p.z = 0.1 * p.x * p.x - 0.05 * p.y * p.x * p.x;
  LimitOptions options;
  options.isolation_levels = 0;
  options.refine.boundary = BoundaryInterpolation::edge_only;
  const LimitResult r = limit_positions(grid, catmull_clark_scheme(), options);
  const MeshTopology t(grid);
  int checked = 0;
  for (Index v = 0; v < grid.vertex_count(); ++v) {
    if (t.vertex_kind(v) != VertexKind::boundary || t.vertex_face_count(v) != 2) continue;
    Index nb[2];
    int n = 0;
    for (const Index e : t.vertex_edges(v))
      if (t.is_boundary_edge(e)) nb[n++] = t.other_vertex(e, v);
    const Vec3 expected = (1.0 / 6.0) * (grid.positions[static_cast<std::size_t>(nb[0])] + grid.positions[static_cast<std::size_t>(nb[1])]) +
                          (2.0 / 3.0) * grid.positions[static_cast<std::size_t>(v)];
    EXPECT_LT(norm(r.positions[static_cast<std::size_t>(v)] - expected), 1e-12) << "vertex " << v;
    ++checked;
  }
  EXPECT_EQ(checked, 12);
}

TEST(Limit, NormalsOfAPlaneAndACube) {
  // Both routes take the corner's two sharp edges as tangents, in the plane
  // too (the generic masks: the corner configuration's pair 1/2).
  for (const LimitRoute route : {LimitRoute::generic, LimitRoute::closed_form}) {
    LimitOptions options;
    options.route = route;
    const LimitResult plane = limit_positions(test::quad_grid(4, 4), catmull_clark_scheme(), options);
    int defined = 0;
    for (const Vec3& n : plane.normals) {
      if (norm(n) == 0.0) continue;
      EXPECT_NEAR(n.z, 1.0, 1e-12);
      ++defined;
    }
    EXPECT_EQ(defined, 25);
  }
  // The cube's corners: by symmetry the normal points along the diagonal.
  const PolygonMesh cube = test::cube();
  const LimitResult r = limit_positions(cube, catmull_clark_scheme());
  Vec3 centre;
  for (const Vec3& p : cube.positions) centre += (1.0 / 8.0) * p;
  for (std::size_t v = 0; v < cube.positions.size(); ++v) {
    const Vec3 out = cube.positions[v] - centre;
    EXPECT_NEAR(dot(r.normals[v], (1.0 / norm(out)) * out), 1.0, 1e-12) << "vertex " << v;
  }
}

}  // namespace
}  // namespace subdiv
