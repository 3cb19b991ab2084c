#include "analysis/patch_basis.h"

namespace subdiv {
namespace {

/// The quartic monomials u^a v^b with a + b <= 4, in Stam's order:
/// 1, u, v, uu, uv, vv, uuu, uuv, uvv, vvv, uuuu, uuuv, uuvv, uvvv, vvvv.
constexpr std::array<std::array<int, 2>, 15> kMonomials = {{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {3, 0},
                                                            {2, 1}, {1, 2}, {0, 3}, {4, 0}, {3, 1}, {2, 2}, {1, 3},
                                                            {0, 4}}};

/// Stam's box-spline basis: row i, times 1/12, are control point i's
/// coefficients over kMonomials.
constexpr int kBoxSplineTable[12][15] = {
    {1, -2, -4, 0, 6, 6, 2, 0, -6, -4, -1, -2, 0, 2, 1},
    {1, 2, -2, 0, -6, 0, -4, 0, 6, 2, 2, 4, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -1, -2, 0, 0, 0},
    {1, -4, -2, 6, 6, 0, -4, -6, 0, 2, 1, 2, 0, -2, -1},
    {6, 0, 0, -12, -12, -12, 8, 12, 12, 8, -1, -2, 0, -2, -1},
    {1, 4, 2, 6, 6, 0, -4, -6, -12, -4, -1, -2, 0, 4, 2},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0},
    {1, -2, 2, 0, -6, 0, 2, 6, 0, -4, -1, -2, 0, 4, 2},
    {1, 2, 4, 0, 6, 6, -4, -12, -6, -4, 2, 4, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 2, 6, 6, 2, -1, -2, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -2, -1},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 1},
};

/// d^k/dx^k of x^a: a (a-1) .. (a-k+1) x^(a-k), 0 where k > a.
double derivative_of_power(double x, int a, int k) noexcept {
  if (k > a) return 0.0;
  double factor = 1.0;
  for (int i = 0; i < k; ++i) factor *= a - i;
  double power = 1.0;
  for (int i = 0; i < a - k; ++i) power *= x;
  return factor * power;
}

/// Every monomial's (ku, kv) derivative at (u, v).
std::array<double, 15> monomial_derivatives(double u, double v, int ku, int kv) noexcept {
  std::array<double, 15> m{};
  for (std::size_t i = 0; i < kMonomials.size(); ++i) {
    m[i] = derivative_of_power(u, kMonomials[i][0], ku) * derivative_of_power(v, kMonomials[i][1], kv);
  }
  return m;
}

void box_spline_derivative(double u, double v, int ku, int kv, std::array<double, 12>& out) noexcept {
  const std::array<double, 15> m = monomial_derivatives(u, v, ku, kv);
  for (std::size_t i = 0; i < out.size(); ++i) {
    double sum = 0.0;
    for (std::size_t j = 0; j < m.size(); ++j) sum += kBoxSplineTable[i][j] * m[j];
    out[i] = sum / 12.0;
  }
}

}  // namespace

PatchWeights<16> bicubic_bspline_weights(double u, double v) noexcept {
  const CubicBasis bu = cubic_bspline(u);
  const CubicBasis bv = cubic_bspline(v);
  PatchWeights<16> w;
  for (std::size_t j = 0; j < 4; ++j) {
    for (std::size_t i = 0; i < 4; ++i) {
      const std::size_t k = i + 4 * j;
      w.value[k] = bu.value[i] * bv.value[j];
      w.du[k] = bu.d1[i] * bv.value[j];
      w.dv[k] = bu.value[i] * bv.d1[j];
      w.duu[k] = bu.d2[i] * bv.value[j];
      w.duv[k] = bu.d1[i] * bv.d1[j];
      w.dvv[k] = bu.value[i] * bv.d2[j];
    }
  }
  return w;
}

PatchWeights<12> box_spline_weights(double u, double v) noexcept {
  PatchWeights<12> w;
  box_spline_derivative(u, v, 0, 0, w.value);
  box_spline_derivative(u, v, 1, 0, w.du);
  box_spline_derivative(u, v, 0, 1, w.dv);
  box_spline_derivative(u, v, 2, 0, w.duu);
  box_spline_derivative(u, v, 1, 1, w.duv);
  box_spline_derivative(u, v, 0, 2, w.dvv);
  return w;
}

PatchPoint box_spline_point(const std::array<Vec3, 12>& points, double u, double v) noexcept {
  // The patch as a polynomial: its coefficient of each monomial, from the
  // table's (integer, mostly zero) entries.
  std::array<Vec3, 15> coefficient{};
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = 0; j < coefficient.size(); ++j)
      if (kBoxSplineTable[i][j] != 0) coefficient[j] += static_cast<double>(kBoxSplineTable[i][j]) * points[i];
  }
  const auto derivative = [&](int ku, int kv) {
    const std::array<double, 15> m = monomial_derivatives(u, v, ku, kv);
    Vec3 sum{};
    for (std::size_t j = 0; j < m.size(); ++j) sum += m[j] * coefficient[j];
    return (1.0 / 12.0) * sum;
  };
  return {derivative(0, 0), derivative(1, 0), derivative(0, 1), derivative(2, 0), derivative(1, 1), derivative(0, 2)};
}

}  // namespace subdiv
