// Exact evaluation at an extraordinary Catmull-Clark corner
// and Loop corner (src/analysis/extraordinary_patch.h): at valence 4 the
// Catmull-Clark patch is the bicubic B-spline; at valences 3..12 both equal
// the schemes' own refinement followed by the closed-form limit masks at
// every level-3 vertex of the face; derivatives match finite differences.
#include "analysis/extraordinary_patch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "analysis/patch_basis.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/refine/configuration.h"
#include "subdiv/refine/refine.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

/// The ring mesh the patch's model is made on, with random heights, and the
/// model face's ring in the patch's order.
struct Model {
  RingMesh ring;
  std::vector<Index> face_ring_vertices;
  Vec3 u, v;  // layout of the face's next and previous corners (the centre is at the origin)
};

Model model(SplitRule split, int valence, std::mt19937& random) {
  Configuration configuration;
  configuration.kind = Configuration::Kind::interior;
  configuration.k = valence;
  Model m{ring_mesh(split, configuration, 4), {}, {}, {}};
  std::uniform_real_distribution<double> height(-0.5, 0.5);
  for (Vec3& p : m.ring.mesh.positions) p.z = height(random);
  const MeshTopology topology(m.ring.mesh);
  const Index corner = topology.vertex_corners(m.ring.centre)[0];
  m.face_ring_vertices = face_ring(topology, corner)->vertices;
  const auto layout = [&](Index c) {
    Vec3 p = m.ring.mesh.positions[static_cast<std::size_t>(topology.corner_vertex(c))];
    p.z = 0;
    return p;
  };
  m.u = layout(topology.corner_next(corner));
  m.v = layout(topology.corner_prev(corner));
  return m;
}

std::vector<Vec3> control_points(const Model& m) {
  std::vector<Vec3> points;
  for (const Index v : m.face_ring_vertices) points.push_back(m.ring.mesh.positions[static_cast<std::size_t>(v)]);
  return points;
}

TEST(ExtraordinaryPatch, ValenceFourIsTheBicubicSpline) {
  std::mt19937 random(5);
  const ExtraordinaryPatch patch(SplitRule::quad, 4);
  const Model m = model(SplitRule::quad, 4, random);
  const std::vector<Vec3> ring = control_points(m);
  // The 16 points by their grid coordinates in the face's frame.
  std::array<Vec3, 16> grid{};
  int found = 0;
  for (const Vec3& p : ring) {
    const double i = dot(p, m.u) / dot(m.u, m.u), j = dot(p, m.v) / dot(m.v, m.v);
    const auto index = static_cast<std::size_t>((std::lround(i) + 1) + 4 * (std::lround(j) + 1));
    grid[index] = p;
    ++found;
  }
  ASSERT_EQ(found, 16);
  // Tolerances relative to the control points' extent.
  double extent = 0.0;
  for (const Vec3& p : ring) extent = std::max(extent, norm(p));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::array<double, 2>> parameters = {{1.0, 1.0}, {0.5, 0.0}, {1e-9, 3e-9}, {0.3, 0.0}, {1e-300, 0.0}};
  for (int i = 0; i < 20; ++i) parameters.push_back({unit(random), unit(random)});
  for (const auto& [s, t] : parameters) {
    const PatchPoint p = patch.evaluate(ring, s, t);
    const PatchWeights<16> w = bicubic_bspline_weights(s, t);
    Vec3 position{}, du{}, dv{}, duu{}, duv{}, dvv{};
    for (std::size_t k = 0; k < 16; ++k) {
      position = position + w.value[k] * grid[k];
      du = du + w.du[k] * grid[k];
      dv = dv + w.dv[k] * grid[k];
      duu = duu + w.duu[k] * grid[k];
      duv = duv + w.duv[k] * grid[k];
      dvv = dvv + w.dvv[k] * grid[k];
    }
    EXPECT_LT(norm(p.position - position), 1e-13 * extent) << "(" << s << ", " << t << ")";
    EXPECT_LT(norm(p.du - du), 1e-12 * extent) << "(" << s << ", " << t << ")";
    EXPECT_LT(norm(p.dv - dv), 1e-12 * extent) << "(" << s << ", " << t << ")";
    EXPECT_LT(norm(p.duu - duu), 1e-11 * extent) << "(" << s << ", " << t << ")";
    EXPECT_LT(norm(p.duv - duv), 1e-11 * extent) << "(" << s << ", " << t << ")";
    EXPECT_LT(norm(p.dvv - dvv), 1e-11 * extent) << "(" << s << ", " << t << ")";
  }
}

