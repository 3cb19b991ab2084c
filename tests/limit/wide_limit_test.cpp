// Generic limit masks over more than the one-ring (the Butterfly schemes,
// whose stencils reach one triangle past the edge), matched to the mesh face
// by face:
// - both schemes interpolate, so the limit of every vertex is the vertex
//   itself (an independent check of the limit masks and of the match);
// - limit normals against the refined surface (the mean of the face normals
//   around the vertex), closing level by level;
// - at a regular vertex (valence 6) the modified Butterfly's tangent plane
//   against central differences along the refined grid lines, and against
//   the exact normal of a cubic height field, which the 8-point rule
//   reproduces;
// - a vertex with another extraordinary vertex in its neighbourhood is not
//   matched, until refinement separates them;
// - for Loop and Catmull-Clark the match gives the one-ring results:
//   the canonical ring built by hand (centre, then counter-clockwise from
//   the first face's outgoing edge) with the analysis's masks, bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

std::string shared_mesh(const std::string& name) { return (std::filesystem::path(SUBDIV_SHARED_MESH_DIR) / name).string(); }

double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

Vec3 unit(const Vec3& v) { return (1.0 / norm(v)) * v; }

// The mean of the unit normals of the triangles around v.
Vec3 mean_face_normal(const PolygonMesh& m, const MeshTopology& t, Index v) {
  Vec3 sum;
  for (const Index c : t.vertex_corners(v)) {
    const auto f = m.face(t.corner_face(c));
    const Vec3 a = m.positions[static_cast<std::size_t>(f[0])], b = m.positions[static_cast<std::size_t>(f[1])],
               d = m.positions[static_cast<std::size_t>(f[2])];
    sum += unit(cross(b - a, d - a));
  }
  return unit(sum);
}

struct Case {
  std::string name;
  PolygonMesh mesh;
};

std::vector<Case> closed_triangle_meshes() {
  std::vector<Case> cases{{"triangulated cube", triangulate(test::cube())}};
  const std::string shared = shared_mesh("opensubdiv/loop_cube_asymmetric.obj");
  if (std::filesystem::exists(shared)) cases.push_back({"loop_cube_asymmetric", read_mesh(shared).mesh});
  return cases;
}

const Scheme* butterfly_schemes[] = {&butterfly_scheme(), &modified_butterfly_scheme()};

TEST(WideLimit, ButterflyMasksReachPastTheOneRing) {
  for (const Scheme* scheme : butterfly_schemes) {
    AnalysisOptions options;
    options.characteristic_map = false;
    const ConfigurationAnalysis a = analyze(*scheme, {Configuration::Kind::interior, 6}, options);
    ASSERT_TRUE(a.matrix.invariant) << scheme->name;
    EXPECT_GE(a.matrix.rings, 2) << scheme->name;
    // The eigensolver's limit mask is e_0 to rounding.
    ASSERT_TRUE(a.limit_mask) << scheme->name;
    Eigen::VectorXd e0 = Eigen::VectorXd::Zero(a.limit_mask->size());
    e0[0] = 1.0;
    EXPECT_LT((*a.limit_mask - e0).cwiseAbs().maxCoeff(), 1e-14) << scheme->name;
  }
}

TEST(WideLimit, ButterflyLimitPositionsAreTheVertices) {
  for (const Scheme* scheme : butterfly_schemes)
    for (const Case& c : closed_triangle_meshes()) {
      const LimitResult r = limit_positions(c.mesh, *scheme);
      EXPECT_EQ(r.approximated, 0) << scheme->name << " " << c.name;
      for (std::size_t v = 0; v < c.mesh.positions.size(); ++v) {
        EXPECT_EQ(r.sources[v], LimitSource::generic) << scheme->name << " " << c.name << " vertex " << v;
        EXPECT_EQ(r.positions[v].x, c.mesh.positions[v].x) << scheme->name << " " << c.name << " vertex " << v;
        EXPECT_EQ(r.positions[v].y, c.mesh.positions[v].y) << scheme->name << " " << c.name << " vertex " << v;
        EXPECT_EQ(r.positions[v].z, c.mesh.positions[v].z) << scheme->name << " " << c.name << " vertex " << v;
      }
    }
}

