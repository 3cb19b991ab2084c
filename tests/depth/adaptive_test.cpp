// Adaptive refinement: the output is conforming (closed inputs stay closed
// with every edge on exactly two faces, so no T-junction), every vertex is a
// vertex of a uniform level at that level's position and within eps of its
// limit, and it needs fewer faces than uniform refinement.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>
#include <vector>
#include <random>
#include <string>

#include "subdiv/core/error.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/mesh_stats.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/kobbelt.h"
#include "subdiv/rules/loop.h"
#include "depth/depth_test_meshes.h"
#include "support/gcc_schemes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// A uniform level and where a vertex of the walked hierarchy is in it.
// 4-8's levels (two steps each) are refined one step at a time, its own
// route, whose numbering differs from its two-step quad split's (faces too,
// from the second level on): a vertex is found by its position there, equal
// to rounding.
struct UniformLevel {
  PolygonMesh mesh;
  std::vector<std::pair<double, Index>> by_x;  // 4-8: (x, vertex), sorted

  std::optional<Index> find(Index index, const Vec3& p, double tolerance) const {
    if (by_x.empty()) return index;
    auto it = std::lower_bound(by_x.begin(), by_x.end(), std::pair{p.x - tolerance, Index{-1}});
    for (; it != by_x.end() && it->first <= p.x + tolerance; ++it)
      if (norm(mesh.positions[static_cast<std::size_t>(it->second)] - p) <= tolerance) return it->second;
    return std::nullopt;
  }
};

// Level `number` + 1 of the walked hierarchy (`steps` refinement steps
// each): the sqrt3 split's two steps in one refinement, 4-8's one at a time.
UniformLevel next_level(const UniformLevel& level, int number, const Scheme& scheme, int steps) {
  RefineOptions one;
  one.levels = scheme.split == SplitRule::sqrt3 ? 2 : 1;
  one.start_level = steps * number;
  one.regular_grids = false;
  UniformLevel next{refine(level.mesh, scheme, one), {}};
  if (steps == one.levels) return next;
  one.start_level += 1;
  next.mesh = refine(next.mesh, scheme, one);
  for (Index v = 0; v < next.mesh.vertex_count(); ++v)
    next.by_x.emplace_back(next.mesh.positions[static_cast<std::size_t>(v)].x, v);
  std::sort(next.by_x.begin(), next.by_x.end());
  return next;
}

void expect_conforming_and_within(const PolygonMesh& input, const Scheme& scheme, double eps,
                                  const std::string& name, const AdaptiveResult& result) {
  const MeshTopology t(result.mesh);
  const MeshTopology input_topology(input);
  const MeshStats in = compute_stats(input, input_topology), out = compute_stats(result.mesh, t);
  // A crack (a T-junction) is an edge with one face inside the mesh: on a
  // closed input every edge has two, and on an open one the boundary has as
  // many loops as the input's.
  for (Index e = 0; e < t.edge_count(); ++e) {
    ASSERT_EQ(t.edge_face_count(e), in.boundary_edges == 0 ? 2 : std::min<Index>(t.edge_face_count(e), 2))
        << name << ": edge " << t.edge_vertices(e)[0] << "-" << t.edge_vertices(e)[1];
  }
  EXPECT_EQ(out.boundary_loops, in.boundary_loops) << name;
  EXPECT_EQ(out.euler_characteristic, in.euler_characteristic) << name;
  EXPECT_TRUE(validate(result.mesh).ok()) << name;
  // Every vertex, independently: the uniform level it names, refined here by
  // the masks as adaptive refinement refines (refine()'s grid path gives the
  // same points up to rounding; 4-8's single steps too), has it at that
  // position, and its distance to the limit there is <= eps.
  std::vector<UniformLevel> levels{{input, {}}};
  std::vector<LimitDistances> distances{limit_distances(input, scheme)};
  const double rounding = result.steps_per_level == 1 ? 0.0 : 1e-12 * test::radius(input);
  for (std::size_t v = 0; v < result.sources.size(); ++v) {
    const AdaptiveVertexSource source = result.sources[v];
    while (static_cast<int>(levels.size()) <= source.level) {
      levels.push_back(next_level(levels.back(), static_cast<int>(levels.size()) - 1, scheme, result.steps_per_level));
      LimitOptions at_level;
      at_level.refine.start_level = result.steps_per_level * (static_cast<int>(levels.size()) - 1);
      distances.push_back(limit_distances(levels.back().mesh, scheme, at_level));
    }
    const auto level = static_cast<std::size_t>(source.level);
    const std::optional<Index> found = levels[level].find(source.index, result.mesh.positions[v], rounding);
    ASSERT_TRUE(found) << name << ": vertex " << v << " is not a vertex of level " << level;
    const auto index = static_cast<std::size_t>(*found);
    if (rounding == 0.0) {
      ASSERT_EQ(result.mesh.positions[v], levels[level].mesh.positions[index]) << name << ": vertex " << v;
    }
    EXPECT_LE(distances[level].distances[index], eps) << name << ": vertex " << v;
  }
}

