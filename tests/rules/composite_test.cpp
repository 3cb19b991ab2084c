// Composite schemes written as averaging operators (rules/composite.h):
// - the presets equal the native schemes they spell out, refinement for
//   refinement (Loop; Kobbelt's sqrt3), to 1e-14 of the mesh's size, at
//   extraordinary vertices of valence 3 to 8;
// - the analysis and the limit positions of a user's spec are the native
//   scheme's;
// - every stencil row of a user's spec sums to one, and refinement commutes
//   with affine maps;
// - a spec that does not parse, or whose averages do not reach the old
//   vertices evenly, is refused naming why.

#include "subdiv/rules/composite.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/loop.h"
#include "subdiv/rules/sqrt3.h"
#include "support/stencil_checks.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// Closed triangle meshes with interior valences 3 to 8.
std::vector<std::pair<std::string, PolygonMesh>> closed_triangle_meshes() {
  return {{"tetrahedron", test::tetrahedron()},
          {"bipyramid 5", test::jittered(test::bipyramid(5), 3)},
          {"bipyramid 8", test::jittered(test::bipyramid(8), 4)},
          {"triangulated cube", test::jittered(triangulate(test::cube()), 5)},
          {"spot", triangulate(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh)}};
}

void expect_same_refinement(const Scheme& composite, const Scheme& native, int levels) {
  for (const auto& [name, mesh] : closed_triangle_meshes()) {
    SCOPED_TRACE(name);
    RefineOptions o;
    o.levels = levels;
    const PolygonMesh a = refine(mesh, composite, o), b = refine(mesh, native, o);
    ASSERT_EQ(a.face_indices, b.face_indices);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.positions.size(); ++i) worst = std::max(worst, norm(a.positions[i] - b.positions[i]));
    EXPECT_LT(worst, 1e-14 * test::radius(mesh));
  }
}

TEST(Composite, LoopPresetIsLoop) { expect_same_refinement(composite_loop_scheme(), loop_scheme(), 3); }

TEST(Composite, Sqrt3PresetIsKobbeltsSqrt3) {
  expect_same_refinement(composite_sqrt3_kobbelt_scheme(), sqrt3_scheme(), 4);
}

TEST(Composite, ASpecIsParsedOnceAndFoundByName) {
  const std::string spec = "composite:Tvv4,VdE,EVc(loop),VdE,EVc(loop)";
  const Scheme* found = find_scheme(spec);
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found, &composite_scheme(spec));
  EXPECT_EQ(found->name, spec);
  EXPECT_EQ(found->split, SplitRule::triangle);
  EXPECT_EQ(composite_scheme("composite:Tvv3,VF,FF,FVc(sqrt3)").split, SplitRule::sqrt3);
}

TEST(Composite, AUsersSpecHasTheNativeSpectraAndLimits) {
  const Scheme& spec = composite_scheme("composite:Tvv4,VdE,EVc(loop),VdE,EVc(loop)");
  AnalysisOptions options;
  options.characteristic_map = false;
  for (int k = 3; k <= 8; ++k) {
    const Configuration c{Configuration::Kind::interior, k, CornerType::convex};
    const ConfigurationAnalysis a = analyze(spec, c, options), b = analyze(loop_scheme(), c, options);
    ASSERT_EQ(a.leading.size(), b.leading.size());
    for (std::size_t i = 0; i < a.leading.size(); ++i)
      EXPECT_NEAR(std::abs(a.leading[i] - b.leading[i]), 0.0, 1e-12) << "k = " << k << ", lambda_" << i;
  }
  for (const auto& [name, mesh] : closed_triangle_meshes()) {
    const LimitResult a = limit_positions(mesh, spec), b = limit_positions(mesh, loop_scheme());
    EXPECT_EQ(a.approximated, 0) << name;
    for (std::size_t v = 0; v < a.positions.size(); ++v)
      EXPECT_LT(norm(a.positions[v] - b.positions[v]), 1e-12 * test::radius(mesh)) << name << " vertex " << v;
  }
}

TEST(Composite, StencilRowsSumToOneAndRefinementIsAffine) {
  for (const char* spec : {"composite:Tvv4,VdE,EV", "composite:Tvv4,VdE,EVc(0.25),VdEc(0.3),EV",
                           "composite:Tvv3,VF,FF,FV,VF,FF,FV", "composite:Tvv3,VF,FFc(0.4),FE,EF,FVc(0.6)"}) {
    SCOPED_TRACE(spec);
    const Scheme& scheme = composite_scheme(spec);
    const PolygonMesh mesh = test::jittered(test::bipyramid(5), 9);
    EXPECT_TRUE(validate(test::expect_stencils_are_the_fast_path(mesh, scheme, 2, 1e-13)).ok());
    test::expect_refinement_commutes_with_an_affine_map(mesh, scheme, 2, 1e-12);
  }
}

