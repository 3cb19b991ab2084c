// The piecewise-smooth rules (Biermann, Levin and Zorin 2000; Zorin's
// survey, sections 3.2 and 3.3): golden edge weights, the regular case
// giving back the standard rules bit for bit, only the touched vertices
// moving, the spectra the rules were designed for, and the geometry they fix
// (no kink at extraordinary boundary vertices, no flip at concave corners).

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>

#include "refine/piecewise_smooth.h"
#include "subdiv/analysis/analyze.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

constexpr double kPi = std::numbers::pi;

RefineOptions rules(BoundaryRules r, int levels = 1) {
  RefineOptions o;
  o.levels = levels;
  o.boundary_rules = r;
  return o;
}

const Scheme& scheme_for(SplitRule split) { return split == SplitRule::quad ? catmull_clark_scheme() : loop_scheme(); }

// A fan of k faces around a boundary vertex (the centre), `rings` faces deep,
// with heights that make it a generic surface.
RingMesh lifted_fan(SplitRule split, Configuration c, int rings, unsigned seed) {
  RingMesh fan = ring_mesh(split, c, rings);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  for (Vec3& p : fan.mesh.positions) p.z = 0.4 * p.x * p.x - 0.3 * p.x * p.y + 0.2 * p.y + jitter(random);
  fan.mesh.positions[static_cast<std::size_t>(fan.centre)].z = 0.0;
  return fan;
}

// The row of child vertex `child` as a map vertex -> weight.
std::map<Index, double> row_of(const StencilTable& t, Index child) {
  std::map<Index, double> row;
  const auto v = t.row_vertices(child);
  const auto w = t.row_weights(child);
  for (std::size_t i = 0; i < v.size(); ++i) row[v[i]] += w[i];
  return row;
}

// --- golden weights --------------------------------------------------------

TEST(PiecewiseSmooth, GammaAtTheRegularSectorIsThreeEighths) {
  EXPECT_DOUBLE_EQ(loop_gamma(kPi / 3), 0.375);
  EXPECT_DOUBLE_EQ(catmull_clark_gamma(kPi / 2), 0.375);
  EXPECT_DOUBLE_EQ(loop_gamma(kPi), 0.75);
  EXPECT_DOUBLE_EQ(catmull_clark_gamma(kPi), 0.625);
}

// The edge point of every smooth edge at the boundary centre of a fan with
// k faces: 3/4 - gamma on the centre, gamma on the other end, and the
// standard weights on the rest (Loop 1/8, 1/8; Catmull-Clark 1/16 on the
// four other corners of the two quads).
TEST(PiecewiseSmooth, EdgeWeightsNextToABoundaryVertex) {
  for (const SplitRule split : {SplitRule::triangle, SplitRule::quad}) {
    for (int k = 2; k <= 7; ++k) {
      SCOPED_TRACE(std::string(to_string(split)) + " k=" + std::to_string(k));
      const RingMesh fan = ring_mesh(split, {Configuration::Kind::boundary, k}, 2);
      const Scheme& scheme = scheme_for(split);
      const auto tables = refine_stencils(fan.mesh, scheme, rules(BoundaryRules::piecewise_smooth));
      const MeshTopology t(fan.mesh);
      const double theta = kPi / k;
      const double gamma = split == SplitRule::quad ? catmull_clark_gamma(theta) : loop_gamma(theta);
      const Index edge_points = split == SplitRule::quad ? t.face_count() : 0;
      int checked = 0;
      for (const Index e : t.vertex_edges(fan.centre)) {
        if (t.is_boundary_edge(e)) continue;
        const Index w = t.other_vertex(e, fan.centre);
        const auto row = row_of(tables[0], edge_points + e);
        EXPECT_NEAR(row.at(fan.centre), 0.75 - gamma, 1e-15);
        EXPECT_NEAR(row.at(w), gamma, 1e-15);
        double rest = 0.0;
        for (const auto& [v, weight] : row) {
          if (v == fan.centre || v == w) continue;
          EXPECT_NEAR(weight, split == SplitRule::quad ? 1.0 / 16 : 1.0 / 8, 1e-15) << "vertex " << v;
          rest += weight;
        }
        EXPECT_NEAR(rest, 0.25, 1e-15);
        EXPECT_EQ(row.size(), split == SplitRule::quad ? 6u : 4u);
        ++checked;
      }
      EXPECT_EQ(checked, k - 1);
    }
  }
}

