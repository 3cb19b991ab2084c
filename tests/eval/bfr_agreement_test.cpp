// The limit evaluator against OpenSubdiv's Bfr (libosd-dev 3.5). On regular
// faces both are the same polynomial patch and must agree to 1e-12 of the
// mesh's size, derivatives included (this also pins the two
// parameterizations to each other). Near extraordinary vertices Bfr
// approximates (Gregory-like patches below its isolation level): its
// difference from the exact evaluator is reported and must shrink as Bfr's
// isolation level rises; the evaluator's own exactness there is tested
// against the closed-form limits in limit_evaluator_test.cpp.

#include <gtest/gtest.h>

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "refine/grid_test_support.h"
#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/mesh/topology.h"
#include "support/opensubdiv_refiner.h"
#include "support/refine_options.h"
#include "support/scheme_by_name.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace Bfr = OpenSubdiv::Bfr;
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

using grid_test::diagonal;

using test::scheme;

// The unrefined refiner, with the boundary interpolation of the mesh's tags.
std::unique_ptr<Far::TopologyRefiner> base_refiner(const PolygonMesh& mesh, Sdc::SchemeType type) {
  return test::make_refiner(mesh, type, 0,
                            test::boundary_option(mesh.tags.boundary_interpolation == BoundaryInterpolation::edge_only
                                                      ? BoundaryInterpolation::edge_only
                                                      : BoundaryInterpolation::edge_and_corner));
}

// Bfr's surface of every face of a mesh whose faces are its ptex faces.
class BfrSurfaces {
 public:
  BfrSurfaces(const PolygonMesh& mesh, Sdc::SchemeType type, int approx_level) {
    refiner_ = base_refiner(mesh, type);
    Bfr::RefinerSurfaceFactory<>::Options options;
    options.SetApproxLevelSmooth(approx_level);
    factory_ = std::make_unique<Bfr::RefinerSurfaceFactory<>>(*refiner_, options);
    for (const Vec3& p : mesh.positions) points_.insert(points_.end(), {p.x, p.y, p.z});
  }

  // Position, du, dv, duu, duv, dvv at (u, v) of `face`.
  std::array<Vec3, 6> evaluate(Index face, double u, double v) const {
    Bfr::Surface<double> surface;
    if (!factory_->InitVertexSurface<double>(face, &surface)) throw std::runtime_error("Bfr: no surface");
    std::vector<double> patch(3 * static_cast<std::size_t>(surface.GetNumPatchPoints()));
    const Bfr::Surface<double>::PointDescriptor desc(3);
    surface.PreparePatchPoints(points_.data(), desc, patch.data(), desc);
    std::array<std::array<double, 3>, 6> d{};
    const double uv[2] = {u, v};
    surface.Evaluate(uv, patch.data(), desc, d[0].data(), d[1].data(), d[2].data(), d[3].data(), d[4].data(),
                     d[5].data());
    std::array<Vec3, 6> out;
    for (std::size_t i = 0; i < 6; ++i) out[i] = {d[i][0], d[i][1], d[i][2]};
    return out;
  }

 private:
  std::unique_ptr<Far::TopologyRefiner> refiner_;
  std::unique_ptr<Bfr::RefinerSurfaceFactory<>> factory_;
  std::vector<double> points_;
};

std::array<Vec3, 6> as_array(const LimitPoint& p) { return {p.position, p.du, p.dv, p.duu, p.duv, p.dvv}; }

// The largest difference in positions (and in each derivative, scaled by
// the mesh's size) over random parameters of every face.
struct Differences {
  double position = 0.0;
  double derivatives = 0.0;
  int compared = 0;  ///< points
};

// Which faces are compared: all, those with an extraordinary corner, or
// those without one (interior vertices of another valence than the
// regular one; boundary vertices count as regular).
enum class Faces { all, irregular, regular };

