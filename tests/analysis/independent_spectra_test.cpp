// Every number `subdiv analyze` prints for Loop and Catmull-Clark at
// interior valences k = 3..12, against an independent computation: the
// local subdivision matrices written from the published rules on a layout
// built here (the two-ring for the spectrum, the one-ring for the masks),
// matched to the analysis' neighbourhood by layout position only, their
// spectra from a plain dense Eigen solver, and the closed forms of the
// subdominant eigenvalue and of the limit and tangent masks.
//
// Rules (Loop 1987; Catmull and Clark 1978, as in Stam 1998 and Zorin's
// survey, section 4):
//   Loop: vertex (1 - k beta) v + beta sum(neighbours), beta(k) =
//     (1/k) (5/8 - (3/8 + 1/4 cos(2 pi / k))^2); edge 3/8, 3/8 on its ends,
//     1/8, 1/8 on the opposite vertices.
//   Catmull-Clark: face point the centroid; edge point (v + w + f_1 + f_2)/4
//     with its faces' points; vertex point (F + 2 R + (n - 3) v) / n, F the
//     mean of the face points around v, R the mean of the edge midpoints.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "subdiv/analysis/analyze.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"

namespace subdiv {
namespace {

constexpr double kTolerance = 1e-10;

// A planar layout of k sectors of a regular grid around the origin, built
// here: sector s spans the rays at 2 pi s / k and 2 pi (s + 1) / k.
struct Layout {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;