// --- the regular case and locality ---------------------------------------

// With the piecewise-smooth rules a child vertex moves only when it is the
// edge point of a smooth edge with an end on the boundary whose sector is
// not regular (Loop: 3 faces, Catmull-Clark: 2); every other vertex,
// including all of those at regular boundary vertices, is bit for bit the
// standard one.
TEST(PiecewiseSmooth, OnlyEdgePointsNextToIrregularBoundaryVerticesMove) {
  std::vector<std::pair<std::string, PolygonMesh>> meshes;
  meshes.emplace_back("quad grid", test::quad_grid(5, 4));
  meshes.emplace_back("triangle grid", test::triangle_grid(5, 4));
  for (int k = 1; k <= 5; ++k) {
    meshes.emplace_back("quad fan k=" + std::to_string(k),
                        lifted_fan(SplitRule::quad, {Configuration::Kind::boundary, k}, 3, 11u + k).mesh);
    meshes.emplace_back("triangle fan k=" + std::to_string(k),
                        lifted_fan(SplitRule::triangle, {Configuration::Kind::boundary, k}, 3, 19u + k).mesh);
  }
  std::mt19937 random(7);
  std::uniform_real_distribution<double> height(-1.0, 1.0);
  int moved_total = 0;
  for (auto& [name, mesh] : meshes) {
    SCOPED_TRACE(name);
    for (Vec3& p : mesh.positions) p.z += height(random);
    const bool quads = mesh.face_size(0) == 4;
    const Scheme& scheme = quads ? catmull_clark_scheme() : loop_scheme();
    const Index regular = quads ? 2 : 3;
    const MeshTopology t(mesh);
    const Index edge_points = quads ? t.face_count() : 0;
    std::set<Index> predicted;
    for (Index e = 0; e < t.edge_count(); ++e) {
      if (t.edge_face_count(e) != 2) continue;
      for (const Index v : t.edge_vertices(e))
        if (t.vertex_kind(v) == VertexKind::boundary && t.vertex_face_count(v) != regular) predicted.insert(edge_points + e);
    }
    const PolygonMesh standard = refine(mesh, scheme, rules(BoundaryRules::standard));
    const PolygonMesh smooth = refine(mesh, scheme, rules(BoundaryRules::piecewise_smooth));
    ASSERT_EQ(standard.vertex_count(), smooth.vertex_count());
    std::set<Index> moved;
    for (Index v = 0; v < standard.vertex_count(); ++v)
      if (!(standard.positions[static_cast<std::size_t>(v)] == smooth.positions[static_cast<std::size_t>(v)])) moved.insert(v);
    EXPECT_EQ(moved, predicted);
    moved_total += static_cast<int>(moved.size());
  }
  EXPECT_GT(moved_total, 20);  // the comparison is not vacuous
}

// --- the spectra the rules were designed for ------------------------------

// Boundary vertices with any number of faces: the subdominant pair is 1/2,
// 1/2 (the boundary curve's tangent and the cross-boundary direction) and
// Reif's criterion holds, where the standard rules lose that pair from
// k = 4 (Loop) and k = 3 (Catmull-Clark) on.
TEST(PiecewiseSmooth, BoundaryVerticesOfAnyValenceAreC1) {
  AnalysisOptions piecewise;
  piecewise.rules.boundary_rules = BoundaryRules::piecewise_smooth;
  for (const Scheme* scheme : {&loop_scheme(), &catmull_clark_scheme()}) {
    for (int k = 1; k <= 9; ++k) {
      SCOPED_TRACE(std::string(scheme->name) + " boundary k=" + std::to_string(k));
      const ConfigurationAnalysis a = analyze(*scheme, {Configuration::Kind::boundary, k}, piecewise);
      ASSERT_GE(a.leading.size(), 4u);
      EXPECT_NEAR(a.leading[1].real(), 0.5, 1e-12);
      EXPECT_NEAR(a.leading[2].real(), 0.5, 1e-12);
      EXPECT_LT(std::abs(a.leading[3]), 0.5 - 1e-3);
      EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << a.reason;
      const ConfigurationAnalysis standard = analyze(*scheme, {Configuration::Kind::boundary, k});
      const int first_irregular = scheme->split == SplitRule::quad ? 3 : 4;
      if (k >= first_irregular) {
        EXPECT_GT(std::abs(standard.leading[1]), 0.5 + 1e-3);
      }
    }
  }
}

