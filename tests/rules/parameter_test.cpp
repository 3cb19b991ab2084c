// Every family's parameters are checked by the library, with a typed error,
// at every refinement entry point (the CLI adds nothing of its own).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "subdiv/analysis/analyze.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/generalized_catmull_clark.h"
#include "subdiv/rules/kobbelt.h"
#include "support/tension.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using test::with_tension;

void expect_refused(const Scheme& scheme, const PolygonMesh& mesh) {
  EXPECT_THROW(refine(mesh, scheme), ParameterError) << scheme.name;
  EXPECT_THROW(refine_stencils(mesh, scheme), ParameterError);
  EXPECT_THROW(refine_stencil_table(mesh, scheme), ParameterError);
  EXPECT_THROW(refine_hierarchy(mesh, scheme), ParameterError);
  EXPECT_THROW(check_refinable(mesh, scheme, {}), ParameterError);
}

// Kobbelt's virtual-point weight 2w / (1 + 2w) needs w > -1/2: at -1/2 the
// library used to return NaN positions.
TEST(SchemeParameters, KobbeltTension) {
  const PolygonMesh cube = test::cube();
  for (const double w : {-0.5, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    expect_refused(with_tension(kobbelt_scheme(), w), cube);
  try {
    refine(cube, with_tension(kobbelt_scheme(), -0.5));
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("kobbelt needs w > -1/2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(analyze(with_tension(kobbelt_scheme(), -0.5), {Configuration::Kind::interior, 4}), ParameterError);
  // Inside the range the positions are finite.
  for (const double w : {-0.49, 0.0, 1.0 / 16.0, 0.3}) {
    const PolygonMesh out = refine(cube, with_tension(kobbelt_scheme(), w));
    for (const Vec3& p : out.positions) EXPECT_TRUE(std::isfinite(p.x + p.y + p.z)) << w;
  }
}

TEST(SchemeParameters, ButterflyTensionMustBeFinite) {
  const PolygonMesh mesh = triangulate(test::cube());
  expect_refused(with_tension(butterfly_scheme(), std::numeric_limits<double>::quiet_NaN()), mesh);
  EXPECT_NO_THROW(refine(mesh, with_tension(butterfly_scheme(), -0.2)));  // any finite w is a member
}

// Generalized Catmull-Clark: the degree, the number of smoothing operators
// and each operator's weights (Chen and Prautzsch: alpha, beta >= 0,
// 0 < alpha + beta < 1); midpoint subdivision's weights are fixed.
TEST(SchemeParameters, GeneralizedCatmullClarkDegreeAndWeights) {
  const PolygonMesh cube = test::cube();
  Scheme low = generalized_catmull_clark_scheme();
  std::get<DegreeParameters>(low.parameters).degree = 1;
  expect_refused(low, cube);
  EXPECT_THROW(set_degree(low, 1), ParameterError);
  Scheme counted = generalized_catmull_clark_scheme();
  set_degree(counted, 7);  // three operators B_1 .. B_3
  std::get<DegreeParameters>(counted.parameters).smoothing.resize(2);
  expect_refused(counted, cube);
  Scheme weights = generalized_catmull_clark_scheme();
  std::get<DegreeParameters>(weights.parameters).smoothing = {SmoothingWeights{.alpha = 0.7, .beta = 0.4}};
  expect_refused(weights, cube);
  Scheme midpoint = midpoint_scheme();
  std::get<DegreeParameters>(midpoint.parameters).smoothing = {SmoothingWeights{.alpha = 0.3, .beta = 0.5}};
  expect_refused(midpoint, cube);
  // The defaults and other degrees refine.
  for (const int n : {2, 3, 4, 5}) {
    Scheme s = midpoint_scheme();
    set_degree(s, n);
    EXPECT_NO_THROW(refine(cube, s)) << n;
  }
}

// A family's check receives only its own parameters: the schemes without
// parameters hold none, the tension families a tension.
TEST(SchemeParameters, EachFamilyHoldsItsOwn) {
  for (const Scheme* s : all_schemes()) {
    EXPECT_NO_THROW(check_parameters(*s)) << s->name;
    EXPECT_EQ(takes_tension(*s), tension_parameters(s->parameters) != nullptr) << s->name;
    if (s->steps) {  // a degree (gcc, midpoint), quasi 4-8's boundary treatment or averaging operators
      EXPECT_TRUE(degree_parameters(s->parameters) != nullptr ||
                  std::holds_alternative<Quasi48Parameters>(s->parameters) ||
                  std::holds_alternative<CompositeParameters>(s->parameters))
          << s->name;
    }
  }
  EXPECT_TRUE(takes_tension(butterfly_scheme()));
  EXPECT_TRUE(takes_tension(kobbelt_scheme()));
  EXPECT_FALSE(std::holds_alternative<std::monostate>(midpoint_scheme().parameters));
}

}  // namespace
}  // namespace subdiv