void expect_conforming_and_within(const PolygonMesh& input, const Scheme& scheme, double eps,
                                  const std::string& name) {
  expect_conforming_and_within(input, scheme, eps, name, adaptive_refine(input, scheme, eps));
}

TEST(Adaptive, ConformingAndWithinEpsOnBundledMeshes) {
  std::mt19937 random(9);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  expect_conforming_and_within(triangulate(cube), loop_scheme(), 0.01, "cube (loop)");
  expect_conforming_and_within(cube, catmull_clark_scheme(), 0.01, "cube (catmull-clark)");
  expect_conforming_and_within(perturbed(triangulate(cube), 0.1, random), loop_scheme(), 0.005, "perturbed cube (loop)");
  expect_conforming_and_within(perturbed(cube, 0.1, random), catmull_clark_scheme(), 0.005,
                               "perturbed cube (catmull-clark)");
  expect_conforming_and_within(spinning_top(18, 4.0, 7.0, 7.0), loop_scheme(), 0.05, "spinning top (loop)");
  expect_conforming_and_within(spinning_top(7, 4.0, 7.0, 3.0), catmull_clark_scheme(), 0.05,
                               "spinning top (catmull-clark)");
}

TEST(Adaptive, ConformingAndWithinEpsOnSharedMeshes) {
  const std::string dir = test::shared_mesh_dir();
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "shared mesh collection not found at " << dir;
  std::mt19937 random(12);
  for (const char* file : {"cgal/hole.obj", "cgal/3torus.obj", "opensubdiv/catmark_torus.obj"}) {
    const PolygonMesh mesh = read_mesh(dir + "/" + file).mesh;
    const double eps = 0.02 * (mesh.positions.empty() ? 1.0 : limit_distances(mesh, catmull_clark_scheme()).max);
    expect_conforming_and_within(triangulate(mesh), loop_scheme(), eps, std::string(file) + " (loop)");
    expect_conforming_and_within(mesh, catmull_clark_scheme(), eps, std::string(file) + " (catmull-clark)");
    expect_conforming_and_within(perturbed(mesh, eps, random), catmull_clark_scheme(), eps,
                                 std::string(file) + " (perturbed, catmull-clark)");
  }
}