/// At valences 3..12 the patch equals the scheme's refinement followed by
/// its closed-form limit masks at every level-3 vertex of the face.
void expect_patch_equals_refined_limits(SplitRule split, const Scheme& scheme) {
  std::mt19937 random(9);
  const bool quads = split == SplitRule::quad;
  for (int valence = 3; valence <= 12; ++valence) {
    const ExtraordinaryPatch patch(split, valence);
    // Loop's matrix at valence 3 is defective (no eigenbasis).
    EXPECT_EQ(patch.uses_eigenbasis(), quads || valence != 3) << "valence " << valence;
    const Model m = model(split, valence, random);
    const std::vector<Vec3> ring = control_points(m);
    RefineOptions options;
    options.levels = 3;
    const PolygonMesh refined = refine(m.ring.mesh, scheme, options);
    const LimitResult limit = limit_positions(refined, scheme);
    // Within the face's sector the layout is linear, and a level-3 vertex
    // sits at its parameter: layout p / 8 = s u + t v.
    const std::vector<Vec3> layout = child_layout(split, m.ring, 3);
    const double uu = dot(m.u, m.u), uv = dot(m.u, m.v), vv = dot(m.v, m.v);
    int inside = 0;
    for (std::size_t i = 0; i < layout.size(); ++i) {
      const Vec3 p{layout[i].x, layout[i].y, 0.0};
      const double pu = dot(p, m.u), pv = dot(p, m.v), det = uu * vv - uv * uv;
      const double s = (pu * vv - pv * uv) / det, t = (pv * uu - pu * uv) / det;
      if (s < -1e-9 || t < -1e-9 || (quads ? std::max(s, t) : s + t) > 1 + 1e-9) continue;
      ++inside;
      const double ds = std::round(s * 8) / 8, dt = std::round(t * 8) / 8;
      ASSERT_NEAR(s, ds, 1e-9);
      ASSERT_NEAR(t, dt, 1e-9);
      const PatchPoint q = patch.evaluate(ring, ds, dt);
      EXPECT_LT(norm(q.position - limit.positions[i]), 1e-12) << "valence " << valence << " at (" << ds << ", " << dt << ")";
    }
    // The level-3 grid of the face: 9 x 9 points, or 9 + 8 + ... + 1 = 45.
    EXPECT_EQ(inside, quads ? 81 : 45) << "valence " << valence;
  }
}

TEST(ExtraordinaryPatch, CatmullClarkEqualsRefinementAndLimitMasks) {
  expect_patch_equals_refined_limits(SplitRule::quad, catmull_clark_scheme());
}

TEST(ExtraordinaryPatch, LoopEqualsRefinementAndLimitMasks) {
  expect_patch_equals_refined_limits(SplitRule::triangle, loop_scheme());
}

TEST(ExtraordinaryPatch, DerivativesMatchFiniteDifferences) {
  std::mt19937 random(3);
  for (const SplitRule split : {SplitRule::quad, SplitRule::triangle}) {
  for (const int valence : {3, 5, 8}) {
    const ExtraordinaryPatch patch(split, valence);
    const std::vector<Vec3> ring = control_points(model(split, valence, random));
    // Points in each regular child, at several levels (the last two in the
    // triangle's middle child).
    for (const auto& [s, t] : std::vector<std::array<double, 2>>{{0.7, 0.2}, {0.2, 0.6}, {0.05, 0.02}, {0.3, 0.3}, {0.03, 0.04}}) {
      const double h = 1e-6 * std::max(s, t);
      const PatchPoint p = patch.evaluate(ring, s, t);
      const PatchPoint ps = patch.evaluate(ring, s + h, t), ms = patch.evaluate(ring, s - h, t);
      const PatchPoint pt = patch.evaluate(ring, s, t + h), mt = patch.evaluate(ring, s, t - h);
      const double scale = norm(p.du) + norm(p.dv);
      EXPECT_LT(norm(p.du - (1.0 / (2 * h)) * (ps.position - ms.position)), 1e-6 * scale) << valence << " (" << s << ", " << t << ")";
      EXPECT_LT(norm(p.dv - (1.0 / (2 * h)) * (pt.position - mt.position)), 1e-6 * scale) << valence << " (" << s << ", " << t << ")";
      const double second = norm(p.duu) + norm(p.duv) + norm(p.dvv);
      EXPECT_LT(norm(p.duu - (1.0 / (2 * h)) * (ps.du - ms.du)), 1e-5 * second) << valence << " (" << s << ", " << t << ")";
      EXPECT_LT(norm(p.duv - (1.0 / (2 * h)) * (pt.du - mt.du)), 1e-5 * second) << valence << " (" << s << ", " << t << ")";
      EXPECT_LT(norm(p.dvv - (1.0 / (2 * h)) * (pt.dv - mt.dv)), 1e-5 * second) << valence << " (" << s << ", " << t << ")";
    }
  }
  }
}