  int point(Vec3 p) {
    for (std::size_t i = 0; i < points.size(); ++i)
      if (norm(points[i] - p) < 1e-9) return static_cast<int>(i);
    points.push_back(p);
    return static_cast<int>(points.size()) - 1;
  }
  int find(Vec3 p) const {
    for (std::size_t i = 0; i < points.size(); ++i)
      if (norm(points[i] - p) < 1e-9) return static_cast<int>(i);
    return -1;
  }
  // Faces that contain vertex v (and w, when given).
  std::vector<int> faces_with(int v, int w = -1) const {
    std::vector<int> out;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto& face = faces[f];
      if (std::find(face.begin(), face.end(), v) != face.end() &&
          (w < 0 || std::find(face.begin(), face.end(), w) != face.end()))
        out.push_back(static_cast<int>(f));
    }
    return out;
  }
  // Neighbours of v: the vertices next to it along its faces' sides.
  std::vector<int> neighbours(int v) const {
    std::vector<int> out;
    for (const int f : faces_with(v)) {
      const auto& face = faces[static_cast<std::size_t>(f)];
      const std::size_t n = face.size();
      const std::size_t i = static_cast<std::size_t>(std::find(face.begin(), face.end(), v) - face.begin());
      for (const int w : {face[(i + 1) % n], face[(i + n - 1) % n]})
        if (std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
    }
    return out;
  }
};

Vec3 ray(int k, int s) {
  const double a = 2.0 * std::numbers::pi * s / k;
  return {std::cos(a), std::sin(a), 0.0};
}

// `rings` rings of faces: quads (i, j) .. (i+1, j+1) or the triangles of
// the same cells, per sector.
Layout grid(int k, int rings, bool quads) {
  Layout l;
  auto at = [&](int s, int i, int j) { return l.point(static_cast<double>(i) * ray(k, s) + static_cast<double>(j) * ray(k, s + 1)); };
  for (int s = 0; s < k; ++s)
    for (int i = 0; i < rings; ++i)
      for (int j = 0; j < rings; ++j) {
        if (quads) {
          l.faces.push_back({at(s, i, j), at(s, i + 1, j), at(s, i + 1, j + 1), at(s, i, j + 1)});
        } else if (i + j < rings) {
          l.faces.push_back({at(s, i, j), at(s, i + 1, j), at(s, i, j + 1)});
          if (i + j + 1 < rings) l.faces.push_back({at(s, i + 1, j), at(s, i + 1, j + 1), at(s, i, j + 1)});
        }
      }
  return l;
}

using Row = std::map<int, double>;  // layout vertex -> weight

void add(Row& to, const Row& from, double scale) {
  for (const auto& [v, w] : from) to[v] += scale * w;
}

double loop_beta_formula(int k) {
  const double c = 0.375 + 0.25 * std::cos(2.0 * std::numbers::pi / k);
  return (0.625 - c * c) / k;
}

// The point one level down at layout position q (a vertex point at a
// vertex, an edge point at an edge midpoint, a face point at a quad's
// centroid), from the rules above.
Row loop_point(const Layout& l, Vec3 q) {
  if (const int v = l.find(q); v >= 0) {
    const std::vector<int> ring = l.neighbours(v);
    const int n = static_cast<int>(ring.size());
    const double beta = loop_beta_formula(n);
    Row r{{v, 1.0 - n * beta}};
    for (const int w : ring) r[w] += beta;
    return r;
  }
  for (std::size_t v = 0; v < l.points.size(); ++v)
    for (const int w : l.neighbours(static_cast<int>(v))) {
      if (norm(0.5 * (l.points[v] + l.points[static_cast<std::size_t>(w)]) - q) > 1e-9) continue;
      const std::vector<int> sides = l.faces_with(static_cast<int>(v), w);
      EXPECT_EQ(sides.size(), 2u);
      Row r{{static_cast<int>(v), 0.375}, {w, 0.375}};
      for (const int f : sides)
        for (const int u : l.faces[static_cast<std::size_t>(f)])
          if (u != static_cast<int>(v) && u != w) r[u] += 0.125;
      return r;
    }
  ADD_FAILURE() << "no vertex or edge of the layout at (" << q.x << ", " << q.y << ")";
  return {};
}

Row cc_face_point(const Layout& l, int f) {
  Row r;
  const auto& face = l.faces[static_cast<std::size_t>(f)];
  for (const int v : face) r[v] += 1.0 / static_cast<double>(face.size());
  return r;
}

Row cc_point(const Layout& l, Vec3 q) {
  if (const int v = l.find(q); v >= 0) {
    const std::vector<int> faces = l.faces_with(v);
    const std::vector<int> ring = l.neighbours(v);
    const double n = static_cast<double>(ring.size());
    EXPECT_EQ(faces.size(), ring.size());
    Row r{{v, (n - 3.0) / n}};
    for (const int f : faces) add(r, cc_face_point(l, f), 1.0 / (n * n));      // F / n
    for (const int w : ring) add(r, Row{{v, 0.5}, {w, 0.5}}, 2.0 / (n * n));  // 2 R / n
    return r;
  }
  for (std::size_t v = 0; v < l.points.size(); ++v)
    for (const int w : l.neighbours(static_cast<int>(v))) {
      if (norm(0.5 * (l.points[v] + l.points[static_cast<std::size_t>(w)]) - q) > 1e-9) continue;
      const std::vector<int> sides = l.faces_with(static_cast<int>(v), w);
      EXPECT_EQ(sides.size(), 2u);
      Row r{{static_cast<int>(v), 0.25}, {w, 0.25}};
      for (const int f : sides) add(r, cc_face_point(l, f), 0.25);
      return r;
    }
  for (std::size_t f = 0; f < l.faces.size(); ++f) {
    Vec3 centroid;
    for (const int v : l.faces[f]) centroid += 0.25 * l.points[static_cast<std::size_t>(v)];
    if (norm(centroid - q) < 1e-9) return cc_face_point(l, static_cast<int>(f));
  }
  ADD_FAILURE() << "no element of the layout at (" << q.x << ", " << q.y << ")";
  return {};
}

// The matrix over the analysis' neighbourhood (its layout, in its order):
// row a is the point at layout[a] / 2, the image of layout[a]. Rows are
// written over `l`'s vertices, then found in the neighbourhood by position;
// weight outside it fails.
Eigen::MatrixXd from_rules(bool loop, const Layout& l, const std::vector<Vec3>& layout) {
  const auto n = static_cast<Eigen::Index>(layout.size());
  std::vector<int> column(l.points.size(), -1);
  for (Eigen::Index a = 0; a < n; ++a) {
    const int v = l.find(layout[static_cast<std::size_t>(a)]);
    EXPECT_GE(v, 0) << "neighbourhood vertex " << a << " is not in the layout";
    if (v >= 0) column[static_cast<std::size_t>(v)] = static_cast<int>(a);
  }
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Vec3 q = 0.5 * layout[static_cast<std::size_t>(a)];
    for (const auto& [v, w] : loop ? loop_point(l, q) : cc_point(l, q)) {
      const int b = column[static_cast<std::size_t>(v)];
      if (b < 0) {
        EXPECT_EQ(w, 0.0) << "row " << a << " weights a vertex outside the neighbourhood";
        continue;
      }
      S(a, b) += w;
    }
  }
  return S;
}

// The spectrum of S by a plain dense solver, checked against the analysis'
// distinct eigenvalues: each with algebraic multiplicity m takes the m
// computed eigenvalues nearest to it; their mean (accurate where a Jordan
// block splits the copies by roundoff) matches it, and so does each copy
// where the analysis reports no Jordan block. Returns the computed values
// sorted by magnitude.
std::vector<std::complex<double>> check_spectrum(const Eigen::MatrixXd& S, const Spectrum& reported, const std::string& what) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(S, false);
  EXPECT_EQ(solver.info(), Eigen::Success) << what;
  const Eigen::VectorXcd values = solver.eigenvalues();
  std::vector<std::complex<double>> pool(values.begin(), values.end());
  std::vector<std::complex<double>> sorted = pool;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](std::complex<double> a, std::complex<double> b) { return std::abs(a) > std::abs(b); });
  EXPECT_EQ(static_cast<Eigen::Index>(reported.dimension()), S.rows()) << what;
  for (const Eigenvalue& e : reported.values) {
    std::sort(pool.begin(), pool.end(), [&](std::complex<double> a, std::complex<double> b) {
      return std::abs(a - e.value) < std::abs(b - e.value);
    });
    const auto m = static_cast<std::size_t>(e.algebraic);
    if (pool.size() < m) {
      ADD_FAILURE() << what << ": more eigenvalues reported than the matrix has";
      return sorted;
    }
    std::complex<double> mean;
    for (std::size_t i = 0; i < m; ++i) mean += pool[i] / static_cast<double>(m);
    EXPECT_LT(std::abs(mean - e.value), kTolerance) << what << ": eigenvalue " << e.value << " x" << m << ", computed mean " << mean;
    if (!e.defective()) {
      for (std::size_t i = 0; i < m; ++i) {
        EXPECT_LT(std::abs(pool[i] - e.value), kTolerance)
            << what << ": eigenvalue " << e.value << " copy " << i << ": " << pool[i];
      }
    }
    pool.erase(pool.begin(), pool.begin() + static_cast<std::ptrdiff_t>(m));
  }
  EXPECT_TRUE(pool.empty()) << what << ": " << pool.size() << " eigenvalues not reported";
  return sorted;
}