// Composite schemes of the quad and triangle splits refine adaptively on
// their uniform levels as any scheme of their split: gcc and midpoint of
// odd degree, and composite-loop, whose adaptive mesh is Loop's (same faces,
// positions to rounding: its levels equal Loop's to 1e-14).
TEST(Adaptive, CompositeSchemesOfThePrimalSplits) {
  std::mt19937 random(14);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  for (const Scheme& scheme : {test::midpoint(3), test::midpoint(5), test::gcc(5, 0.5, 0.25)}) {
    const std::string name = std::string(scheme.name) + " of degree " +
                             std::to_string(std::get<DegreeParameters>(scheme.parameters).degree);
    expect_conforming_and_within(cube, scheme, 0.01, "cube (" + name + ")");
    expect_conforming_and_within(perturbed(cube, 0.1, random), scheme, 0.005, "perturbed cube (" + name + ")");
  }
  const Scheme& composite_loop = *find_scheme("composite-loop");
  const PolygonMesh bumpy = perturbed(triangulate(cube), 0.1, random);
  expect_conforming_and_within(bumpy, composite_loop, 0.005, "perturbed cube (composite-loop)");
  const PolygonMesh top = spinning_top(7, 4.0, 7.0, 3.0);
  const AdaptiveResult composite = adaptive_refine(top, composite_loop, 0.05);
  const AdaptiveResult loop = adaptive_refine(top, loop_scheme(), 0.05);
  ASSERT_GT(composite.transition_faces, 0);
  ASSERT_EQ(composite.mesh.face_indices, loop.mesh.face_indices);
  ASSERT_EQ(composite.mesh.vertex_count(), loop.mesh.vertex_count());
  for (std::size_t v = 0; v < loop.mesh.positions.size(); ++v)
    ASSERT_LE(norm(composite.mesh.positions[v] - loop.mesh.positions[v]), 1e-12 * test::radius(top)) << v;
}

TEST(Adaptive, HalvesTheFacesOnARealMesh) {
  // Spot's control mesh: smooth body, sharp ears and horns. Uniform
  // refinement must go as deep everywhere as the worst place needs.
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  const AdaptiveResult cc = adaptive_refine(spot, catmull_clark_scheme(), 0.004);
  EXPECT_GE(static_cast<double>(cc.uniform_faces), 2.0 * cc.mesh.face_count());
  const AdaptiveResult loop = adaptive_refine(triangulate(spot), loop_scheme(), 0.004);
  EXPECT_GE(static_cast<double>(loop.uniform_faces), 2.0 * loop.mesh.face_count());
}

TEST(Adaptive, NothingToDoKeepsTheMesh) {
  // eps above every distance: the control mesh is the answer.
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  const AdaptiveResult result = adaptive_refine(cube, catmull_clark_scheme(), 10.0);
  EXPECT_EQ(result.mesh.face_count(), cube.face_count());
  EXPECT_EQ(result.transition_faces, 0);
  EXPECT_EQ(result.uniform_depth, 0);
}

TEST(Adaptive, RefusesBadAccuracy) {
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  EXPECT_THROW((void)adaptive_refine(cube, catmull_clark_scheme(), 0.0), InvalidInputError);
  AdaptiveOptions shallow;
  shallow.max_level = 1;
  EXPECT_THROW((void)adaptive_refine(cube, catmull_clark_scheme(), 1e-6, shallow), InvalidInputError);
}

// 4-8 walks its two-step quad split's hierarchy: each level is two of its
// steps, and every vertex is checked against 4-8's own refinement and its own
// limits (the sqrt2 analysis' masks), a second route to the same surface.
TEST(Adaptive, FourEightInLevelsOfTwoSteps) {
  std::mt19937 random(15);
  const Scheme& four_eight = *find_scheme("four-eight");
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  expect_conforming_and_within(cube, four_eight, 0.01, "cube (four-eight)");
  expect_conforming_and_within(perturbed(cube, 0.1, random), four_eight, 0.005, "perturbed cube (four-eight)");
  expect_conforming_and_within(spinning_top(7, 4.0, 7.0, 3.0), four_eight, 0.05, "spinning top (four-eight)");
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  expect_conforming_and_within(spot, four_eight, 0.004, "spot (four-eight)");
  const AdaptiveResult result = adaptive_refine(spot, four_eight, 0.004);
  EXPECT_EQ(result.steps_per_level, 2);
  EXPECT_GT(result.transition_faces, 0);
  EXPECT_GE(static_cast<double>(result.uniform_faces), 1.5 * result.mesh.face_count());
}