/// Below the cached levels the patch steps the ring down; there it must
/// equal the cached levels on the ring subdivided kCachedLevels times
/// (A^L C), at (2^L s, 2^L t) with derivatives of order d scaled by
/// 2^(L d): the patch's self-similarity.
TEST(ExtraordinaryPatch, DeepLevelsEqualTheCachedRouteOnTheSubdividedRing) {
  std::mt19937 random(11);
  constexpr int L = ExtraordinaryPatch::kCachedLevels;
  for (const SplitRule split : {SplitRule::quad, SplitRule::triangle}) {
    for (const int valence : {3, 5, 8, 12}) {
      const ExtraordinaryPatch patch(split, valence);
      // The ring moved so that the corner's limit is the origin (the
      // surface moves with it): A^L of it keeps its digits.
      std::vector<Vec3> ring = control_points(model(split, valence, random));
      const Vec3 limit = patch.evaluate(ring, 0.0, 0.0).position;
      for (Vec3& p : ring) p = p - limit;
      Eigen::MatrixXd power = Eigen::MatrixXd::Identity(patch.size(), patch.size());
      for (int i = 0; i < L; ++i) power = patch.subdivision_matrix() * power;
      std::vector<Vec3> deeper(ring.size());
      for (std::size_t r = 0; r < ring.size(); ++r)
        for (std::size_t c = 0; c < ring.size(); ++c)
          deeper[r] += power(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) * ring[c];
      const double first = std::ldexp(1.0, L), second = first * first;
      for (int level = L; level < 2 * L; ++level) {
        for (const auto& [s0, t0] : std::vector<std::array<double, 2>>{{0.7, 0.2}, {0.2, 0.6}, {0.3, 0.3}}) {
          const double s = std::ldexp(s0, -level), t = std::ldexp(t0, -level);
          const PatchPoint deep = patch.evaluate(ring, s, t);
          const PatchPoint cached = patch.evaluate(deeper, first * s, first * t);
          const std::string where = "valence " + std::to_string(valence) + " level " + std::to_string(level);
          EXPECT_LT(norm(deep.position - cached.position), 1e-12) << where;
          const double d1 = norm(deep.du) + norm(deep.dv);
          EXPECT_LT(norm(deep.du - first * cached.du), 1e-9 * d1) << where;
          EXPECT_LT(norm(deep.dv - first * cached.dv), 1e-9 * d1) << where;
          const double d2 = norm(deep.duu) + norm(deep.duv) + norm(deep.dvv);
          EXPECT_LT(norm(deep.duu - second * cached.duu), 1e-8 * d2) << where;
          EXPECT_LT(norm(deep.duv - second * cached.duv), 1e-8 * d2) << where;
          EXPECT_LT(norm(deep.dvv - second * cached.dvv), 1e-8 * d2) << where;
        }
      }
    }
  }
}