// Concave corners: lambda_3 = 1/2 + (cos(pi/k) - cos(theta_k)) / 4 for Loop
// (survey, section 3.2, whose extracted text lost the parentheses; the first
// sine eigenvector x_i = sin(i pi / k) gives it directly) exceeds 1/2, so the
// corner is not tangent-plane continuous until the flatness modification
// scales it to 1/4.
TEST(PiecewiseSmooth, FlatnessMakesConcaveCornersC1) {
  for (const Scheme* scheme : {&loop_scheme(), &catmull_clark_scheme()}) {
    for (int k = 2; k <= 6; ++k) {
      SCOPED_TRACE(std::string(scheme->name) + " concave corner k=" + std::to_string(k));
      const Configuration corner{Configuration::Kind::corner, k, CornerType::concave};
      const auto spectrum = detail::flatness_spectrum(*scheme, k, 1.5 * kPi);
      if (scheme->split == SplitRule::triangle) {
        EXPECT_NEAR(spectrum->lambda3, 0.5 + (std::cos(kPi / k) - std::cos(1.5 * kPi / k)) / 4, 1e-12);
      }
      EXPECT_GT(spectrum->lambda3, 0.5);
      AnalysisOptions off;
      off.rules.boundary_rules = BoundaryRules::piecewise_smooth;
      off.rules.flatness = 0.0;
      const ConfigurationAnalysis flipped = analyze(*scheme, corner, off);
      EXPECT_NEAR(std::abs(flipped.leading[1]), spectrum->lambda3, 1e-10);
      EXPECT_NE(flipped.verdict, SmoothnessVerdict::c1);
      AnalysisOptions on = off;
      on.rules.flatness.reset();
      const ConfigurationAnalysis fixed = analyze(*scheme, corner, on);
      EXPECT_NEAR(fixed.leading[1].real(), 0.5, 1e-12);
      EXPECT_NEAR(fixed.leading[2].real(), 0.5, 1e-12);
      EXPECT_NEAR(std::abs(fixed.leading[3]), 0.25, 1e-12);
      EXPECT_EQ(fixed.verdict, SmoothnessVerdict::c1) << fixed.reason;
    }
  }
}

// --- geometry -------------------------------------------------------------

// The faces of the one-ring around the centre, in the order of the local
// subdivision matrix: centre 0, then the ring counter-clockwise (quads: edge
// neighbour, face-opposite vertex, ...; boundary fans end with the last edge
// neighbour).
std::vector<std::vector<int>> one_ring_faces(SplitRule split, int k, bool closed) {
  std::vector<std::vector<int>> faces;
  const int step = split == SplitRule::quad ? 2 : 1;
  const int ring = closed ? step * k : step * k + 1;
  for (int j = 0; j < k; ++j) {
    const int e = 1 + step * j;
    const int next = 1 + (step * (j + 1)) % (closed ? ring : ring + 1);
    if (split == SplitRule::quad) faces.push_back({0, e, e + 1, next});
    else faces.push_back({0, e, next});
  }
  return faces;
}

Vec3 face_normal(const Eigen::MatrixXd& p, const std::vector<int>& face) {
  Vec3 n;
  for (std::size_t i = 0; i < face.size(); ++i) {
    const auto a = p.row(face[i]), b = p.row(face[(i + 1) % face.size()]);
    n += cross(Vec3{a(0), a(1), a(2)}, Vec3{b(0), b(1), b(2)});
  }
  return n;
}

