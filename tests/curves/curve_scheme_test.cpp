#include "subdiv/curves/curve_scheme.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

#include "subdiv/core/error.h"
#include "support/bsplines.h"
#include "support/stencil_rows.h"

namespace subdiv {
namespace {

std::vector<Vec3> random_points(Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> p(static_cast<std::size_t>(n));
  for (Vec3& v : p) v = {u(rng), u(rng), u(rng)};
  return p;
}

double distance(Vec3 a, Vec3 b) { return norm(a - b); }

/// An observed error for the test report (--gtest_output=xml).
std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

/// Applies a mask anchored at `anchor` to points, wrapping (closed polygons).
Vec3 apply_wrapped(const CurveMask& mask, const std::vector<Vec3>& p, Index anchor) {
  const auto n = static_cast<Index>(p.size());
  Vec3 sum;
  for (const auto& [offset, weight] : mask)
    sum += weight * p[static_cast<std::size_t>(((anchor + offset) % n + n) % n)];
  return sum;
}

using test::cubic_bspline;
using test::quadratic_bspline;

/// sum_j p_j basis(t - j - shift), the control point j at parameter j + shift;
/// closed: j taken modulo the point count.
Vec3 spline(const std::vector<Vec3>& p, bool closed, double t, const std::function<double(double)>& basis,
            double shift = 0.0) {
  const auto n = static_cast<Index>(p.size());
  const auto j0 = static_cast<Index>(std::floor(t - shift));
  Vec3 sum;
  for (Index j = j0 - 3; j <= j0 + 3; ++j) {
    if (!closed && (j < 0 || j >= n)) continue;
    sum += basis(t - j - shift) * p[static_cast<std::size_t>((j % n + n) % n)];
  }
  return sum;
}

std::vector<CurveScheme> schemes_under_test() {
  std::vector<CurveScheme> out;
  for (const CurveScheme* s : all_curve_schemes()) out.push_back(*s);
  out.push_back(four_point_scheme(0.1));
  out.push_back(four_point_scheme(0.0));
  return out;
}

double sum_of(const CurveMask& m) {
  double s = 0.0;
  for (const auto& e : m) s += e.weight;
  return s;
}

TEST(CurveScheme, Registry) {
  std::vector<std::string_view> names;
  for (const CurveScheme* s : all_curve_schemes()) {
    names.push_back(s->name);
    EXPECT_EQ(find_curve_scheme(s->name), s);
    EXPECT_FALSE(s->summary.empty());
    EXPECT_FALSE(s->citation.empty());
    EXPECT_EQ(s->arity, 2);
  }
  EXPECT_EQ(names, (std::vector<std::string_view>{"cubic-bspline", "chaikin", "four-point"}));
  EXPECT_EQ(find_curve_scheme("cubic-bspline"), &cubic_bspline_curve_scheme());
  EXPECT_EQ(find_curve_scheme("chaikin"), &chaikin_curve_scheme());
  EXPECT_EQ(find_curve_scheme("four-point"), &four_point_curve_scheme());
  EXPECT_EQ(find_curve_scheme("catmull-clark"), nullptr);  // a surface scheme, not a curve scheme
  EXPECT_EQ(find_curve_scheme(""), nullptr);
  EXPECT_EQ(four_point_curve_scheme().tension, 1.0 / 16.0);
  const CurveScheme w = four_point_scheme(0.1);
  EXPECT_EQ(w.name, "four-point");
  EXPECT_EQ(w.tension, 0.1);
  EXPECT_DOUBLE_EQ(w.odd[0].weight, -0.1);
  EXPECT_DOUBLE_EQ(w.odd[1].weight, 0.6);
  EXPECT_TRUE(chaikin_curve_scheme().dual);
  EXPECT_FALSE(cubic_bspline_curve_scheme().dual);
  EXPECT_TRUE(four_point_curve_scheme().interpolating);
  EXPECT_FALSE(cubic_bspline_curve_scheme().interpolating);
}

TEST(CurveScheme, MasksSumToOne) {
  for (const CurveScheme& s : schemes_under_test()) {
    SCOPED_TRACE(std::string(s.name) + " w=" + std::to_string(s.tension));
    EXPECT_NEAR(sum_of(s.even), 1.0, 1e-15);
    EXPECT_NEAR(sum_of(s.odd), 1.0, 1e-15);
    EXPECT_FALSE(s.end.empty());
    for (const CurveMask& m : s.end) EXPECT_NEAR(sum_of(m), 1.0, 1e-15);
    ASSERT_FALSE(s.limit.empty());
    EXPECT_NEAR(sum_of(s.limit), 1.0, 1e-15);
    if (s.interpolating) {
      ASSERT_EQ(s.even.size(), 1u);
      EXPECT_EQ(s.even[0].offset, 0);
      EXPECT_EQ(s.even[0].weight, 1.0);
    }
    if (s.tangent.empty()) continue;
    // A derivative: 0 on constants, 1 on p_j = j (anchored at i, or at i + 1/2
    // for a dual scheme: the same, as the weights sum to 0).
    double moment = 0.0;
    for (const auto& e : s.tangent) moment += e.offset * e.weight;
    EXPECT_NEAR(sum_of(s.tangent), 0.0, 1e-15);
    EXPECT_NEAR(moment, 1.0, 1e-15);
  }
  // w = 0 (linear interpolation) has no tangent at the points; the C1 range has.
  EXPECT_TRUE(four_point_scheme(0.0).tangent.empty());
  EXPECT_TRUE(four_point_scheme(0.2).tangent.empty());
  EXPECT_FALSE(four_point_scheme(0.1).tangent.empty());
}

TEST(CurveScheme, GoldenMasks) {
  const auto masks_equal = [](const CurveMask& m, std::vector<std::pair<int, double>> expected) {
    ASSERT_EQ(m.size(), expected.size());
    for (std::size_t i = 0; i < m.size(); ++i) {
      EXPECT_EQ(m[i].offset, expected[i].first);
      EXPECT_DOUBLE_EQ(m[i].weight, expected[i].second);
    }
  };
  const CurveScheme& b = cubic_bspline_curve_scheme();
  masks_equal(b.even, {{-1, 1.0 / 8}, {0, 6.0 / 8}, {1, 1.0 / 8}});
  masks_equal(b.odd, {{0, 0.5}, {1, 0.5}});
  masks_equal(b.limit, {{-1, 1.0 / 6}, {0, 2.0 / 3}, {1, 1.0 / 6}});
  masks_equal(b.tangent, {{-1, -0.5}, {1, 0.5}});
  EXPECT_EQ(b.support_radius, 2.0);
  const CurveScheme& c = chaikin_curve_scheme();
  masks_equal(c.even, {{0, 0.75}, {1, 0.25}});
  masks_equal(c.odd, {{0, 0.25}, {1, 0.75}});
  EXPECT_EQ(c.support_radius, 1.5);
  const CurveScheme& f = four_point_curve_scheme();
  masks_equal(f.odd, {{-1, -1.0 / 16}, {0, 9.0 / 16}, {1, 9.0 / 16}, {2, -1.0 / 16}});
  ASSERT_EQ(f.end.size(), 2u);
  masks_equal(f.end[1], {{0, 5.0 / 16}, {1, 15.0 / 16}, {2, -5.0 / 16}, {3, 1.0 / 16}});
  masks_equal(f.tangent, {{-2, 1.0 / 12}, {-1, -8.0 / 12}, {1, 8.0 / 12}, {2, -1.0 / 12}});
  EXPECT_EQ(f.support_radius, 3.0);
}

// The child counts of curve_scheme.h, checked against refine().
TEST(CurveRefine, PointCounts) {
  const CurveScheme& b = cubic_bspline_curve_scheme();
  const CurveScheme& c = chaikin_curve_scheme();
  const CurveScheme& f = four_point_curve_scheme();
  EXPECT_EQ(refined_point_count(b, 5, true, 3), 40);
  EXPECT_EQ(refined_point_count(b, 5, false, 1), 9);
  EXPECT_EQ(refined_point_count(b, 5, false, 3), 33);  // 2^3 (n - 1) + 1
  EXPECT_EQ(refined_point_count(c, 5, false, 1), 10);  // p_0, 2(n - 1) cuts, p_4
  EXPECT_EQ(refined_point_count(c, 5, false, 3), 40);
  EXPECT_EQ(refined_point_count(c, 5, true, 2), 20);
  EXPECT_EQ(refined_point_count(f, 4, false, 2), 13);
  EXPECT_EQ(refined_point_count(f, 4, false, 0), 4);
  for (const CurveScheme& s : schemes_under_test())
    for (const bool closed : {true, false}) {
      const Polyline p{random_points(6, 1), closed};
      EXPECT_EQ(refine(p, s, 2).points.size(), static_cast<std::size_t>(refined_point_count(s, 6, closed, 2)));
      EXPECT_EQ(refine(p, s, 2).closed, closed);
    }
}

TEST(CurveRefine, MatchesStencils) {
  double worst = 0.0;
  for (const CurveScheme& s : schemes_under_test())
    for (const bool closed : {true, false})
      for (const Index n : {3, 4, 5, 9}) {
        if (n < (closed ? s.min_closed_points : s.min_open_points)) continue;
        const Polyline coarse{random_points(n, 7u + static_cast<unsigned>(n)), closed};
        for (int levels = 0; levels <= 4; ++levels) {
          SCOPED_TRACE(std::string(s.name) + " w=" + std::to_string(s.tension) + (closed ? " closed" : " open") +
                       " n=" + std::to_string(n) + " levels=" + std::to_string(levels));
          const Polyline fine = refine(coarse, s, levels);
          const StencilTable table = curve_stencils(s, n, closed, levels);
          ASSERT_EQ(table.source_count(), n);
          ASSERT_EQ(static_cast<std::size_t>(table.row_count()), fine.points.size());
          std::vector<Vec3> applied(fine.points.size());
          table.apply(coarse.points, applied);
          if (levels <= 1) {
            EXPECT_EQ(applied, fine.points);  // the same rows summed in the same order
          } else {
            for (std::size_t i = 0; i < applied.size(); ++i) {
              const double d = distance(applied[i], fine.points[i]);
              worst = std::max(worst, d);
              EXPECT_LE(d, 2e-15) << "point " << i;
            }
          }
        }
      }
  RecordProperty("worst_distance", sci(worst));
}

// A closed polygon shorter than a mask wraps onto the same point twice; the
// result must be that of the periodic polygon repeated three times.
TEST(CurveRefine, ShortClosedPolygonsWrap) {
  for (const CurveScheme& s : schemes_under_test()) {
    SCOPED_TRACE(std::string(s.name) + " w=" + std::to_string(s.tension));
    const Polyline triangle{random_points(3, 31), true};
    Polyline repeated{{}, true};
    for (int r = 0; r < 3; ++r)
      repeated.points.insert(repeated.points.end(), triangle.points.begin(), triangle.points.end());
    const Polyline a = refine(triangle, s, 2);
    const Polyline b = refine(repeated, s, 2);
    ASSERT_EQ(b.points.size(), 3 * a.points.size());
    for (std::size_t k = 0; k < b.points.size(); ++k)
      EXPECT_LE(distance(b.points[k], a.points[k % a.points.size()]), 1e-15) << "point " << k;
  }
}

// The limit and tangent masks are left eigenvectors of subdivision (eigenvalues
// 1 and 1/2): applied at child 2i after one level they give the same point and
// half the tangent (per the finer parameter) as at parent i.
TEST(CurveScheme, LimitAndTangentMasksAreEigenvectors) {
  double worst = 0.0;
  for (const CurveScheme& s : schemes_under_test()) {
    SCOPED_TRACE(std::string(s.name) + " w=" + std::to_string(s.tension));
    const Polyline coarse{random_points(12, 3), true};
    const Polyline fine = refine(coarse, s, 1);
    for (Index i = 0; i < 12; ++i) {
      const double d = distance(apply_wrapped(s.limit, fine.points, 2 * i), apply_wrapped(s.limit, coarse.points, i));
      EXPECT_LE(d, 1e-14);
      worst = std::max(worst, d);
      if (s.tangent.empty()) continue;
      const double dt =
          distance(apply_wrapped(s.tangent, fine.points, 2 * i), 0.5 * apply_wrapped(s.tangent, coarse.points, i));
      EXPECT_LE(dt, 1e-14);
      worst = std::max(worst, dt);
    }
  }
  RecordProperty("worst_distance", sci(worst));
}

// The survey's golden example: the cubic B-spline's local subdivision matrix,
// read off the recorded stencils of a closed 12-gon around point 6.
TEST(CurveCubicBSpline, SubdivisionMatrix5x5) {
  const StencilTable table = curve_stencils(cubic_bspline_curve_scheme(), 12, true, 1);
  const double expected[5][5] = {{1, 6, 1, 0, 0}, {0, 4, 4, 0, 0}, {0, 1, 6, 1, 0}, {0, 0, 4, 4, 0}, {0, 0, 1, 6, 1}};
  Eigen::Matrix<double, 5, 5> s = Eigen::Matrix<double, 5, 5>::Zero();
  for (int r = 0; r < 5; ++r) {
    const auto row = test::merged_row(table, 2 * 6 - 2 + r);
    for (const auto& [v, w] : row) {
      ASSERT_GE(v, 4) << "the 5-point neighbourhood is not invariant";
      ASSERT_LE(v, 8) << "the 5-point neighbourhood is not invariant";
      s(r, v - 4) = w;
    }
    for (int c = 0; c < 5; ++c) EXPECT_EQ(s(r, c), expected[r][c] / 8.0) << "row " << r << " column " << c;
  }
  // Its spectrum: 1, 1/2, 1/4, 1/8, 1/8.
  const Eigen::VectorXcd ev = s.eigenvalues();
  std::vector<double> re;
  for (Index i = 0; i < 5; ++i) {
    EXPECT_NEAR(ev[i].imag(), 0.0, 1e-12);
    re.push_back(ev[i].real());
  }
  std::sort(re.rbegin(), re.rend());
  const double spectrum[5] = {1.0, 0.5, 0.25, 0.125, 0.125};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(re[static_cast<std::size_t>(i)], spectrum[i], 1e-7);
}

TEST(CurveCubicBSpline, ClosedLimitIsTheUniformCubicBSpline) {
  const CurveScheme& s = cubic_bspline_curve_scheme();
  const Polyline coarse{random_points(7, 11), true};
  double raw_error[5] = {};
  double limit_error = 0.0;
  for (int levels = 1; levels <= 4; ++levels) {
    const Polyline fine = refine(coarse, s, levels);
    const double h = 1.0 / (1 << levels);
    for (Index k = 0; k < static_cast<Index>(fine.points.size()); ++k) {
      const Vec3 exact = spline(coarse.points, true, k * h, cubic_bspline);
      raw_error[levels] = std::max(raw_error[levels], distance(fine.points[static_cast<std::size_t>(k)], exact));
      if (levels == 4) limit_error = std::max(limit_error, distance(apply_wrapped(s.limit, fine.points, k), exact));
    }
  }
  EXPECT_LE(limit_error, 1e-14);
  // The refined points themselves approach the curve as h^2.
  for (int l = 2; l <= 4; ++l) EXPECT_GT(raw_error[l - 1] / raw_error[l], 3.5) << "level " << l;
  EXPECT_LT(raw_error[4], 0.01);
  RecordProperty("limit_error", sci(limit_error));
  RecordProperty("raw_error_level4", sci(raw_error[4]));
}

// Open: the end points are interpolated, and the limit is the cubic B-spline
// of the polygon extended by the phantom points 2 p_0 - p_1 and
// 2 p_{n-1} - p_{n-2} (cubic_bspline.cpp), everywhere up to the ends.
TEST(CurveCubicBSpline, OpenLimitHasNaturalInterpolatedEnds) {
  const CurveScheme& s = cubic_bspline_curve_scheme();
  const Polyline coarse{random_points(6, 13), false};
  std::vector<Vec3> extended{2.0 * coarse.points[0] - coarse.points[1]};
  extended.insert(extended.end(), coarse.points.begin(), coarse.points.end());
  extended.push_back(2.0 * coarse.points[5] - coarse.points[4]);
  const int levels = 4;
  const Polyline fine = refine(coarse, s, levels);
  ASSERT_EQ(fine.points.size(), 81u);
  EXPECT_EQ(fine.points.front(), coarse.points.front());
  EXPECT_EQ(fine.points.back(), coarse.points.back());
  double error = 0.0;
  for (std::size_t k = 0; k < fine.points.size(); ++k) {
    const Vec3 exact = spline(extended, false, static_cast<double>(k) / 16.0, cubic_bspline, -1.0);
    const Vec3 limit = k == 0 || k + 1 == fine.points.size()
                           ? fine.points[k]
                           : (fine.points[k - 1] + 4.0 * fine.points[k] + fine.points[k + 1]) * (1.0 / 6.0);
    error = std::max(error, distance(limit, exact));
  }
  EXPECT_LE(error, 1e-14);
  RecordProperty("limit_error", sci(error));
}

// Chaikin's limit is the quadratic B-spline with p_j at parameter j: child k
// of level L sits at s_L(k) = k / 2^L + 1/2 - 1/2^(L+1), and the limit mask
// (the midpoint of child edge (k, k+1)) is the curve at the edge's middle.
double chaikin_parameter(Index k, int levels) {
  const double h = 1.0 / (1 << levels);
  return k * h + 0.5 - 0.5 * h;
}

TEST(CurveChaikin, ClosedLimitIsTheUniformQuadraticBSpline) {
  const CurveScheme& s = chaikin_curve_scheme();
  const Polyline coarse{random_points(7, 17), true};
  double raw_error[5] = {};
  double limit_error = 0.0;
  for (int levels = 1; levels <= 4; ++levels) {
    const Polyline fine = refine(coarse, s, levels);
    const double h = 1.0 / (1 << levels);
    for (Index k = 0; k < static_cast<Index>(fine.points.size()); ++k) {
      const double t = chaikin_parameter(k, levels);
      raw_error[levels] = std::max(raw_error[levels], distance(fine.points[static_cast<std::size_t>(k)],
                                                               spline(coarse.points, true, t, quadratic_bspline)));
      if (levels == 4)
        limit_error = std::max(limit_error, distance(apply_wrapped(s.limit, fine.points, k),
                                                     spline(coarse.points, true, t + 0.5 * h, quadratic_bspline)));
    }
  }
  EXPECT_LE(limit_error, 1e-14);
  for (int l = 2; l <= 4; ++l) EXPECT_GT(raw_error[l - 1] / raw_error[l], 3.5) << "level " << l;
  EXPECT_LT(raw_error[4], 0.01);
  RecordProperty("limit_error", sci(limit_error));
  RecordProperty("raw_error_level4", sci(raw_error[4]));
}

// The limit at a control point's parameter: the primal schemes' limit mask,
// Chaikin's composed from its cuts and edge-midpoint limit (1/8, 3/4, 1/8),
// each equal to the spline evaluated at the point (an independent route).
TEST(CurveScheme, LimitAtPoint) {
  const CurveMask cubic = limit_at_point(cubic_bspline_curve_scheme());
  ASSERT_EQ(cubic.size(), cubic_bspline_curve_scheme().limit.size());
  for (std::size_t j = 0; j < cubic.size(); ++j) {
    EXPECT_EQ(cubic[j].offset, cubic_bspline_curve_scheme().limit[j].offset);
    EXPECT_EQ(cubic[j].weight, cubic_bspline_curve_scheme().limit[j].weight);
  }
  const CurveMask chaikin = limit_at_point(chaikin_curve_scheme());
  ASSERT_EQ(chaikin.size(), 3u);
  const double expected[3] = {1.0 / 8.0, 3.0 / 4.0, 1.0 / 8.0};
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(chaikin[j].offset, static_cast<int>(j) - 1);
    EXPECT_DOUBLE_EQ(chaikin[j].weight, expected[j]);
  }
  const Polyline coarse{random_points(7, 5), true};
  for (Index i = 0; i < 7; ++i) {
    EXPECT_LE(distance(apply_wrapped(chaikin, coarse.points, i),
                       spline(coarse.points, true, static_cast<double>(i), quadratic_bspline)), 1e-14) << i;
    EXPECT_LE(distance(apply_wrapped(limit_at_point(cubic_bspline_curve_scheme()), coarse.points, i),
                       spline(coarse.points, true, static_cast<double>(i), cubic_bspline)), 1e-14) << i;
  }
}

// Refinability: the refined points of a closed polygon are the control points
// of the same spline on the finer knots. Level L's point k is the control
// point at parameter k h (cubic) or chaikin_parameter(k, L) (quadratic), h =
// 2^-L, its basis function scaled by h; both curves are evaluated from the
// basis functions everywhere, not only at the points.
TEST(CurveRefine, ClosedBSplineSchemesKeepTheirSpline) {
  struct Case {
    const CurveScheme* scheme;
    std::function<double(double)> basis;
    bool quadratic;
  };
  for (const Case& c : {Case{&cubic_bspline_curve_scheme(), cubic_bspline, false},
                        Case{&chaikin_curve_scheme(), quadratic_bspline, true}}) {
    const Polyline coarse{random_points(6, 29), true};
    for (int levels = 1; levels <= 5; ++levels) {
      const Polyline fine = refine(coarse, *c.scheme, levels);
      const double h = 1.0 / (1 << levels);
      const double shift = c.quadratic ? chaikin_parameter(0, levels) / h : 0.0;
      double error = 0.0;
      for (int i = 0; i <= 6 * 64; ++i) {
        const double t = i / 64.0 + 0.01;  // off the knots and on every span
        error = std::max(
            error, distance(spline(fine.points, true, t / h, c.basis, shift), spline(coarse.points, true, t, c.basis)));
      }
      EXPECT_LE(error, 1e-13) << c.scheme->name << " level " << levels;
    }
  }
}

// Open: end points kept; the limit is the quadratic B-spline of the polygon
// with doubled end points (chaikin.cpp). With those doubled, the refined
// points are the pure corner cutting of the doubled polygon.
TEST(CurveChaikin, OpenLimitIsQuadraticBSplineWithDoubledEnds) {
  const CurveScheme& s = chaikin_curve_scheme();
  const Polyline coarse{random_points(5, 19), false};
  std::vector<Vec3> doubled{coarse.points.front()};
  doubled.insert(doubled.end(), coarse.points.begin(), coarse.points.end());
  doubled.push_back(coarse.points.back());
  const int levels = 4;
  const Polyline fine = refine(coarse, s, levels);
  ASSERT_EQ(fine.points.size(), 80u);
  EXPECT_EQ(fine.points.front(), coarse.points.front());
  EXPECT_EQ(fine.points.back(), coarse.points.back());
  std::vector<Vec3> fine_doubled{fine.points.front()};
  fine_doubled.insert(fine_doubled.end(), fine.points.begin(), fine.points.end());
  fine_doubled.push_back(fine.points.back());
  const double h = 1.0 / 16.0;
  double error = 0.0;
  for (Index k = 0; k + 1 < static_cast<Index>(fine_doubled.size()); ++k) {
    const Vec3 limit =
        0.5 * (fine_doubled[static_cast<std::size_t>(k)] + fine_doubled[static_cast<std::size_t>(k) + 1]);
    error = std::max(error,
                     distance(limit, spline(doubled, false, chaikin_parameter(k, levels) + 0.5 * h, quadratic_bspline)));
  }
  EXPECT_LE(error, 1e-14);
  RecordProperty("limit_error", sci(error));
}

TEST(CurveFourPoint, Interpolates) {
  for (const double w : {1.0 / 16.0, 0.1})
    for (const bool closed : {true, false}) {
      const CurveScheme s = four_point_scheme(w);
      const Polyline coarse{random_points(6, 23), closed};
      const Polyline fine = refine(coarse, s, 3);
      for (std::size_t i = 0; i < coarse.points.size(); ++i) EXPECT_EQ(fine.points[8 * i], coarse.points[i]);
    }
}

// y = x^3 - 2x sampled at x = -3 .. 3: with w = 1/16 every refined point lies
// on the cubic, the end edges included (their end rule is the cubic's).
TEST(CurveFourPoint, ReproducesCubics) {
  const auto f = [](double x) { return x * x * x - 2.0 * x; };
  Polyline coarse;
  for (int x = -3; x <= 3; ++x) coarse.points.push_back({static_cast<double>(x), f(x), 0.0});
  const Polyline fine = refine(coarse, four_point_curve_scheme(), 3);
  ASSERT_EQ(fine.points.size(), 49u);
  double error = 0.0;
  for (std::size_t k = 0; k < fine.points.size(); ++k) {
    const double x = -3.0 + static_cast<double>(k) / 8.0;
    EXPECT_NEAR(fine.points[k].x, x, 1e-14);
    error = std::max(error, std::abs(fine.points[k].y - f(fine.points[k].x)));
  }
  EXPECT_LE(error, 1e-12);
  RecordProperty("cubic_error", sci(error));
  // The tangent mask gives the cubic's derivative at interior points.
  const CurveScheme& s = four_point_curve_scheme();
  for (Index i = 2; i + 2 < 7; ++i) {
    const double x = -3.0 + i;
    EXPECT_NEAR(apply_wrapped(s.tangent, coarse.points, i).y, 3.0 * x * x - 2.0, 1e-13);
  }
  // Another tension does not reproduce the cubic, but still linear data.
  const Polyline other = refine(coarse, four_point_scheme(0.1), 3);
  double off = 0.0;
  for (std::size_t k = 0; k < other.points.size(); ++k) {
    EXPECT_NEAR(other.points[k].x, -3.0 + static_cast<double>(k) / 8.0, 1e-14);
    off = std::max(off, std::abs(other.points[k].y - f(other.points[k].x)));
  }
  EXPECT_GT(off, 1e-3);
}

TEST(CurveScheme, Errors) {
  const auto message = [](const auto& call) {
    try {
      call();
    } catch (const InvalidInputError& e) {
      return std::string(e.what());
    }
    return std::string("no InvalidInputError");
  };
  const auto expect_message = [&](const auto& call, const std::string& part) {
    const std::string m = message(call);
    EXPECT_NE(m.find(part), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  };
  const CurveScheme& b = cubic_bspline_curve_scheme();
  const CurveScheme& f = four_point_curve_scheme();
  const Polyline three{random_points(3, 29), false};
  expect_message([&] { refine(three, b, -1); }, "levels must be >= 0, got -1");
  expect_message([&] { refine(three, f, 1); },
                 "curve scheme 'four-point': an open polyline needs at least 4 points, got 3");
  expect_message(
      [&] {
        refine(Polyline{random_points(2, 29), true}, b, 1);
      },
      "a closed polygon needs at least 3 points, got 2");
  expect_message(
      [&] {
        refine(Polyline{random_points(1, 29), false}, chaikin_curve_scheme(), 1);
      },
      "an open polyline needs at least 2 points, got 1");
  expect_message([&] { refine(Polyline{}, b, 0); }, "needs at least 2 points, got 0");
  expect_message([&] { curve_stencils(b, -5, true, 1); }, "needs at least 3 points, got -5");
  expect_message([&] { curve_stencils(b, 4, true, -2); }, "levels must be >= 0");
  expect_message([&] { refined_point_count(b, 4, true, 40); }, "would make more than 2147483647 points");
  expect_message([&] { four_point_scheme(std::nan("")); }, "tension w must be finite");
  CurveScheme ternary = b;
  ternary.arity = 3;
  expect_message([&] { refine(three, ternary, 1); }, "only binary schemes (arity 2) are supported, got arity 3");
  CurveScheme no_ends = b;  // the even mask at p_0 needs p_{-1}
  no_ends.end.clear();
  expect_message([&] { refine(three, no_ends, 1); }, "the mask of child 0 reaches point -1, outside the open polyline");
  CurveScheme empty = b;
  empty.odd.clear();
  expect_message([&] { refine(three, empty, 1); }, "masks must not be empty");
}

}  // namespace
}  // namespace subdiv