Differences differences(const PolygonMesh& mesh, const char* name, Sdc::SchemeType type, int approx_level,
                        Faces which) {
  const LimitEvaluator evaluator(mesh, scheme(name));
  const BfrSurfaces bfr(mesh, type, approx_level);
  const bool triangles = evaluator.triangles();
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Differences d;
  const MeshTopology t(mesh);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    // Boundary vertices are regular with two faces (or a quad corner's one),
    // three for triangles.
    bool irregular = false;
    for (const Index v : t.face_vertices(f)) {
      const Index faces = t.vertex_face_count(v);
      irregular |= t.vertex_kind(v) == VertexKind::interior ? t.valence(v) != (triangles ? 6 : 4)
                                                            : faces != (triangles ? 3 : 2) && (triangles || faces != 1);
    }
    if ((which == Faces::irregular && !irregular) || (which == Faces::regular && irregular)) continue;
    for (int k = 0; k < 12; ++k) {
      double u = unit(random), v = unit(random);
      if (triangles && u + v > 1.0) {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      ++d.compared;
      const auto ours = as_array(evaluator.evaluate(f, u, v));
      const auto theirs = bfr.evaluate(f, u, v);
      d.position = std::max(d.position, norm(ours[0] - theirs[0]));
      for (std::size_t i = 1; i < 6; ++i) d.derivatives = std::max(d.derivatives, norm(ours[i] - theirs[i]));
    }
  }
  const double size = diagonal(mesh);
  return {d.position / size, d.derivatives / size, d.compared};
}

TEST(BfrAgreement, RegularFacesAreTheSamePatches) {
  const Differences quads = differences(grid_test::torus(8), "catmull-clark", Sdc::SCHEME_CATMARK, 2, Faces::all);
  EXPECT_LE(quads.position, 1e-12);
  EXPECT_LE(quads.derivatives, 1e-12);
  const Differences triangles =
      differences(grid_test::triangulated_torus(8), "loop", Sdc::SCHEME_LOOP, 2, Faces::all);
  EXPECT_LE(triangles.position, 1e-12);
  EXPECT_LE(triangles.derivatives, 1e-12);
}

// Boundaries, corners and infinitely sharp creases: both evaluate the
// reflected bicubic and box-spline patches (Bfr's regular boundary
// patches) away from extraordinary vertices.
TEST(BfrAgreement, BoundaryCreaseAndCornerFacesAreTheSamePatches) {
  // The creased cube split once more, so that faces along the creases have
  // no corner of valence 3.
  const PolygonMesh creased = refine(test::creased_cube(), scheme("bilinear"), test::levels(1));
  ASSERT_GT(creased.tags.creases.size(), 20u);
  for (const PolygonMesh& mesh : {test::jittered(test::quad_grid(5, 4), 3), test::jittered(creased, 4)}) {
    const Differences d = differences(mesh, "catmull-clark", Sdc::SCHEME_CATMARK, 2, Faces::regular);
    EXPECT_GE(d.compared, 20 * 12);  // every face of the grid, 72 of the cube's 96
    EXPECT_LE(d.position, 1e-12);
    EXPECT_LE(d.derivatives, 1e-12);
  }
}

// The double pyramid, jittered (split into quads for Catmull-Clark below).
PolygonMesh bipyramid(int n, unsigned seed) { return test::jittered(test::bipyramid(n), seed); }

TEST(BfrAgreement, NearExtraordinaryVerticesBfrApproachesTheExactSurfaceAsItIsolatesDeeper) {
  struct Case {
    const char* name;
    Sdc::SchemeType type;
    PolygonMesh mesh;
  };
  std::vector<Case> cases;
  for (int n : {3, 5, 8})
    cases.push_back({"catmull-clark", Sdc::SCHEME_CATMARK,
                     test::jittered(refine(bipyramid(n, 3u + n), scheme("bilinear"), test::levels(1)), 9)});
  for (int n : {4, 5, 8}) cases.push_back({"loop", Sdc::SCHEME_LOOP, bipyramid(n, 5u + n)});
  for (const Case& c : cases) {
    const Differences coarse = differences(c.mesh, c.name, c.type, 2, Faces::irregular);
    const Differences fine = differences(c.mesh, c.name, c.type, 6, Faces::irregular);
    std::cout << "[ bfr      ] " << c.name << ", " << c.mesh.vertex_count()
              << " vertices: Bfr's largest difference from the exact surface near extraordinary vertices, "
              << "relative to the mesh's size: " << coarse.position << " (isolation level 2), " << fine.position
              << " (level 6)\n";
    EXPECT_GT(coarse.position, 1e-9) << c.name << ": Bfr is exact here too?";
    EXPECT_LT(coarse.position, 1e-2) << c.name << ": the parameterizations differ";
    EXPECT_LT(fine.position, coarse.position / 4) << c.name;
  }
}

