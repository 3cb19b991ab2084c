#pragma once
// The centred uniform B-spline basis functions, written out from their
// definitions, for tests that compare a scheme with the spline it
// generalises.

#include <cmath>

namespace subdiv::test {

/// The cubic B-spline centred at 0, support [-2, 2].
inline double cubic_bspline(double x) {
  x = std::abs(x);
  if (x < 1.0) return 2.0 / 3.0 - x * x + 0.5 * x * x * x;
  if (x < 2.0) return (2.0 - x) * (2.0 - x) * (2.0 - x) / 6.0;
  return 0.0;
}

/// The quadratic B-spline centred at 0, support [-3/2, 3/2]: 3/4 - x^2 on
/// |x| <= 1/2, (3/2 - |x|)^2 / 2 on 1/2 <= |x| <= 3/2.
inline double quadratic_bspline(double x) {
  x = std::abs(x);
  if (x < 0.5) return 0.75 - x * x;
  if (x < 1.5) return 0.5 * (1.5 - x) * (1.5 - x);
  return 0.0;
}

/// The uniform B-spline of any degree n >= 0 centred at 0, support
/// [-(n+1)/2, (n+1)/2], by the Cox-de Boor recursion on the uniform knots
///   B_n(x) = ((h + x) B_(n-1)(x + 1/2) + (h - x) B_(n-1)(x - 1/2)) / n,
/// h = (n+1)/2, from B_0 = the indicator of [-1/2, 1/2).
inline double centred_bspline(int n, double x) {
  const double h = 0.5 * (n + 1);
  if (x < -h || x >= h) return 0.0;
  if (n == 0) return 1.0;
  return ((h + x) * centred_bspline(n - 1, x + 0.5) + (h - x) * centred_bspline(n - 1, x - 0.5)) / n;
}

}  // namespace subdiv::test