// The angle between the limit normal and the mean face normal at each input
// vertex after 1..6 steps: it shrinks by a quarter or more per level over
// the last three, and ends below 0.02 rad.
// Butterfly is C1 at valences 4 to 7 only (at 3 its subdominant 1/4 is
// triple): vertices elsewhere are not compared for it.
TEST(WideLimit, ButterflyNormalsAgreeWithTheRefinedSurface) {
  constexpr int kLevels = 6;
  for (const Scheme* scheme : butterfly_schemes)
    for (const Case& c : closed_triangle_meshes()) {
      const LimitResult r = limit_positions(c.mesh, *scheme);
      const MeshTopology coarse(c.mesh);
      std::vector<double> previous(c.mesh.positions.size(), 1e9);
      int compared = 0;
      for (int levels = 1; levels <= kLevels; ++levels) {
        RefineOptions o;
        o.levels = levels;
        const PolygonMesh fine = refine(c.mesh, *scheme, o);
        const MeshTopology t(fine);
        const Index first = fine.vertex_count() - c.mesh.vertex_count();  // vertex points come last
        for (Index v = 0; v < c.mesh.vertex_count(); ++v) {
          const int k = coarse.valence(v);
          if (scheme == &butterfly_scheme() && (k < 4 || k > 7)) continue;
          const Vec3 n = r.normals[static_cast<std::size_t>(v)];
          ASSERT_NEAR(norm(n), 1.0, 1e-12) << scheme->name << " " << c.name << " vertex " << v;
          const double angle = angle_between(n, mean_face_normal(fine, t, first + v));
          auto& p = previous[static_cast<std::size_t>(v)];
          // From level 4 on: the first levels are not yet asymptotic
          // (measured: Butterfly on the cube 0.042 rad at level 1, then
          // 0.055; the modified rules on loop_cube_asymmetric's valence-5
          // vertices 1.1e-4 at level 2, then 2.3e-4).
          if (levels >= 4) {
            EXPECT_LT(angle, 0.75 * p) << scheme->name << " " << c.name << " vertex " << v << " (valence " << k
                                       << ") level " << levels;
          }
          if (levels == kLevels)
            std::printf("[ MEASURED ] %s, %s, vertex %d (valence %d): limit normal vs mean face normal %.3g rad "
                        "(level %d), %.3g (level %d)\n",
                        std::string(scheme->name).c_str(), c.name.c_str(), v, k, p, levels - 1, angle, levels);
          p = angle;
          compared += levels == kLevels;
        }
      }
      EXPECT_GT(compared, 0) << scheme->name << " " << c.name;
      const double worst = *std::max_element(previous.begin(), previous.end(), [](double a, double b) {
        return (a < 1e8 ? a : 0.0) < (b < 1e8 ? b : 0.0);
      });
      EXPECT_LT(worst, 0.02) << scheme->name << " " << c.name;
    }
}

// A regular triangle grid lifted onto z = f(x, y), f cubic; the centre
// vertex has valence 6 and its whole neighbourhood is regular.
PolygonMesh cubic_height_field(int n) {
  PolygonMesh grid = test::triangle_grid(n, n);
  for (Vec3& p : grid.positions) {
    const double x = p.x - 0.5 * n, y = p.y - 0.5 * n;
    p.z = 0.1 * x + 0.05 * y + 0.04 * x * x - 0.03 * x * y + 0.02 * y * y + 0.004 * x * x * x - 0.003 * x * y * y;
  }
  return grid;
}

Vec3 cubic_normal_at_centre() { return unit({-0.1, -0.05, 1.0}); }  // the gradient at x = y = 0

