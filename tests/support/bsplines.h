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

}  // namespace subdiv::test