// The one-ring of a configuration lifted out of its plane by a generic
// height, then subdivided `levels` times with the configuration's local
// subdivision matrix (read off the refinement itself).
Eigen::MatrixXd subdivided_ring(const Scheme& scheme, const Configuration& c, const RefineOptions& rules, int levels,
                                double lift) {
  const LocalSubdivisionMatrix m = local_subdivision_matrix(scheme, c, 1, rules);
  Eigen::MatrixXd p(m.S.rows(), 3);
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    const Vec3 q = m.layout[static_cast<std::size_t>(i)];
    p.row(i) << q.x, q.y, lift * (0.7 * q.x * q.x - 0.4 * q.x * q.y + 0.3 * q.y * q.y + 0.25 * q.x + 0.1 * std::sin(3.0 * i));
  }
  for (int l = 0; l < levels; ++l) {
    p = m.S * p;
    const Eigen::RowVector3d centre = p.row(0);
    p.rowwise() -= centre;  // follow the centre
    p /= p.rowwise().norm().maxCoeff();  // and keep the ring at unit size
  }
  return p;
}

// The largest angle between the normals of the one-ring's faces.
double normal_spread(const Eigen::MatrixXd& p, const std::vector<std::vector<int>>& faces) {
  std::vector<Vec3> normals;
  for (const auto& f : faces) {
    const Vec3 n = face_normal(p, f);
    normals.push_back((1.0 / norm(n)) * n);
  }
  double spread = 0.0;
  for (const Vec3& x : normals)
    for (const Vec3& y : normals) spread = std::max(spread, std::atan2(norm(cross(x, y)), dot(x, y)));
  return spread;
}

double boundary_spread(const Scheme& scheme, int k, BoundaryRules r, int levels) {
  const Eigen::MatrixXd p = subdivided_ring(scheme, {Configuration::Kind::boundary, k}, rules(r), levels, 1.0);
  return normal_spread(p, one_ring_faces(scheme.split, k, false));
}

// The survey's kink: around an extraordinary boundary vertex the normals of
// the faces converge to one direction, geometrically, with the
// piecewise-smooth rules. With the standard rules the analysis
// (`subdiv analyze -s loop --boundary -k 1..9`, `-s catmull-clark
// --boundary -k 1..8`) finds:
// - Loop k <= 5, Catmull-Clark k <= 3: C1.
// - Loop k = 6, Catmull-Clark k = 4: lambda_2 = |lambda_3| = 1/2 with a
//   Jordan block (Reif's eigenvalue condition fails); the normals close
//   only like 1/n.
// - Loop k >= 7, Catmull-Clark k >= 5: the eigenvalue condition holds, with
//   lambda_1 > lambda_2 > |lambda_3| = 1/2 (Loop k = 7: 0.6002, 0.5309, 0.5;
//   Catmull-Clark k = 5: 0.6263, 0.5500, 0.5), but the characteristic map is
//   not regular: both subdominant eigenvalues exceed the boundary curve's
//   1/2, so their eigenvectors vanish on the boundary curve and the map
//   collapses it to the centre (18 degenerate faces of the refined map).
//   The verdict is inconclusive, not C1; for Loop k = 7..9 the faces'
//   normals settle at distinct directions (checked below).
TEST(PiecewiseSmooth, ExtraordinaryBoundaryVerticesHaveOneNormal) {
  for (const Scheme* scheme : {&loop_scheme(), &catmull_clark_scheme()}) {
    for (int k = 2; k <= 8; ++k) {
      SCOPED_TRACE(std::string(scheme->name) + " boundary k=" + std::to_string(k));
      const double at40 = boundary_spread(*scheme, k, BoundaryRules::piecewise_smooth, 40);
      const double at80 = boundary_spread(*scheme, k, BoundaryRules::piecewise_smooth, 80);
      EXPECT_LT(at80, 0.03);
      EXPECT_LT(at80, 0.2 * at40 + 1e-15);
    }
  }
  for (int k = 7; k <= 9; ++k) {
    SCOPED_TRACE("loop standard boundary k=" + std::to_string(k));
    const double at40 = boundary_spread(loop_scheme(), k, BoundaryRules::standard, 40);
    const double at80 = boundary_spread(loop_scheme(), k, BoundaryRules::standard, 80);
    EXPECT_GT(at80, 0.05);        // a kink: the faces keep distinct normals
    EXPECT_GT(at80, 0.9 * at40);  // and it does not close
  }
  const std::pair<const Scheme*, int> jordan[] = {{&loop_scheme(), 6}, {&catmull_clark_scheme(), 4}};
  for (const auto& [scheme, k] : jordan) {
    SCOPED_TRACE(std::string(scheme->name) + " boundary k=" + std::to_string(k));
    EXPECT_GT(boundary_spread(*scheme, k, BoundaryRules::standard, 80),
              1000.0 * boundary_spread(*scheme, k, BoundaryRules::piecewise_smooth, 80));
  }
}