TEST(WideLimit, RegularModifiedButterflyTangentsAgreeWithFiniteDifferences) {
  constexpr int kGrid = 10;
  const PolygonMesh grid = cubic_height_field(kGrid);
  const Index centre = (kGrid / 2) * (kGrid + 1) + kGrid / 2;
  ASSERT_EQ(grid.positions[static_cast<std::size_t>(centre)].x, 0.5 * kGrid);
  ASSERT_EQ(grid.positions[static_cast<std::size_t>(centre)].y, 0.5 * kGrid);
  ASSERT_EQ(MeshTopology(grid).valence(centre), 6);
  const LimitResult r = limit_positions(grid, modified_butterfly_scheme());
  ASSERT_EQ(r.sources[static_cast<std::size_t>(centre)], LimitSource::generic);
  const Vec3 n = r.normals[static_cast<std::size_t>(centre)];
  const Vec3 t1 = r.tangents1[static_cast<std::size_t>(centre)], t2 = r.tangents2[static_cast<std::size_t>(centre)];
  // The 8-point rule reproduces cubics: the tangent plane is the height
  // field's.
  EXPECT_LT(angle_between(n, cubic_normal_at_centre()), 1e-12);
  // Central differences along the two grid lines through the vertex on the
  // refined surface (interpolating: refined vertices lie on the limit
  // surface), spacing 2^-level.
  double previous = 1e9;
  for (int levels = 1; levels <= 4; ++levels) {
    RefineOptions o;
    o.levels = levels;
    const PolygonMesh fine = refine(grid, modified_butterfly_scheme(), o);
    const double h = std::ldexp(1.0, -levels);
    const Vec3 c = grid.positions[static_cast<std::size_t>(centre)];
    auto at = [&](double dx, double dy) {
      for (const Vec3& p : fine.positions)
        if (std::fabs(p.x - c.x - dx) < 1e-12 && std::fabs(p.y - c.y - dy) < 1e-12) return p;
      ADD_FAILURE() << "no refined vertex at offset " << dx << ", " << dy;
      return Vec3{};
    };
    const Vec3 du = at(h, 0) - at(-h, 0), dv = at(0, h) - at(0, -h);
    const Vec3 fd_normal = unit(cross(du, dv));
    const double angle = angle_between(n, fd_normal);
    // Each mask tangent lies in the difference plane.
    const double off_plane = std::max(std::fabs(dot(unit(t1), fd_normal)), std::fabs(dot(unit(t2), fd_normal)));
    EXPECT_LT(off_plane, std::sin(angle) + 1e-12) << "level " << levels;
    if (angle > 1e-13) {
      EXPECT_LT(angle, 0.5 * previous) << "level " << levels;
    }
    previous = angle;
    std::printf("[ MEASURED ] regular modified-butterfly tangent plane vs central differences, h = 2^-%d: %.3g rad\n",
                levels, angle);
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(WideLimit, NeighbourhoodsWithAnotherExtraordinaryVertexAreNotMatched) {
  // The triangulated cube: every vertex is extraordinary (valence 4 or 5)
  // and next to another; refinement separates them.
  const PolygonMesh cube = triangulate(test::cube());
  LimitOptions none;
  none.isolation_levels = 0;
  const LimitResult at_once = limit_positions(cube, modified_butterfly_scheme(), none);
  EXPECT_EQ(at_once.approximated, cube.vertex_count());
  LimitOptions one;
  one.isolation_levels = 1;
  EXPECT_EQ(limit_positions(cube, modified_butterfly_scheme(), one).approximated, 0);
  // Loop's one-ring masks need no separation.
  LimitOptions loop_none = none;
  loop_none.route = LimitRoute::generic;
  EXPECT_EQ(limit_positions(cube, loop_scheme(), loop_none).approximated, 0);
}

// The pre-generalisation one-ring: centre, then per face its outgoing
// neighbour (and for quads the opposite vertex), a boundary fan closed by
// the last face's incoming neighbour.
std::vector<Index> one_ring(const MeshTopology& t, Index v, bool quads) {
  std::vector<Index> ring{v};
  const auto corners = t.vertex_corners(v);
  for (std::size_t j = 0; j < corners.size(); ++j) {
    const Index next = t.corner_next(corners[j]);
    ring.push_back(t.corner_vertex(next));
    if (quads) ring.push_back(t.corner_vertex(t.corner_next(next)));
    if (t.vertex_kind(v) == VertexKind::boundary && j + 1 == corners.size())
      ring.push_back(t.corner_vertex(t.corner_prev(corners[j])));
  }
  return ring;
}

TEST(WideLimit, OneRingSchemesMatchAsBefore) {
  struct One {
    const Scheme* scheme;
    PolygonMesh mesh;
  };
  auto bumpy = [](PolygonMesh m) {
    for (Vec3& p : m.positions) p.z = 0.3 * std::sin(1.3 * p.x + 0.7 * p.y) + 0.1 * p.x * p.y;
    return m;
  };
  const One cases[] = {
      {&catmull_clark_scheme(), read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh},
      {&catmull_clark_scheme(), bumpy(test::quad_grid(4, 3))},
      {&loop_scheme(), read_mesh(test::bundled_path("tetrahedron.obj")).mesh},
      {&loop_scheme(), bumpy(triangulate(test::quad_grid(3, 3)))},
      {&loop_scheme(), bumpy(test::triangle_grid(3, 4))},
  };
  for (const One& c : cases) {
    const bool quads = c.scheme->split == SplitRule::quad;
    LimitOptions options;
    options.route = LimitRoute::generic;
    const LimitResult r = limit_positions(c.mesh, *c.scheme, options);
    RefineOptions o;
    o.levels = options.isolation_levels;
    const PolygonMesh fine = refine(c.mesh, *c.scheme, o);
    const MeshTopology t(fine);
    const Index first = fine.vertex_count() - c.mesh.vertex_count();
    AnalysisOptions a_options;
    a_options.characteristic_map = false;
    int compared = 0;
    for (Index i = 0; i < c.mesh.vertex_count(); ++i) {
      const Index v = first + i;
      const bool boundary = t.vertex_kind(v) == VertexKind::boundary;
      if (boundary && t.vertex_face_count(v) < 2) continue;  // corners keep their position
      EXPECT_EQ(r.sources[static_cast<std::size_t>(i)], LimitSource::generic) << c.scheme->name << " vertex " << i;
      const int k = boundary ? t.vertex_face_count(v) : t.valence(v);
      const ConfigurationAnalysis a = analyze(
          *c.scheme, {boundary ? Configuration::Kind::boundary : Configuration::Kind::interior, k}, a_options);
      ASSERT_EQ(a.matrix.rings, 1);
      const std::vector<Index> ring = one_ring(t, v, quads);
      ASSERT_EQ(static_cast<std::size_t>(a.limit_mask->size()), ring.size());
      Vec3 limit, t1, t2;
      for (std::size_t j = 0; j < ring.size(); ++j) {
        const Vec3 p = fine.positions[static_cast<std::size_t>(ring[j])];
        const auto e = static_cast<Eigen::Index>(j);
        limit += (*a.limit_mask)[e] * p;
        t1 += (*a.tangent_masks)[0][e] * p;
        t2 += (*a.tangent_masks)[1][e] * p;
      }
      const auto s = static_cast<std::size_t>(i);
      EXPECT_EQ(r.positions[s].x, limit.x) << c.scheme->name << " vertex " << i;
      EXPECT_EQ(r.positions[s].y, limit.y) << c.scheme->name << " vertex " << i;
      EXPECT_EQ(r.positions[s].z, limit.z) << c.scheme->name << " vertex " << i;
      // Tangents: the first as the mask gives it, the second oriented by
      // the faces.
      EXPECT_EQ(r.tangents1[s].x, t1.x) << c.scheme->name << " vertex " << i;
      EXPECT_EQ(r.tangents1[s].y, t1.y) << c.scheme->name << " vertex " << i;
      EXPECT_EQ(r.tangents1[s].z, t1.z) << c.scheme->name << " vertex " << i;
      const double sign = dot(r.tangents2[s], t2) < 0.0 ? -1.0 : 1.0;
      EXPECT_EQ(r.tangents2[s].x, sign * t2.x) << c.scheme->name << " vertex " << i;
      EXPECT_EQ(r.tangents2[s].y, sign * t2.y) << c.scheme->name << " vertex " << i;
      EXPECT_EQ(r.tangents2[s].z, sign * t2.z) << c.scheme->name << " vertex " << i;
      ++compared;
    }
    EXPECT_GT(compared, 0) << c.scheme->name;
  }
}

}  // namespace
}  // namespace subdiv
