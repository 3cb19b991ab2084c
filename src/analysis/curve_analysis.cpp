#include "subdiv/analysis/curve_analysis.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

#include "subdiv/core/error.h"

namespace subdiv {

namespace {

constexpr int kMaxHalfWidth = 8;

// The matrix over the neighbourhood of half-width m, or nullopt when a row
// uses a point outside it. Primal: parents c-m .. c+m, children 2c-m ..
// 2c+m (child 2c is the vertex point of c). Dual: parents c-m+1 .. c+m,
// children 2c-m+1 .. 2c+m (children 2c and 2c+1 are the two cuts of the
// edge (c, c+1), whose midpoint is the edge's).
std::optional<Eigen::MatrixXd> neighbourhood_matrix(const StencilTable& table, Index points, Index centre, int m,
                                                    bool dual) {
  const int size = dual ? 2 * m : 2 * m + 1;
  const Index first_parent = centre - m + (dual ? 1 : 0);
  const Index first_child = 2 * centre - m + (dual ? 1 : 0);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(size, size);
  for (int r = 0; r < size; ++r) {
    const Index child = first_child + r;
    const auto vertices = table.row_vertices(child);
    const auto weights = table.row_weights(child);
    for (std::size_t e = 0; e < vertices.size(); ++e) {
      const Index column = ((vertices[e] - first_parent) % points + points) % points;
      if (column >= size) {
        if (weights[e] != 0.0) return std::nullopt;
        continue;
      }
      S(r, column) += weights[e];
    }
  }
  return S;
}

// The masks, the spectrum and the point's own conditions (a.c1: they hold).
CurveAnalysis analyze_curve_point(const CurveScheme& scheme, double tolerance) {
  // A closed polygon long enough that no mask wraps into the neighbourhood.
  const Index points = 8 * kMaxHalfWidth;
  const Index centre = points / 2;
  const StencilTable table = curve_stencils(scheme, points, true, 1);
  CurveAnalysis a;
  for (int m = 1; m <= kMaxHalfWidth && a.half_width == 0; ++m)
    if (auto S = neighbourhood_matrix(table, points, centre, m, scheme.dual)) {
      a.half_width = m;
      a.S = std::move(*S);
    }
  if (a.half_width == 0)
    throw InvalidInputError(std::string(scheme.name) + ": no invariant neighbourhood within " +
                            std::to_string(kMaxHalfWidth) + " points on either side");

  a.wide_S = *neighbourhood_matrix(table, points, centre, a.half_width + 1, scheme.dual);
  a.spectrum = spectrum(a.wide_S, tolerance);
  const auto all = a.spectrum.expanded();
  a.leading.assign(all.begin(), all.begin() + std::min<std::ptrdiff_t>(4, static_cast<std::ptrdiff_t>(all.size())));
  a.limit_mask = left_eigenvector(a.S, 1.0, tolerance);

  // Point positions ..., -1, 0, 1, ... (dual: -1/2, 1/2 around the edge).
  const auto n = a.S.rows();
  Eigen::VectorXd position(n);
  for (Eigen::Index i = 0; i < n; ++i)
    position[i] = static_cast<double>(i) - (scheme.dual ? (static_cast<double>(n) - 1.0) / 2.0 : a.half_width);

  const auto& v = a.spectrum.values;
  const bool unit = !v.empty() && std::abs(v[0].value - 1.0) < tolerance && v[0].algebraic == 1;
  if (!unit) {
    a.reason = "lambda_0 = 1 is not a simple eigenvalue";
    return a;
  }
  if (v.size() < 2 || !v[1].real() || v[1].algebraic != 1 || !(v[1].value.real() > 0.0)) {
    a.reason = "lambda_1 is not real, positive and simple";
    return a;
  }
  const double lambda1 = v[1].value.real();
  if (v.size() > 2 && std::abs(v[2].value) > lambda1 - tolerance) {
    a.reason = "|lambda_2| is not below lambda_1";
    return a;
  }
  if (auto l = left_eigenvector(a.S, lambda1, tolerance)) {
    const double scale = l->dot(position);
    if (std::abs(scale) > tolerance) a.tangent_mask = *l / scale;
  }
  // The right eigenvector of lambda_1 over the wide neighbourhood: the
  // characteristic map.
  const auto wide = a.wide_S.rows();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a.wide_S - lambda1 * Eigen::MatrixXd::Identity(wide, wide));
  lu.setThreshold(tolerance);
  const Eigen::VectorXd x = lu.kernel().col(0);
  bool increasing = true, decreasing = true;
  for (Eigen::Index i = 1; i < wide; ++i) {
    increasing = increasing && x[i] > x[i - 1];
    decreasing = decreasing && x[i] < x[i - 1];
  }
  if (!increasing && !decreasing) {
    a.reason = "the eigenvector of lambda_1 is not monotone: the characteristic map is not injective";
    return a;
  }
  a.c1 = true;
  a.reason = "lambda_1 simple and dominant, characteristic map monotone";
  return a;
}

}  // namespace

CurveAnalysis analyze_curve(const CurveScheme& scheme, double tolerance) {
  CurveAnalysis a = analyze_curve_point(scheme, tolerance);
  a.regular = regular_smoothness(curve_lattice_rule(scheme));
  const std::string at_point = "at a point: " + a.reason;
  if (a.regular.verdict == SmoothnessVerdict::c1 && !a.c1)
    a.verdict = SmoothnessVerdict::inconclusive;  // the two routes disagree: say so, claim nothing
  else
    a.verdict = a.regular.verdict;
  a.c1 = a.verdict == SmoothnessVerdict::c1;
  a.reason = a.regular.reason + "; " + at_point;
  return a;
}

}  // namespace subdiv