// The sqrt3 split's faces nest every two steps (1-to-9): its hierarchy is
// walked in levels of two steps, closed and open meshes alike.
TEST(Adaptive, Sqrt3InLevelsOfTwoSteps) {
  std::mt19937 random(16);
  const Scheme& sqrt3 = *find_scheme("sqrt3");
  const PolygonMesh cube = triangulate(read_mesh(test::bundled_path("cube.obj")).mesh);
  expect_conforming_and_within(cube, sqrt3, 0.005, "cube (sqrt3)");
  expect_conforming_and_within(perturbed(cube, 0.1, random), sqrt3, 0.005, "perturbed cube (sqrt3)");
  expect_conforming_and_within(spinning_top(7, 4.0, 7.0, 3.0), sqrt3, 0.05, "spinning top (sqrt3)");
  const PolygonMesh l_shape = triangulate(read_mesh(test::bundled_path("l_shape.obj")).mesh);
  expect_conforming_and_within(l_shape, sqrt3, 0.002, "l_shape (sqrt3)");
  const AdaptiveResult result = adaptive_refine(l_shape, sqrt3, 0.002);
  EXPECT_EQ(result.steps_per_level, 2);
  EXPECT_GT(result.transition_faces, 0);
  EXPECT_GE(static_cast<double>(result.uniform_faces), 2.0 * result.mesh.face_count());
  // Kobbelt's sqrt3 spelt as a composite (closed meshes): the same adaptive mesh.
  const PolygonMesh bumpy = perturbed(cube, 0.1, random);
  const AdaptiveResult native = adaptive_refine(bumpy, sqrt3, 0.003);
  const AdaptiveResult composite = adaptive_refine(bumpy, *find_scheme("composite-sqrt3-kobbelt"), 0.003);
  ASSERT_GT(native.transition_faces, 0);
  ASSERT_EQ(composite.mesh.face_indices, native.mesh.face_indices);
  for (std::size_t v = 0; v < native.mesh.positions.size(); ++v)
    ASSERT_LE(norm(composite.mesh.positions[v] - native.mesh.positions[v]), 1e-12 * test::radius(bumpy)) << v;
}

// The dual split has no face hierarchy: a face one level down exists where
// the faces it is made from are split, and the levels meet in half E-faces
// and fan polygons (docs/depth.md).
TEST(Adaptive, DualSplitJoinedByHalfEFacesAndFans) {
  std::mt19937 random(18);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  const Scheme& doo_sabin = *find_scheme("doo-sabin");
  expect_conforming_and_within(cube, doo_sabin, 0.003, "cube (doo-sabin)");
  expect_conforming_and_within(perturbed(cube, 0.1, random), doo_sabin, 0.003, "perturbed cube (doo-sabin)");
  expect_conforming_and_within(spinning_top(7, 4.0, 7.0, 3.0), doo_sabin, 0.05, "spinning top (doo-sabin)");
  const PolygonMesh spot = read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh;
  expect_conforming_and_within(spot, doo_sabin, 0.004, "spot (doo-sabin)");
  const AdaptiveResult result = adaptive_refine(spot, doo_sabin, 0.004);
  EXPECT_GT(result.transition_faces, 0);
  EXPECT_GE(static_cast<double>(result.uniform_faces), 4.0 * result.mesh.face_count());
  // The balance rule: every vertex of a transition (a face whose vertices
  // come from two levels) is a corner of a leaf (a face of one level).
  for (const AdaptiveResult& adaptive : {result, adaptive_refine(perturbed(cube, 0.1, random), doo_sabin, 0.003)}) {
    const PolygonMesh& out = adaptive.mesh;
    std::vector<char> in_leaf(static_cast<std::size_t>(out.vertex_count()), 0);
    std::vector<Index> in_transition;
    for (Index f = 0; f < out.face_count(); ++f) {
      const auto level = [&](Index c) { return adaptive.sources[static_cast<std::size_t>(out.face_indices[c])].level; };
      bool one_level = true;
      for (Index c = out.face_offsets[f]; c < out.face_offsets[f + 1]; ++c) one_level = one_level && level(c) == level(out.face_offsets[f]);
      for (Index c = out.face_offsets[f]; c < out.face_offsets[f + 1]; ++c) {
        if (one_level) in_leaf[static_cast<std::size_t>(out.face_indices[c])] = 1;
        else in_transition.push_back(out.face_indices[c]);
      }
    }
    ASSERT_FALSE(in_transition.empty());
    for (const Index v : in_transition) ASSERT_TRUE(in_leaf[static_cast<std::size_t>(v)]) << "vertex " << v;
  }
  // Midedge: two of its steps are a dual split, walked in levels of two steps.
  const Scheme& midedge = *find_scheme("midedge");
  expect_conforming_and_within(cube, midedge, 0.005, "cube (midedge)");
  expect_conforming_and_within(perturbed(cube, 0.1, random), midedge, 0.005, "perturbed cube (midedge)");
  const AdaptiveResult by_midedge = adaptive_refine(cube, midedge, 0.005);
  EXPECT_EQ(by_midedge.steps_per_level, 2);
  EXPECT_GT(by_midedge.transition_faces, 0);
  // Composite schemes whose level ends with a dual step.
  for (const Scheme& scheme : {test::midpoint(2), test::gcc(4, 0.5, 0.25)})
    expect_conforming_and_within(perturbed(cube, 0.1, random), scheme, 0.005,
                                 "perturbed cube (" + std::string(scheme.name) + ", even degree)");
  // Open meshes are refused.
  PolygonMesh square;
  square.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.add_face(std::vector<Index>{0, 1, 2, 3});
  square.positions[2].z = 0.5;
  EXPECT_THROW((void)adaptive_refine(square, doo_sabin, 0.001), InvalidInputError);
}