// The left eigenvectors of the eigenvalue lambda span the same space as
// `basis` (columns), both of dimension basis.cols().
void expect_same_left_space(const Eigen::MatrixXd& S, double lambda, const Eigen::MatrixXd& basis,
                            const Eigen::VectorXd& v, const std::string& what) {
  // v is a left eigenvector of S ...
  EXPECT_LT((S.transpose() * v - lambda * v).cwiseAbs().maxCoeff(), kTolerance) << what;
  // ... in the span of the closed form's basis.
  const Eigen::MatrixXd q = basis.householderQr().householderQ() * Eigen::MatrixXd::Identity(basis.rows(), basis.cols());
  EXPECT_LT((v - q * (q.transpose() * v)).cwiseAbs().maxCoeff(), kTolerance) << what;
}

// Reif's eigenvalue condition on the independently computed spectrum:
// 1 simple, lambda_1 = lambda_2 real positive, above |lambda_3|, with two
// eigenvectors (rank of S - lambda_1 I from an SVD).
bool reif_condition(const Eigen::MatrixXd& S, const std::vector<std::complex<double>>& l) {
  if (l.size() < 4 || std::abs(l[0] - 1.0) > kTolerance || std::abs(l[1]) > 1.0 - kTolerance) return false;
  if (std::abs(l[1].imag()) > kTolerance || std::abs(l[2].imag()) > kTolerance || l[1].real() <= 0 || l[2].real() <= 0)
    return false;
  if (std::abs(l[2]) <= std::abs(l[3]) + kTolerance) return false;
  const Eigen::MatrixXd shifted = S - l[1].real() * Eigen::MatrixXd::Identity(S.rows(), S.cols());
  const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(shifted).singularValues();
  const auto null = (sigma.array() < 1e-9).count();
  return null == (std::abs(l[1] - l[2]) < kTolerance ? 2 : 1);
}