/// The two routes to the same formula, A^n by products (evaluate, down to
/// 2^-(2 kCachedLevels) of the corner) and A^n through the eigenbasis,
/// agree at every level they share; derivatives relative to their own size.
TEST(ExtraordinaryPatch, ProductsAndEigenbasisRoutesAgree) {
  std::mt19937 random(17);
  for (const SplitRule split : {SplitRule::quad, SplitRule::triangle}) {
    for (const int valence : {3, 5, 7, 12}) {
      const ExtraordinaryPatch patch(split, valence);
      const std::vector<Vec3> ring = control_points(model(split, valence, random));
      // Without an eigenbasis (Loop at valence 3) the reference takes A^n
      // by products, level by level, and loses second derivatives' digits
      // as 4^n: compared while those stay below 1e-9.
      const int levels = patch.uses_eigenbasis() ? 2 * ExtraordinaryPatch::kCachedLevels : 11;
      for (int level = 0; level < levels; ++level) {
        for (const auto& [s0, t0] : std::vector<std::array<double, 2>>{{0.7, 0.2}, {0.2, 0.6}, {0.3, 0.3}, {0.9, 0.0}}) {
          const double s = std::ldexp(s0, -level), t = std::ldexp(t0, -level);
          const PatchPoint a = patch.evaluate(ring, s, t);
          const PatchPoint b = patch.evaluate_in_eigenbasis(ring, s, t);
          const std::string where = "valence " + std::to_string(valence) + " level " + std::to_string(level) + " (" +
                                    std::to_string(s0) + ", " + std::to_string(t0) + ")";
          EXPECT_LT(norm(a.position - b.position), 1e-12) << where;
          const double d1 = norm(b.du) + norm(b.dv);
          EXPECT_GT(d1, 0.0) << where;
          EXPECT_LT(norm(a.du - b.du), 1e-9 * d1) << where;
          EXPECT_LT(norm(a.dv - b.dv), 1e-9 * d1) << where;
          const double d2 = norm(b.duu) + norm(b.duv) + norm(b.dvv);
          EXPECT_LT(norm(a.duu - b.duu), 1e-8 * d2) << where;
          EXPECT_LT(norm(a.duv - b.duv), 1e-8 * d2) << where;
          EXPECT_LT(norm(a.dvv - b.dvv), 1e-8 * d2) << where;
        }
      }
    }
  }
}

/// Close to the corner, at any depth and through every route, the surface
/// goes to the corner's limit (lambda^n away) and its normal (du x dv) to
/// the normal of the scheme's tangent masks, as fast as the subsubdominant
/// eigenvalue allows (slowly at high valence: about 1e-5 at 2^-100 for
/// valence 12); second derivatives stay finite.
TEST(ExtraordinaryPatch, NearTheCornerNormalsApproachTheTangentMasks) {
  std::mt19937 random(19);
  for (const SplitRule split : {SplitRule::quad, SplitRule::triangle}) {
    const Scheme& scheme = split == SplitRule::quad ? catmull_clark_scheme() : loop_scheme();
    for (const int valence : {3, 5, 8, 12}) {
      const ExtraordinaryPatch patch(split, valence);
      const Model m = model(split, valence, random);
      const std::vector<Vec3> ring = control_points(m);
      const LimitResult limit = limit_positions(m.ring.mesh, scheme);
      const auto centre = static_cast<std::size_t>(m.ring.centre);
      for (const auto& [level, tolerance] : std::vector<std::pair<int, double>>{{100, 1e-3}, {600, 1e-9}}) {
        for (const auto& [s0, t0] : std::vector<std::array<double, 2>>{{0.7, 0.2}, {0.2, 0.6}, {0.3, 0.3}}) {
          const PatchPoint p = patch.evaluate(ring, std::ldexp(s0, -level), std::ldexp(t0, -level));
          const std::string where = "valence " + std::to_string(valence) + " level " + std::to_string(level);
          EXPECT_LT(norm(p.position - limit.positions[centre]), 1e-12) << where;
          // Each derivative scaled to its largest coordinate first: at 2^-600
          // they are far below (or above) what squares can hold.
          const auto scaled = [](Vec3 d) { return (1.0 / std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)})) * d; };
          const Vec3 n = cross(scaled(p.du), scaled(p.dv));
          ASSERT_GT(norm(n), 0.0) << where;
          EXPECT_LT(norm((1.0 / norm(n)) * n - limit.normals[centre]), tolerance) << where;
          for (const Vec3& d : {p.duu, p.duv, p.dvv})
            EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)) << where;
        }
      }
    }
  }
}