// Bfr's isolation stops at level 6 whatever a higher approximation level
// asks (measured: its values at 6 and 10 are identical), so it is the
// regular patches of the refinement only where a face's parameter lies at
// least 2^-5 from an extraordinary corner (one level of our isolation
// counted). There the two must agree to rounding, derivatives included;
// closer in, Bfr's difference is reported (the evaluator's own values there
// equal the closed-form limits at level-6 dyadic points,
// limit_evaluator_test.cpp).
TEST(BfrAgreement, AroundExtraordinaryVerticesWhereBfrIsExactTheTwoAgree) {
  for (const char* name : {"catmull-clark", "loop"}) {
    SCOPED_TRACE(name);
    const bool loop = std::string(name) == "loop";
    const PolygonMesh mesh =
        loop ? bipyramid(7, 2) : test::jittered(refine(bipyramid(5, 4), scheme("bilinear"), test::levels(1)), 6);
    const LimitEvaluator evaluator(mesh, scheme(name));
    const BfrSurfaces bfr(mesh, loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, 6);
    const MeshTopology t(mesh);
    const std::vector<std::array<double, 2>> quad = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const std::vector<std::array<double, 2>> triangle = {{0, 0}, {1, 0}, {0, 1}};
    const auto& corners = loop ? triangle : quad;
    const auto n = corners.size();
    const double size = diagonal(mesh);
    int checked = 0, negated = 0;
    double closer_in = 0.0;
    for (Index f = 0; f < mesh.face_count(); ++f) {
      const auto vertices = t.face_vertices(f);
      for (std::size_t k = 0; k < n; ++k) {
        if (t.valence(vertices[k]) == (loop ? 6 : 4)) continue;
        const auto& p = corners[k];
        const auto& next = corners[(k + 1) % n];
        const auto& prev = corners[(k + n - 1) % n];
        const auto at = [&](double a, double b) {
          return std::array<double, 2>{p[0] + a * (next[0] - p[0]) + b * (prev[0] - p[0]),
                                       p[1] + a * (next[1] - p[1]) + b * (prev[1] - p[1])};
        };
        for (const double a : {0.002, 0.04, 0.07, 0.2})
          for (const double b : {0.002, 0.04, 0.09}) {
            const auto [u, v] = at(a, b);
            const auto ours = as_array(evaluator.evaluate(f, u, v));
            const auto theirs = bfr.evaluate(f, u, v);
            if (std::max(a, b) < 1.0 / 32) {
              closer_in = std::max(closer_in, norm(ours[0] - theirs[0]) / size);
              continue;
            }
            ASSERT_LE(norm(ours[0] - theirs[0]), 1e-12 * size) << "face " << f << " at (" << u << ", " << v << ")";
            for (std::size_t i = 1; i < 6; ++i) {
              const double tolerance = 1e-10 * (size + norm(theirs[i]));
              // Bfr 3.5's Loop second derivatives come out negated in some
              // sub-patches of its isolation (ours match finite differences,
              // limit_evaluator_test.cpp): counted and reported, not failed.
              if (loop && i >= 3 && norm(ours[i] + theirs[i]) <= tolerance && norm(ours[i]) > tolerance) {
                ++negated;
                continue;
              }
              ASSERT_LE(norm(ours[i] - theirs[i]), tolerance)
                  << "face " << f << " derivative " << i << " at (" << u << ", " << v << ")";
            }
            ++checked;
          }
      }
    }
    std::cout << "[ bfr      ] " << name << ": equal to Bfr at " << checked
              << " points 2^-5 to 0.2 from extraordinary vertices; 0.002 from them Bfr differs by up to " << closer_in
              << " of the mesh's size";
    if (negated > 0) std::cout << "; Bfr's second derivatives are negated in " << negated << " of the comparisons";
    std::cout << "\n";
    EXPECT_GT(checked, 50);
  }
}

}  // namespace
}  // namespace subdiv