struct Expected {
  double lambda;  ///< the subdominant eigenvalue's closed form
  Eigen::VectorXd limit;
  Eigen::MatrixXd tangents;  ///< two columns spanning the tangent masks
};

// Closed forms on the one-ring in the analysis' order (matched by position).
Expected closed_forms(bool loop, int k, const std::vector<Vec3>& layout) {
  const auto n = static_cast<Eigen::Index>(layout.size());
  Expected e{0.0, Eigen::VectorXd::Zero(n), Eigen::MatrixXd::Zero(n, 2)};
  const double theta = 2.0 * std::numbers::pi / k;
  for (Eigen::Index a = 0; a < n; ++a) {
    const Vec3 p = layout[static_cast<std::size_t>(a)];
    const double angle = std::atan2(p.y, p.x), r = norm(p);
    if (loop) {
      const double beta = loop_beta_formula(k), chi = 8.0 * beta / (3.0 + 8.0 * k * beta);
      e.limit[a] = r < 1e-9 ? 1.0 - k * chi : chi;
      if (r > 1e-9) e.tangents.row(a) << std::cos(angle), std::sin(angle);
    } else {
      // Centre n^2, edge neighbours 4, face vertices 1, over n (n + 5).
      // Tangents (Halstead et al.): A_k cos(2 pi i / k) on edge neighbour
      // i, cos(2 pi i / k) + cos(2 pi (i + 1) / k) on the face vertex
      // between i and i + 1; the face vertex sits at angle theta (i + 1/2),
      // where that is 2 cos(theta / 2) cos(angle).
      const double d = k * (k + 5.0);
      const double A = 1.0 + std::cos(theta) + std::cos(theta / 2) * std::sqrt(2.0 * (9.0 + std::cos(theta)));
      // Edge neighbours lie on the rays, face vertices halfway between (by
      // angle: at k = 3 both are at distance 1).
      const double half_steps = (angle < 0 ? angle + 2.0 * std::numbers::pi : angle) / (theta / 2);
      const bool edge = std::lround(half_steps) % 2 == 0;
      e.limit[a] = r < 1e-9 ? k * k / d : edge ? 4.0 / d : 1.0 / d;
      const double scale = r < 1e-9 ? 0.0 : edge ? A : 2.0 * std::cos(theta / 2);
      e.tangents.row(a) << scale * std::cos(angle), scale * std::sin(angle);
    }
  }
  e.lambda = loop ? 0.375 + 0.25 * std::cos(theta)
                  : (5.0 + std::cos(theta) + std::cos(theta / 2) * std::sqrt(2.0 * (9.0 + std::cos(theta)))) / 16.0;
  return e;
}