// An open sqrt3 mesh at an odd level: its first step trisects the boundary,
// and the next level's faces at the boundary straddle two faces.
TEST(Adaptive, OpenSqrt3MeshesAtOddLevelsAreRefused) {
  const PolygonMesh l_shape = triangulate(read_mesh(test::bundled_path("l_shape.obj")).mesh);
  AdaptiveOptions odd;
  odd.depth.refine.start_level = 1;
  EXPECT_THROW((void)adaptive_refine(l_shape, *find_scheme("sqrt3"), 0.002, odd), InvalidInputError);
}

// The distance from p to triangle (a, b, c): the nearest point is inside,
// on an edge or at a corner (C. Ericson, Real-Time Collision Detection,
// section 5.1.5).
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return norm(p - a);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return norm(p - b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return norm(p - (a + (d1 / (d1 - d3)) * ab));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return norm(p - c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return norm(p - (a + (d2 / (d2 - d6)) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return norm(p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
  const double denominator = 1.0 / (va + vb + vc);
  return norm(p - (a + (vb * denominator) * ab + (vc * denominator) * ac));
}

// Interpolating schemes: every vertex is on the limit, and the faces are
// refined until their next level's vertices lie within eps (1 - r) of them.
// Checked independently on triangle meshes: every vertex of the uniform
// level below the uniform depth (those vertices are on the limit) is within
// eps of the adaptive mesh's flat triangles.
void expect_interpolating_within(const PolygonMesh& input, const Scheme& scheme, double eps, const std::string& name) {
  const AdaptiveResult result = adaptive_refine(input, scheme, eps);
  expect_conforming_and_within(input, scheme, eps, name, result);
  EXPECT_EQ(result.measure, DepthMeasure::surface_to_limit) << name;
  EXPECT_GT(result.largest_displacement, 0.0) << name;
  EXPECT_LE(result.largest_displacement, result.displacement_threshold) << name;
  EXPECT_LT(result.displacement_threshold, eps) << name;
  if (scheme.split != SplitRule::triangle && scheme.split != SplitRule::sqrt3) return;
  RefineOptions deeper;
  deeper.levels = (result.uniform_depth + 1) * result.steps_per_level;
  const PolygonMesh limit_points = refine(input, scheme, deeper);
  const PolygonMesh& out = result.mesh;
  // Each triangle's bounding box: a point further from the box than the
  // nearest triangle so far skips the triangle.
  std::vector<std::pair<Vec3, Vec3>> boxes;
  for (Index f = 0; f < out.face_count(); ++f) {
    Vec3 low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
    for (Index c = out.face_offsets[f]; c < out.face_offsets[f + 1]; ++c) {
      const Vec3& q = out.positions[static_cast<std::size_t>(out.face_indices[c])];
      low = {std::min(low.x, q.x), std::min(low.y, q.y), std::min(low.z, q.z)};
      high = {std::max(high.x, q.x), std::max(high.y, q.y), std::max(high.z, q.z)};
    }
    boxes.emplace_back(low, high);
  }
  double worst = 0.0;
  for (const Vec3& p : limit_points.positions) {
    double nearest = std::numeric_limits<double>::infinity();
    for (Index f = 0; f < out.face_count() && nearest > 0.0; ++f) {
      const auto& [low, high] = boxes[static_cast<std::size_t>(f)];
      const Vec3 outside{std::max({low.x - p.x, 0.0, p.x - high.x}), std::max({low.y - p.y, 0.0, p.y - high.y}),
                         std::max({low.z - p.z, 0.0, p.z - high.z})};
      if (norm(outside) >= nearest) continue;
      const auto corner = [&](Index i) { return out.positions[static_cast<std::size_t>(out.face_indices[out.face_offsets[f] + i])]; };
      nearest = std::min(nearest, distance_to_triangle(p, corner(0), corner(1), corner(2)));
    }
    worst = std::max(worst, nearest);
  }
  EXPECT_LE(worst, eps) << name;
  EXPECT_GT(worst, 0.0) << name;  // a curved mesh: the check could fail
}

TEST(Adaptive, ButterfliesByTheirFacesDisplacements) {
  std::mt19937 random(17);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  expect_interpolating_within(triangulate(cube), butterfly_scheme(), 0.01, "cube (butterfly)");
  expect_interpolating_within(perturbed(triangulate(cube), 0.1, random), modified_butterfly_scheme(), 0.01,
                              "perturbed cube (modified-butterfly)");
  expect_interpolating_within(read_mesh(test::bundled_path("tetrahedron.obj")).mesh, modified_butterfly_scheme(),
                              0.01, "tetrahedron (modified-butterfly)");
  // Spot's body is smooth, its ears and horns are not.
  const AdaptiveResult spot =
      adaptive_refine(triangulate(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh), butterfly_scheme(), 0.01);
  EXPECT_GE(static_cast<double>(spot.uniform_faces), 4.0 * spot.mesh.face_count());
}

TEST(Adaptive, KobbeltByItsFacesDisplacements) {
  std::mt19937 random(19);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  expect_interpolating_within(cube, kobbelt_scheme(), 0.01, "cube (kobbelt)");
  expect_interpolating_within(perturbed(cube, 0.1, random), kobbelt_scheme(), 0.01, "perturbed cube (kobbelt)");
}

// The rotating splits' interpolating schemes, in levels of two steps.
TEST(Adaptive, RotatingInterpolatingSchemesByTheirFacesDisplacements) {
  std::mt19937 random(20);
  const PolygonMesh cube = read_mesh(test::bundled_path("cube.obj")).mesh;
  const Scheme& sqrt3 = *find_scheme("interpolatory-sqrt3");
  expect_interpolating_within(triangulate(cube), sqrt3, 0.005, "cube (interpolatory-sqrt3)");
  expect_interpolating_within(perturbed(triangulate(cube), 0.1, random), sqrt3, 0.01,
                              "perturbed cube (interpolatory-sqrt3)");
  expect_interpolating_within(cube, *find_scheme("interpolating-sqrt2"), 0.005, "cube (interpolating-sqrt2)");
}

}  // namespace
}  // namespace subdiv
