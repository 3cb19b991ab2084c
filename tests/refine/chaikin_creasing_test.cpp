// OpenSubdiv's Chaikin creasing method (Sdc::Options::CREASE_CHAIKIN) against
// values computed by hand from Sdc::Crease's rules, and, where OpenSubdiv is
// installed, against OpenSubdiv itself on meshes the regression shapes do
// not cover (boundaries, four semi-sharp edges at a vertex, sharpness that
// decays at one end only, non-dyadic sharpness).
//
// Sdc::Crease::SubdivideEdgeSharpnessesAroundVertex, Chaikin: at a vertex
// whose semi-sharp edges (0 < s < 10) have sharpness s_1 .. s_n, n >= 2, the
// child of edge i at that vertex gets
//     max(0, 3/4 s_i + 1/4 (sum_{j != i} s_j) / (n - 1) - 1);
// with n = 1 it gets s_i - 1 (the uniform rule); smooth and infinitely
// sharp edges keep their sharpness and are not averaged in.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"
#include "support/scheme_by_name.h"
#include "support/test_meshes.h"

#ifdef SUBDIV_HAVE_OPENSUBDIV
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/sdc/crease.h>

#include "support/opensubdiv_refiner.h"
#endif

namespace subdiv {
namespace {

using test::scheme;

std::vector<double> around(CreaseMethod method, std::vector<double> parent) {
  std::vector<double> child(parent.size());
  subdivide_sharpness_around_vertex(method, parent, child);
  return child;
}

TEST(ChaikinCreasing, SharpnessAroundAVertexByHand) {
  // Two semi-sharp edges, 2 and 3, a smooth and an infinitely sharp one:
  //   2 -> 3/4 * 2 + 1/4 * 3 - 1 = 1.25,   3 -> 3/4 * 3 + 1/4 * 2 - 1 = 1.75.
  EXPECT_EQ(around(CreaseMethod::chaikin, {2.0, 0.0, 3.0, 10.0}), (std::vector<double>{1.25, 0.0, 1.75, 10.0}));
  EXPECT_EQ(around(CreaseMethod::uniform, {2.0, 0.0, 3.0, 10.0}), (std::vector<double>{1.0, 0.0, 2.0, 10.0}));
  // Three: 1 -> 3/4 + 1/4 * (2 + 3) / 2 - 1 = 0.375, 2 -> 3/2 + 1/4 * 2 - 1 = 1,
  // 3 -> 9/4 + 1/4 * 3/2 - 1 = 1.625.
  EXPECT_EQ(around(CreaseMethod::chaikin, {1.0, 2.0, 3.0}), (std::vector<double>{0.375, 1.0, 1.625}));
  // A single semi-sharp edge (the infinite one is not averaged in): s - 1,
  // as with the uniform method.
  EXPECT_EQ(around(CreaseMethod::chaikin, {2.5, 0.0, 10.0, 0.0}), (std::vector<double>{1.5, 0.0, 10.0, 0.0}));
  // Decay to 0, also for sharpness above 1: 1.2 -> 0.9 + 0.025 - 1 < 0.
  EXPECT_EQ(around(CreaseMethod::chaikin, {1.2, 0.1}), (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(around(CreaseMethod::uniform, {1.2, 0.1})[1], 0.0);
  EXPECT_NEAR(around(CreaseMethod::uniform, {1.2, 0.1})[0], 0.2, 1e-15);
  // A vertex with one edge: the uniform rule.
  EXPECT_EQ(around(CreaseMethod::chaikin, {3.0}), (std::vector<double>{2.0}));
}

// A 4 x 2 grid of unit quads; vertex id(i, j) = 5j + i. The middle row
// carries a crease 6 - 7 - 8 through the interior vertex 7.
PolygonMesh creased_grid(double s67, double s78, CreaseMethod method) {
  PolygonMesh mesh = test::quad_grid(4, 2);
  mesh.tags.creases = {{6, 7, s67}, {7, 8, s78}};
  mesh.tags.crease_method = method;
  mesh.tags.crease_method_set = true;
  return mesh;
}

int end_of(const MeshTopology& t, Index e, Index v) { return t.edge_vertices(e)[0] == v ? 0 : 1; }

TEST(ChaikinCreasing, HalvesOfAnEdgeDifferByTheirEndVertex) {
  const PolygonMesh mesh = creased_grid(2.0, 3.0, CreaseMethod::chaikin);
  const MeshTopology t(mesh);
  const Index e67 = t.find_edge(6, 7), e78 = t.find_edge(7, 8);
  const LevelCreasing chaikin = compute_creasing(mesh, t, BoundaryInterpolation::edge_and_corner, CreaseMethod::chaikin);
  const LevelCreasing uniform = compute_creasing(mesh, t, BoundaryInterpolation::edge_and_corner, CreaseMethod::uniform);
  ASSERT_EQ(chaikin.child_edge_sharpness.size(), 2 * static_cast<std::size_t>(t.edge_count()));
  EXPECT_TRUE(uniform.child_edge_sharpness.empty());  // the uniform method keeps no per-end array

  // At vertex 7 the two semi-sharp edges average (1.25 and 1.75, as above);
  // at 6 and 8 each is the only semi-sharp edge: s - 1, as uniform.
  EXPECT_EQ(child_sharpness_of(chaikin, e67, end_of(t, e67, 6)), 1.0);
  EXPECT_EQ(child_sharpness_of(chaikin, e67, end_of(t, e67, 7)), 1.25);
  EXPECT_EQ(child_sharpness_of(chaikin, e78, end_of(t, e78, 7)), 1.75);
  EXPECT_EQ(child_sharpness_of(chaikin, e78, end_of(t, e78, 8)), 2.0);
  for (const int end : {0, 1}) {
    EXPECT_EQ(child_sharpness_of(uniform, e67, end), 1.0);
    EXPECT_EQ(child_sharpness_of(uniform, e78, end), 2.0);
  }
  // Boundary edges stay infinitely sharp at both ends; smooth edges smooth.
  const Index boundary = t.find_edge(0, 1), smooth = t.find_edge(7, 12);
  for (const int end : {0, 1}) {
    EXPECT_EQ(child_sharpness_of(chaikin, boundary, end), kInfiniteSharpness);
    EXPECT_EQ(child_sharpness_of(chaikin, smooth, end), 0.0);
  }

  // The child level's tags carry each half's own value.
  RefineOptions one;
  const PolygonMesh child = refine(mesh, scheme("catmull-clark"), one);
  const Index ep = mesh.face_count(), vp = ep + t.edge_count();  // first edge point, first vertex point
  const std::vector<CreaseTag> expected = {{vp + 6, ep + e67, 1.0},
                                           {ep + e67, vp + 7, 1.25},
                                           {vp + 7, ep + e78, 1.75},
                                           {ep + e78, vp + 8, 2.0}};
  EXPECT_EQ(child.tags.creases, expected);
  EXPECT_EQ(child.tags.crease_method, CreaseMethod::chaikin);
  // The uniform method: s - 1 for both halves.
  const PolygonMesh uniform_child = refine(creased_grid(2.0, 3.0, CreaseMethod::uniform), scheme("catmull-clark"), one);
  const std::vector<CreaseTag> expected_uniform = {{vp + 6, ep + e67, 1.0},
                                                   {ep + e67, vp + 7, 1.0},
                                                   {vp + 7, ep + e78, 2.0},
                                                   {ep + e78, vp + 8, 2.0}};
  EXPECT_EQ(uniform_child.tags.creases, expected_uniform);
  // Overriding the tag's method gives the other method's result.
  RefineOptions override_uniform;
  override_uniform.crease_method = CreaseMethod::uniform;
  const PolygonMesh overridden = refine(mesh, scheme("catmull-clark"), override_uniform);
  EXPECT_EQ(overridden.tags.creases, expected_uniform);
  EXPECT_EQ(overridden.tags.crease_method, CreaseMethod::uniform);  // the refined tags say how they were made
  EXPECT_EQ(overridden.positions, uniform_child.positions);
}

TEST(ChaikinCreasing, UniformAndChaikinDifferOnlyWhereTheAveragesDo) {
  // One level down the two methods give the same sharp edges and rules here
  // (every child sharpness is >= 1), so level 1 is the same; the sharpness
  // differs (1.25 against 1), and so do later levels.
  for (const char* name : {"catmull-clark", "loop"}) {
    SCOPED_TRACE(name);
    const Scheme& s = scheme(name);
    PolygonMesh chaikin = creased_grid(2.0, 3.0, CreaseMethod::chaikin);
    chaikin.positions[12].z = 1.0;  // above vertex 7
    if (s.traits.needs_triangles) {
      PolygonMesh tri = test::triangle_grid(4, 2);
      tri.positions = chaikin.positions;
      tri.tags = chaikin.tags;
      chaikin = tri;
    }
    PolygonMesh uniform = chaikin;
    uniform.tags.crease_method = CreaseMethod::uniform;
    RefineOptions o;
    o.levels = 1;
    EXPECT_EQ(refine(chaikin, s, o).positions, refine(uniform, s, o).positions);
    o.levels = 4;
    const auto a = refine(chaikin, s, o).positions, b = refine(uniform, s, o).positions;
    ASSERT_EQ(a.size(), b.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, norm(a[i] - b[i]));
    EXPECT_GT(largest, 1e-3);
  }
  // With a single semi-sharp edge at every vertex the methods are the same.
  PolygonMesh single = test::quad_grid(4, 2);
  single.tags.creases = {{6, 7, 2.5}, {8, 13, 1.5}};
  single.positions[12].z = 1.0;
  PolygonMesh single_chaikin = single;
  single_chaikin.tags.crease_method = CreaseMethod::chaikin;
  RefineOptions o;
  o.levels = 4;
  const PolygonMesh a = refine(single_chaikin, scheme("catmull-clark"), o), b = refine(single, scheme("catmull-clark"), o);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.tags.creases, b.tags.creases);
}

TEST(ChaikinCreasing, RulesOneLevelDownFollowEachEnd) {
  // Edge 6-7 has sharpness 1.2, 7-8 has 0.1. At 7 both children decay
  // (1.2 -> 0.9 + 0.025 - 1 < 0); at 6, 6-7 alone gives 0.2.
  const PolygonMesh mesh = creased_grid(1.2, 0.1, CreaseMethod::chaikin);
  const MeshTopology t(mesh);
  const Index e67 = t.find_edge(6, 7), e78 = t.find_edge(7, 8);
  const LevelCreasing chaikin = compute_creasing(mesh, t, BoundaryInterpolation::edge_and_corner, CreaseMethod::chaikin);
  const LevelCreasing uniform = compute_creasing(mesh, t, BoundaryInterpolation::edge_and_corner, CreaseMethod::uniform);
  EXPECT_EQ(child_sharpness_of(chaikin, e67, end_of(t, e67, 7)), 0.0);
  EXPECT_NEAR(child_sharpness_of(chaikin, e67, end_of(t, e67, 6)), 0.2, 1e-15);

  // What a vertex mask one level down sees: Chaikin per end.
  const LevelView down{t, chaikin.edge_sharpness, 1.0, {}, chaikin.child_edge_sharpness};
  EXPECT_FALSE(down.is_sharp_at(e67, 7));
  EXPECT_TRUE(down.is_sharp_at(e67, 6));
  const LevelView uniform_down{t, uniform.edge_sharpness, 1.0};
  EXPECT_TRUE(uniform_down.is_sharp_at(e67, 7));
  EXPECT_TRUE(uniform_down.is_sharp_at(e67, 6));

  // Vertex 7: a crease now. Chaikin: both edges decay, so smooth one level
  // down, blended with weight mean(1.2, 0.1) = 0.65 on the crease rule.
  // Uniform: 6-7 stays sharp (a dart), only 0.1 decays: weight 0.1.
  EXPECT_EQ(chaikin.vertex_rule[7], VertexRule::crease);
  EXPECT_EQ(chaikin.child_vertex_rule[7], VertexRule::smooth);
  EXPECT_NEAR(chaikin.parent_rule_weight[7], 0.65, 1e-15);
  EXPECT_EQ(uniform.child_vertex_rule[7], VertexRule::dart);
  EXPECT_NEAR(uniform.parent_rule_weight[7], 0.1, 1e-15);
  // Vertex 6: one sharp edge, whose child there stays sharp: a dart both ways.
  EXPECT_EQ(chaikin.vertex_rule[6], VertexRule::dart);
  EXPECT_EQ(chaikin.child_vertex_rule[6], VertexRule::dart);

  // Edge 6-7's edge point: one child decays, so OpenSubdiv blends the crease
  // rule with weight s = 1.2 and the smooth rule with -0.2 (uniform: s >= 1,
  // the crease rule). Edge 7-8: both decay, weight 0.1 either way.
  EXPECT_EQ(edge_crease_weight(chaikin, e67), 1.2);
  EXPECT_EQ(edge_crease_weight(uniform, e67), 1.0);
  EXPECT_EQ(edge_crease_weight(chaikin, e78), 0.1);
  EXPECT_EQ(edge_crease_weight(uniform, e78), 0.1);

  // With vertex 12 (above 7) lifted to z = 1, the smooth Catmull-Clark edge
  // point of 6-7 has z = (0 + 0) / 4 + (0 + 1/4) / 4 = 1/16 (the faces
  // 1-2-7-6 and 6-7-12-11), the crease rule z = 0: Chaikin gives
  // -0.2 / 16 = -0.0125, uniform 0.
  PolygonMesh lifted = mesh;
  lifted.positions[12].z = 1.0;
  PolygonMesh lifted_uniform = lifted;
  lifted_uniform.tags.crease_method = CreaseMethod::uniform;
  const Index edge_point = mesh.face_count() + e67;
  EXPECT_NEAR(refine(lifted, scheme("catmull-clark")).positions[static_cast<std::size_t>(edge_point)].z, -0.0125, 1e-15);
  EXPECT_EQ(refine(lifted_uniform, scheme("catmull-clark")).positions[static_cast<std::size_t>(edge_point)].z, 0.0);
}

TEST(ChaikinCreasing, NoPerEndArrayWithoutSemiSharpEdges) {
  // Chaikin's rule is the uniform one without semi-sharp edges: no array.
  PolygonMesh mesh = test::quad_grid(3, 3);
  mesh.tags.creases = {{5, 6, 10.0}};
  mesh.tags.crease_method = CreaseMethod::chaikin;
  const MeshTopology t(mesh);
  EXPECT_TRUE(compute_creasing(mesh, t, BoundaryInterpolation::edge_only, CreaseMethod::chaikin).child_edge_sharpness.empty());
  mesh.tags.creases = {{5, 6, 0.5}};
  EXPECT_FALSE(compute_creasing(mesh, t, BoundaryInterpolation::edge_only, CreaseMethod::chaikin).child_edge_sharpness.empty());
}

TEST(ChaikinCreasing, StencilPathAgreesWithTheFastPath) {
  PolygonMesh mesh = creased_grid(1.2, 0.1, CreaseMethod::chaikin);
  mesh.tags.creases.push_back({7, 12, 2.5});
  mesh.tags.creases.push_back({2, 7, 0.75});
  mesh.positions[12].z = 1.0;
  mesh.positions[3].z = -0.5;
  RefineOptions o;
  o.levels = 3;
  const PolygonMesh fast = refine(mesh, scheme("catmull-clark"), o);
  PolygonMesh via_tables;
  const auto tables = refine_stencils(mesh, scheme("catmull-clark"), o, &via_tables);
  ASSERT_EQ(via_tables.positions.size(), fast.positions.size());
  for (std::size_t i = 0; i < fast.positions.size(); ++i)
    EXPECT_LT(norm(via_tables.positions[i] - fast.positions[i]), 1e-14) << i;
  const StencilTable total = refine_stencil_table(mesh, scheme("catmull-clark"), o);
  std::vector<Vec3> direct(static_cast<std::size_t>(total.row_count()));
  total.apply(mesh.positions, direct);
  for (std::size_t i = 0; i < direct.size(); ++i) EXPECT_LT(norm(direct[i] - fast.positions[i]), 1e-13) << i;
}

#ifdef SUBDIV_HAVE_OPENSUBDIV

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

TEST(ChaikinCreasing, SharpnessAroundAVertexAsSdcCrease) {
  Sdc::Options options;
  options.SetCreasingMethod(Sdc::Options::CREASE_CHAIKIN);
  const Sdc::Crease crease(options);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> sharpness(0.0, 4.0);
  std::uniform_int_distribution<int> kind(0, 5);
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 1 + trial % 7;
    std::vector<float> theirs_in(static_cast<std::size_t>(n)), theirs_out(static_cast<std::size_t>(n));
    for (float& s : theirs_in) {
      const int k = kind(rng);
      s = k == 0 ? 0.0f : k == 1 ? 10.0f : static_cast<float>(sharpness(rng));
    }
    crease.SubdivideEdgeSharpnessesAroundVertex(n, theirs_in.data(), theirs_out.data());
    const std::vector<double> ours = around(CreaseMethod::chaikin, {theirs_in.begin(), theirs_in.end()});
    for (std::size_t i = 0; i < ours.size(); ++i) {
      // OpenSubdiv computes in float.
      EXPECT_NEAR(ours[i], theirs_out[i], 4e-6) << "trial " << trial << " edge " << i;
      EXPECT_EQ(ours[i] > 0.0, theirs_out[i] > 0.0f) << "trial " << trial << " edge " << i;
      // The single-edge form, as Vtr::Refinement uses it per child edge.
      EXPECT_NEAR(ours[i], crease.SubdivideEdgeSharpnessAtVertex(theirs_in[i], n, theirs_in.data()), 4e-6);
    }
  }
}

using test::OsdVertex;

// OpenSubdiv's refinement of `mesh` (its tags) after `levels` steps.
std::vector<Vec3> opensubdiv_refine(const PolygonMesh& mesh, Sdc::SchemeType type, BoundaryInterpolation boundary,
                                    int levels) {
  const auto refiner = test::make_refiner(mesh, type, levels, test::boundary_option(boundary));
  std::vector<OsdVertex> current(mesh.positions.size());
  for (std::size_t i = 0; i < current.size(); ++i) current[i] = {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z};
  const Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int l = 1; l <= levels; ++l) {
    std::vector<OsdVertex> next(static_cast<std::size_t>(refiner->GetLevel(l).GetNumVertices()));
    const OsdVertex* src = current.data();
    OsdVertex* dst = next.data();
    primvar.Interpolate(l, src, dst);
    current = std::move(next);
  }
  std::vector<Vec3> out;
  for (const OsdVertex& v : current) out.push_back({v.x, v.y, v.z});
  return out;
}

// The largest distance from a point of either set to the nearest of the other.
double set_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  auto one_way = [](const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
    double worst = 0.0;
    for (const Vec3& p : from) {
      double best = std::numeric_limits<double>::infinity();
      for (const Vec3& q : to) best = std::min(best, norm(p - q));
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

TEST(ChaikinCreasing, RefinesLikeOpenSubdivWithRandomCreases) {
  // Grids with random semi-sharp creases (on interior and boundary edges,
  // up to four at a vertex, sharpness with inexact averages) and a random
  // relief, both boundary modes, three levels. OpenSubdiv computes sharpness
  // in float, subdiv in double: positions agree to float rounding, far
  // closer than any rule difference would leave them (the uniform method
  // differs from Chaikin's here by more than 1e-2).
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> relief(-0.5, 0.5);
  std::uniform_real_distribution<double> sharpness(0.05, 3.5);
  std::bernoulli_distribution creased(0.45);
  for (int trial = 0; trial < 6; ++trial) {
    const bool loop = trial % 2 == 1;
    PolygonMesh mesh = loop ? test::triangle_grid(4, 4) : test::quad_grid(4, 4);
    for (Vec3& p : mesh.positions) p.z = relief(rng);
    const MeshTopology t(mesh);
    for (Index e = 0; e < t.edge_count(); ++e)
      if (creased(rng)) {
        const auto [a, b] = t.edge_vertices(e);
        mesh.tags.creases.push_back({a, b, static_cast<double>(static_cast<float>(sharpness(rng)))});
      }
    mesh.tags.crease_method = CreaseMethod::chaikin;
    const BoundaryInterpolation boundary =
        trial < 3 ? BoundaryInterpolation::edge_only : BoundaryInterpolation::edge_and_corner;
    RefineOptions o;
    o.levels = 3;
    o.boundary = boundary;
    const Scheme& s = scheme(loop ? "loop" : "catmull-clark");
    const Sdc::SchemeType type = loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
    SCOPED_TRACE("trial " + std::to_string(trial));
    const std::vector<Vec3> ours = refine(mesh, s, o).positions;
    const std::vector<Vec3> theirs = opensubdiv_refine(mesh, type, boundary, o.levels);
    ASSERT_EQ(ours.size(), theirs.size());
    EXPECT_LT(set_distance(ours, theirs), 1e-5);
    PolygonMesh uniform = mesh;
    uniform.tags.crease_method = CreaseMethod::uniform;
    EXPECT_GT(set_distance(refine(uniform, s, o).positions, theirs), 1e-2);
  }
}

TEST(ChaikinCreasing, ExtrapolatedEdgePointAsOpenSubdiv) {
  // The 1.2 / 0.1 crease of RulesOneLevelDownFollowEachEnd, where the edge
  // point of 6-7 weights the crease rule by 1.2: OpenSubdiv's result too.
  PolygonMesh mesh = creased_grid(static_cast<double>(1.2f), static_cast<double>(0.1f), CreaseMethod::chaikin);
  mesh.positions[12].z = 1.0;
  for (const int levels : {1, 2, 3}) {
    RefineOptions o;
    o.levels = levels;
    EXPECT_LT(set_distance(refine(mesh, scheme("catmull-clark"), o).positions,
                           opensubdiv_refine(mesh, Sdc::SCHEME_CATMARK, BoundaryInterpolation::edge_and_corner, levels)),
              1e-7)
        << levels << " levels";
  }
}

#endif  // SUBDIV_HAVE_OPENSUBDIV

}  // namespace
}  // namespace subdiv