// Two primal/dual cycles: with plain means valence 3 fails Reif's eigenvalue
// condition (lambda_2 = |lambda_3| = 1/9), the low valences the paper's
// abstract says need modified rules; with Kobbelt's coefficient in both
// cycles (the composite-sqrt3 preset) it holds at 3..16, and the full
// verdict (characteristic map included) is C1 at 3 (docs/schemes/composite.md
// has the full table, 3..16).
TEST(Composite, TwoCycleSqrt3IsC1AtLowValences) {
  AnalysisOptions spectrum;
  spectrum.characteristic_map = false;
  spectrum.masks = false;
  const Scheme& plain = composite_scheme("composite:Tvv3,VF,FF,FV,VF,FF,FV");
  EXPECT_FALSE(analyze(plain, {Configuration::Kind::interior, 3, CornerType::convex}, spectrum).eigenvalue_condition);
  const Scheme& preset = composite_sqrt3_scheme();
  for (int k = 3; k <= 16; ++k)
    EXPECT_TRUE(analyze(preset, {Configuration::Kind::interior, k, CornerType::convex}, spectrum).eigenvalue_condition)
        << "k = " << k;
  EXPECT_EQ(analyze(preset, {Configuration::Kind::interior, 3, CornerType::convex}).verdict, SmoothnessVerdict::c1);
}

// The sqrt3 split's composites through the generic masks: Kobbelt's preset
// has sqrt3's limits; the two-cycle preset's limits do not depend on the
// isolation levels once its four-ring neighbourhoods match, and deep
// refinement closes on them.
TEST(Composite, Sqrt3CompositesHaveLimits) {
  const PolygonMesh spot = triangulate(read_mesh(test::bundled_path("spot_control_mesh.obj")).mesh);
  const LimitResult kobbelt = limit_positions(spot, composite_sqrt3_kobbelt_scheme());
  const LimitResult native = limit_positions(spot, sqrt3_scheme());
  EXPECT_EQ(kobbelt.approximated, 0);
  for (std::size_t v = 0; v < kobbelt.positions.size(); ++v)
    EXPECT_LT(norm(kobbelt.positions[v] - native.positions[v]), 1e-12 * test::radius(spot)) << "vertex " << v;
  const PolygonMesh mesh = test::jittered(triangulate(test::cube()), 7);  // valences 4, 5 and 6
  const double size = test::radius(mesh);
  LimitOptions three, four;
  three.isolation_levels = 3;
  four.isolation_levels = 4;
  const LimitResult a = limit_positions(mesh, composite_sqrt3_scheme(), three);
  const LimitResult b = limit_positions(mesh, composite_sqrt3_scheme(), four);
  EXPECT_EQ(a.approximated, 0);
  EXPECT_EQ(b.approximated, 0);
  double previous = 0.0;
  for (int levels = 2; levels <= 6; levels += 2) {
    RefineOptions o;
    o.levels = levels;
    const PolygonMesh fine = refine(mesh, composite_sqrt3_scheme(), o);
    const Index first = fine.vertex_count() - mesh.vertex_count();  // vertex points come last
    double worst = 0.0;
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      worst = std::max(worst, norm(fine.positions[static_cast<std::size_t>(first + v)] - a.positions[static_cast<std::size_t>(v)]));
    if (levels > 2) {
      EXPECT_LT(worst, 0.2 * previous) << "level " << levels;  // 0.13 per two steps measured
    }
    previous = worst;
  }
  for (std::size_t v = 0; v < a.positions.size(); ++v)
    EXPECT_LT(norm(a.positions[v] - b.positions[v]), 1e-12 * size) << "vertex " << v;
}

void expect_refused(const std::string& spec, const std::string& part) {
  try {
    const Scheme& scheme = composite_scheme(spec);
    RefineOptions o;
    o.levels = 1;
    (void)refine(test::tetrahedron(), scheme, o);
    ADD_FAILURE() << spec << " was accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << spec << ": " << e.what();
  }
}

TEST(Composite, BadSpecsAreRefusedNamingWhy) {
  expect_refused("composite:VF,FV", "starts with an upsampling");
  expect_refused("composite:Tvv4,VX", "unknown operator 'VX'");
  expect_refused("composite:Tvv4,VdE", "ends on edges");
  expect_refused("composite:Tvv4,FV", "FV reads faces, but the values are on vertices");
  expect_refused("composite:Tvv4,VdE,EVc", "EVc takes a coefficient");
  expect_refused("composite:Tvv4,VdE(2),EV", "VdE takes no coefficient");
  expect_refused("composite:Tvv4,VdE,EVc(half)", "is not a number");
  expect_refused("composite:Tvv4,VdE,,EV", "an empty operator");
  expect_refused("composite:Tvv4", "no averaging operator");
  // Old vertices get 4 P, new ones 0: a new vertex's one-ring mean reads two
  // old and four new vertices, 8/6 of the position.
  expect_refused("composite:Tvv4,VV", "its weights sum to 1.333333");
  // Right after the upsampling only VdEc(1/4) = VdE weights old and new
  // vertices evenly: an edge of an old vertex gets 4 c.
  expect_refused("composite:Tvv4,VdEc(0.3),EV", "its weights sum to");
}

}  // namespace
}  // namespace subdiv