/// A mesh refined once has one extraordinary corner per face at most. Each
/// such face's ring, walked from that corner, must have the model's
/// signature, and the patch over it must give the mesh's closed-form limits
/// at the face's corners: (0, 0) at the extraordinary corner, (1, 0) at the
/// next corner, (0, 1) at the previous one.
void expect_mesh_faces_match_the_model(const PolygonMesh& control, SplitRule split, const Scheme& scheme, int valence) {
  RefineOptions options;
  options.levels = 1;
  const PolygonMesh mesh = test::jittered(refine(control, scheme, options), 17);
  const MeshTopology topology(mesh);
  const LimitResult limit = limit_positions(mesh, scheme);
  const ExtraordinaryPatch patch(split, valence);
  int faces = 0;
  for (Index c = 0; c < topology.corner_count(); ++c) {
    if (topology.valence(topology.corner_vertex(c)) != valence) continue;
    const std::optional<FaceRing> ring = face_ring(topology, c);
    ASSERT_TRUE(ring.has_value()) << "corner " << c;
    ASSERT_EQ(ring->signature, patch.signature()) << "corner " << c;
    std::vector<Vec3> points;
    for (const Index v : ring->vertices) points.push_back(mesh.positions[static_cast<std::size_t>(v)]);
    const auto limit_at = [&](Index corner) { return limit.positions[static_cast<std::size_t>(topology.corner_vertex(corner))]; };
    EXPECT_LT(norm(patch.evaluate(points, 0.0, 0.0).position - limit_at(c)), 1e-12) << "corner " << c;
    EXPECT_LT(norm(patch.evaluate(points, 1.0, 0.0).position - limit_at(topology.corner_next(c))), 1e-12) << "corner " << c;
    EXPECT_LT(norm(patch.evaluate(points, 0.0, 1.0).position - limit_at(topology.corner_prev(c))), 1e-12) << "corner " << c;
    ++faces;
  }
  EXPECT_GT(faces, 0);
}

TEST(ExtraordinaryPatch, MeshFacesMatchTheModel) {
  // The cube's corners have valence 3.
  expect_mesh_faces_match_the_model(test::cube(), SplitRule::quad, catmull_clark_scheme(), 3);
  // The octahedron's have valence 4 among Loop's regular 6.
  PolygonMesh octahedron;
  octahedron.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const std::array<Index, 3> face : std::vector<std::array<Index, 3>>{
           {0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}) {
    octahedron.face_indices.insert(octahedron.face_indices.end(), face.begin(), face.end());
    octahedron.face_offsets.push_back(static_cast<Index>(octahedron.face_indices.size()));
  }
  expect_mesh_faces_match_the_model(octahedron, SplitRule::triangle, loop_scheme(), 4);
}

TEST(ExtraordinaryPatch, RefusesBadInput) {
  EXPECT_THROW(ExtraordinaryPatch(SplitRule::quad, 2), InvalidInputError);
  EXPECT_THROW(ExtraordinaryPatch(SplitRule::dual, 5), InvalidInputError);
  EXPECT_EQ(ExtraordinaryPatch(SplitRule::triangle, 5).size(), 11);
  EXPECT_EQ(ExtraordinaryPatch(SplitRule::triangle, 3).size(), 9);
  const ExtraordinaryPatch patch(SplitRule::quad, 5);
  EXPECT_EQ(patch.size(), 18);
  EXPECT_THROW((void)patch.evaluate(std::vector<Vec3>(17), 0.5, 0.5), InvalidInputError);
  const std::vector<Vec3> ring(18);
  for (const auto& [s, t] : std::vector<std::array<double, 2>>{{-1.0, -1.0}, {-0.1, 0.5}, {1.5, 0.2}, {std::nan(""), 0.5}}) {
    EXPECT_THROW((void)patch.evaluate(ring, s, t), InvalidInputError) << s << ", " << t;
  }
  EXPECT_THROW((void)ExtraordinaryPatch(SplitRule::triangle, 5).evaluate(std::vector<Vec3>(11), 0.6, 0.6), InvalidInputError);
}

}  // namespace
}  // namespace subdiv