// Concave corners (the one-ring of a 270-degree corner lifted out of its
// plane, 40 steps): the standard rules turn faces over (their normals point
// down even when the patch is planar), the piecewise-smooth rules without
// flatness fold the surface (the faces around the corner meet at about a
// right angle however far one refines), and the flatness modification gives
// one normal with every face the right way up.
TEST(PiecewiseSmooth, ConcaveCornersNeitherFlipNorFold) {
  for (const Scheme* scheme : {&loop_scheme(), &catmull_clark_scheme()}) {
    for (int k = 2; k <= 6; ++k) {
      SCOPED_TRACE(std::string(scheme->name) + " concave corner k=" + std::to_string(k));
      const Configuration corner{Configuration::Kind::corner, k, CornerType::concave};
      const auto faces = one_ring_faces(scheme->split, k, false);
      auto faces_down = [&](const Eigen::MatrixXd& p) {
        int down = 0;
        for (const auto& f : faces) down += face_normal(p, f).z < 0.0;
        return down;
      };
      RefineOptions flat = rules(BoundaryRules::piecewise_smooth);
      RefineOptions folded = flat;
      folded.flatness = 0.0;
      for (const double lift : {0.0, 0.5}) {
        const Eigen::MatrixXd good = subdivided_ring(*scheme, corner, flat, 40, lift);
        EXPECT_EQ(faces_down(good), 0);
        EXPECT_LT(normal_spread(good, faces), 1e-9);
        EXPECT_EQ(faces_down(subdivided_ring(*scheme, corner, folded, 40, lift)), 0);
      }
      EXPECT_GT(normal_spread(subdivided_ring(*scheme, corner, folded, 40, 0.5), faces), 1.0);
      const bool flips = scheme->split == SplitRule::triangle ? k <= 4 : k == 2;
      if (flips) {
        EXPECT_GT(faces_down(subdivided_ring(*scheme, corner, rules(BoundaryRules::standard), 40, 0.0)), 0);
      }
    }
  }
}

// The same on real meshes: a planar fan around a 270-degree corner, three
// rings deep, refined five levels with refine(). With the standard rules
// faces near the corner turn over (normal down): measured 48 faces for Loop
// k = 2, 1 for Loop k = 3, 2 for Catmull-Clark k = 2 (Loop k = 4, which the
// local matrices flip after more steps, none yet); with the
// piecewise-smooth rules, with or without flatness, none do. Lifted out of
// the plane, the faces around the corner fold without flatness (the spread
// of their normals grows, 0.7 .. 1.6 rad from level 2 to 6) and close to one
// normal with it (the spread halves a level, about 0.01 rad at level 6).
int faces_down(const PolygonMesh& m) {
  int down = 0;
  for (Index f = 0; f < m.face_count(); ++f) {
    Vec3 n;
    const auto vs = m.face(f);
    for (std::size_t i = 0; i < vs.size(); ++i)
      n += cross(m.positions[static_cast<std::size_t>(vs[i])], m.positions[static_cast<std::size_t>(vs[(i + 1) % vs.size()])]);
    down += n.z < 0.0;
  }
  return down;
}

// The largest angle between the normals of the faces at v.
double spread_at(const PolygonMesh& m, Index v) {
  const MeshTopology t(m);
  std::vector<Vec3> normals;
  for (const Index c : t.vertex_corners(v)) {
    Vec3 n;
    const auto vs = m.face(t.corner_face(c));
    for (std::size_t i = 0; i < vs.size(); ++i)
      n += cross(m.positions[static_cast<std::size_t>(vs[i])], m.positions[static_cast<std::size_t>(vs[(i + 1) % vs.size()])]);
    normals.push_back((1.0 / norm(n)) * n);
  }
  double spread = 0.0;
  for (const Vec3& x : normals)
    for (const Vec3& y : normals) spread = std::max(spread, std::atan2(norm(cross(x, y)), dot(x, y)));
  return spread;
}