void check_scheme(const Scheme& scheme, bool loop) {
  for (int k = 3; k <= 12; ++k) {
    const std::string what = std::string(scheme.name) + " k=" + std::to_string(k);
    const ConfigurationAnalysis a = analyze(scheme, {Configuration::Kind::interior, k, CornerType::convex});
    // The printed n: the one-ring (Loop k + 1, Catmull-Clark 2k + 1).
    ASSERT_EQ(a.matrix.S.rows(), loop ? k + 1 : 2 * k + 1) << what;
    ASSERT_EQ(a.matrix.rings, 1) << what;
    ASSERT_EQ(a.wide_matrix.rings, 2) << what;
    // Matrices from the rules, on a layout three rings wide (every point the
    // two-ring's image needs is made by interior rules there).
    const Layout l = grid(k, 3, !loop);
    const Eigen::MatrixXd S1 = from_rules(loop, l, a.matrix.layout);
    const Eigen::MatrixXd S2 = from_rules(loop, l, a.wide_matrix.layout);
    ASSERT_EQ(a.wide_matrix.S.rows(), loop ? 3 * k + 1 : 6 * k + 1) << what;
    EXPECT_LT((a.matrix.S - S1).cwiseAbs().maxCoeff(), 1e-14) << what;
    EXPECT_LT((a.wide_matrix.S - S2).cwiseAbs().maxCoeff(), 1e-14) << what;

    // The full spectrum (of the two-ring, as printed), then the printed
    // leading values: lambda_1, lambda_2, |lambda_3|, lambda_1^2.
    const std::vector<std::complex<double>> mine = check_spectrum(S2, a.spectrum, what);
    ASSERT_GE(a.leading.size(), 4u) << what;
    const Expected closed = closed_forms(loop, k, a.matrix.layout);
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_NEAR(std::abs(a.leading[i]), std::abs(mine[i]), kTolerance) << what << " |lambda_" << i << "|";
    EXPECT_NEAR(a.leading[0].real(), 1.0, kTolerance) << what;
    EXPECT_NEAR(a.leading[1].real(), closed.lambda, kTolerance) << what;
    EXPECT_NEAR(a.leading[2].real(), closed.lambda, kTolerance) << what;
    EXPECT_EQ(a.leading[1].imag(), 0.0) << what;
    EXPECT_NEAR((a.leading[1] * a.leading[1]).real(), closed.lambda * closed.lambda, kTolerance) << what;
    if (loop) {
      // |lambda_3|: the largest of 5/8 - k beta = lambda_1^2, 3/8 + 1/4
      // cos(4 pi / k) and the two-ring's 1/8.
      const double third = std::max({closed.lambda * closed.lambda,
                                     k > 3 ? std::fabs(0.375 + 0.25 * std::cos(4.0 * std::numbers::pi / k)) : 0.0, 0.125});
      EXPECT_NEAR(std::abs(a.leading[3]), third, kTolerance) << what;
    }
    // Reif's condition, from the independent spectrum.
    EXPECT_EQ(a.eigenvalue_condition, reif_condition(S2, mine)) << what;
    EXPECT_TRUE(a.eigenvalue_condition) << what;

    // Limit mask, entry for entry; tangent masks: left eigenvectors of the
    // independent matrix spanning the closed form's pair.
    ASSERT_TRUE(a.limit_mask.has_value()) << what;
    EXPECT_LT((*a.limit_mask - closed.limit).cwiseAbs().maxCoeff(), kTolerance) << what;
    EXPECT_LT((S1.transpose() * closed.limit - closed.limit).cwiseAbs().maxCoeff(), kTolerance) << what;
    ASSERT_TRUE(a.tangent_masks.has_value()) << what;
    for (int t = 0; t < 2; ++t)
      expect_same_left_space(S1, closed.lambda, closed.tangents, (*a.tangent_masks)[t], what + " tangent " + std::to_string(t));
    EXPECT_NEAR((*a.tangent_masks)[0].dot((*a.tangent_masks)[1]), 0.0, kTolerance) << what;
    EXPECT_EQ(a.verdict, SmoothnessVerdict::c1) << what << ": " << a.reason;
  }
}

TEST(IndependentSpectra, LoopInteriorValences3To12) { check_scheme(loop_scheme(), true); }

TEST(IndependentSpectra, CatmullClarkInteriorValences3To12) { check_scheme(catmull_clark_scheme(), false); }

}  // namespace
}  // namespace subdiv