TEST(PiecewiseSmooth, RefinedConcaveCornerFansNeitherFlipNorFold) {
  for (const Scheme* scheme : {&loop_scheme(), &catmull_clark_scheme()}) {
    for (int k = 2; k <= 4; ++k) {
      SCOPED_TRACE(std::string(scheme->name) + " concave corner fan k=" + std::to_string(k));
      const RingMesh fan = ring_mesh(scheme->split, {Configuration::Kind::corner, k, CornerType::concave}, 3);
      const int levels = 5;
      RefineOptions flat = rules(BoundaryRules::piecewise_smooth, levels);
      RefineOptions folded = flat;
      folded.flatness = 0.0;
      const int standard_down = faces_down(refine(fan.mesh, *scheme, rules(BoundaryRules::standard, levels)));
      const int flat_down = faces_down(refine(fan.mesh, *scheme, flat));
      const int folded_down = faces_down(refine(fan.mesh, *scheme, folded));
      std::printf("  %s concave k=%d planar, %d levels: faces down standard %d, piecewise-smooth %d, without flatness %d\n",
                  std::string(scheme->name).c_str(), k, levels, standard_down, flat_down, folded_down);
      EXPECT_EQ(flat_down, 0);
      EXPECT_EQ(folded_down, 0);
      const bool flips = scheme->split == SplitRule::triangle ? k <= 3 : k == 2;
      if (flips) {
        EXPECT_GT(standard_down, 0);
      }

      RingMesh lifted = fan;
      for (Vec3& p : lifted.mesh.positions)
        p.z = 0.5 * (0.7 * p.x * p.x - 0.4 * p.x * p.y + 0.3 * p.y * p.y + 0.25 * p.x);
      double flat_previous = 0.0, fold_first = 0.0, fold_last = 0.0;
      for (int l = 2; l <= 6; ++l) {
        RefineOptions f = flat, u = folded;
        f.levels = u.levels = l;
        const PolygonMesh a = refine(lifted.mesh, *scheme, f), b = refine(lifted.mesh, *scheme, u);
        const Index corner = a.vertex_count() - lifted.mesh.vertex_count() + lifted.centre;
        const double with = spread_at(a, corner), without = spread_at(b, corner);
        std::printf("  %s concave k=%d lifted, level %d: spread of the corner's face normals %.3e with flatness, "
                    "%.3e without\n",
                    std::string(scheme->name).c_str(), k, l, with, without);
        if (l == 2) fold_first = without;
        fold_last = without;
        if (l > 2) {
          EXPECT_LT(with, 0.7 * flat_previous) << "level " << l;
        }
        flat_previous = with;
      }
      EXPECT_LT(flat_previous, 0.03);
      EXPECT_GT(fold_last, 0.9);          // the fold stays
      EXPECT_GE(fold_last, fold_first);  // and does not close
    }
  }
}

// An L-shaped patch: the n x n grid without its upper right quadrant (faces
// whose centroid has x and y above n/2), vertices renumbered; the reflex
// vertex (n/2, n/2) is tagged as a concave corner. `lift` bends it out of
// the plane.
PolygonMesh l_shape(bool triangles, int n, double lift) {
  const PolygonMesh grid = triangles ? test::triangle_grid(n, n) : test::quad_grid(n, n);
  const double half = 0.5 * n;
  PolygonMesh out;
  std::vector<Index> renumber(static_cast<std::size_t>(grid.vertex_count()), kInvalidIndex);
  std::vector<Index> face;
  for (Index f = 0; f < grid.face_count(); ++f) {
    Vec3 centroid;
    const auto vs = grid.face(f);
    for (const Index v : vs) centroid += (1.0 / static_cast<double>(vs.size())) * grid.positions[static_cast<std::size_t>(v)];
    if (centroid.x > half && centroid.y > half) continue;
    face.clear();
    for (const Index v : vs) {
      Index& r = renumber[static_cast<std::size_t>(v)];
      if (r == kInvalidIndex) {
        r = out.vertex_count();
        Vec3 p = grid.positions[static_cast<std::size_t>(v)];
        p.z = lift * ((p.x - half) * (p.x - half) - 0.5 * (p.y - half) * (p.y - half));
        out.positions.push_back(p);
      }
      face.push_back(r);
    }
    out.add_face(face);
  }
  for (Index v = 0; v < out.vertex_count(); ++v)
    if (out.positions[static_cast<std::size_t>(v)].x == half && out.positions[static_cast<std::size_t>(v)].y == half)
      out.tags.corners.push_back({v, kInfiniteSharpness, CornerType::concave, std::nullopt});
  return out;
}

// The engine applies the flatness modification in the fast path and in the
// stencil path alike, on an L-shaped patch; it changes the concave
// corner's neighbourhood and nothing far from it.
TEST(PiecewiseSmooth, FlatnessInTheFastAndStencilPaths) {
  for (const bool triangles : {false, true}) {
    SCOPED_TRACE(triangles ? "loop" : "catmull-clark");
    const Scheme& scheme = triangles ? loop_scheme() : catmull_clark_scheme();
    const PolygonMesh l = l_shape(triangles, 8, 0.1);
    RefineOptions flat = rules(BoundaryRules::piecewise_smooth, 3);
    RefineOptions folded = flat;
    folded.flatness = 0.0;
    const PolygonMesh fast = refine(l, scheme, flat);
    const StencilTable table = refine_stencil_table(l, scheme, flat);
    std::vector<Vec3> stencil(static_cast<std::size_t>(table.row_count()));
    table.apply(l.positions, stencil);
    ASSERT_EQ(stencil.size(), fast.positions.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < stencil.size(); ++i) worst = std::max(worst, norm(stencil[i] - fast.positions[i]));
    EXPECT_LT(worst, 1e-13);

    const PolygonMesh without = refine(l, scheme, folded);
    const Vec3 corner{4.0, 4.0, 0.0};
    // The modified one-ring lies within sqrt 2 / 2 of the corner after the
    // first step, and each later step's masks reach one (diagonal) edge of
    // that level further: sqrt 2 (1/2 + 1/2 + 1/4) < 2.5 in all.
    int moved = 0, far = 0;
    for (std::size_t i = 0; i < fast.positions.size(); ++i) {
      const Vec3 d = without.positions[i] - corner;
      const bool is_far = std::hypot(d.x, d.y) > 2.5;
      far += is_far;
      if (fast.positions[i] == without.positions[i]) continue;
      ++moved;
      EXPECT_FALSE(is_far) << "vertex " << i << " moved, far from the corner";
    }
    EXPECT_GT(moved, 3);
    EXPECT_GT(far, 100);
  }
}

// Measured corner angles: the L's reflex corner measures 270 degrees, the
// fixed concave angle, so both give the same surface; a corner tagged with
// another angle gives another surface.
TEST(PiecewiseSmooth, MeasuredCornerAngles) {
  const PolygonMesh l = l_shape(false, 4, 0.0);
  RefineOptions fixed = rules(BoundaryRules::piecewise_smooth, 2);
  RefineOptions measured = fixed;
  measured.corner_angles = CornerAngles::measured;
  const PolygonMesh a = refine(l, catmull_clark_scheme(), fixed);
  const PolygonMesh b = refine(l, catmull_clark_scheme(), measured);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.positions.size(); ++i) worst = std::max(worst, norm(a.positions[i] - b.positions[i]));
  EXPECT_LT(worst, 1e-12);
  PolygonMesh wider = l;
  wider.tags.corners.front().angle = 1.25 * kPi;
  const PolygonMesh c = refine(wider, catmull_clark_scheme(), fixed);
  worst = 0.0;
  for (std::size_t i = 0; i < a.positions.size(); ++i) worst = std::max(worst, norm(a.positions[i] - c.positions[i]));
  EXPECT_GT(worst, 1e-3);
}

}  // namespace
}  // namespace subdiv
