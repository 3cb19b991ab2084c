// The four-point interpolating scheme: all of its weights.
//
// Source: N. Dyn, D. Levin, J. A. Gregory, "A 4-point interpolatory
// subdivision scheme for curve design", Computer Aided Geometric Design
// 4(4):257-268, 1987:
//   even point  p_i (kept: the scheme interpolates);
//   odd point   -w p_{i-1} + (1/2 + w)(p_i + p_{i+1}) - w p_{i+2}.
// The limit is C1 for 0 < w < (sqrt(5) - 1)/8; w = 1/16 makes the odd point
// the cubic through the four points at the edge midpoint, so the scheme
// reproduces cubics; w = 0 is linear interpolation.
//
// Limit mask: the identity. Tangent mask (derivative per unit parameter, p_i
// at t = i): t = (b, -a, 0, a, b) on p_{i-2} .. p_{i+2} with
// a = 1/(2 (1 - 4w)), b = -w/(1 - 4w). Derivation: refining once, the
// antisymmetric functional a (p_1 - p_{-1}) + b (p_2 - p_{-2}) becomes
// (a (1/2 + 2w) + b)(p_1 - p_{-1}) - a w (p_2 - p_{-2}); being half of itself
// needs b = -2 a w (both coefficients give it), and a derivative takes
// 1 on p_j = j: 2a + 4b = 1. At w = 1/16: (1, -8, 0, 8, -1)/12, the
// five-point central difference. Given only where the limit is C1.
//
// Open ends: the odd point of the end edge (p_0, p_1) uses the phantom point
// p_{-1} = 4 p_0 - 6 p_1 + 4 p_2 - p_3 (the cubic through p_0 .. p_3,
// extrapolated), which gives (1/2 - 3w, 1/2 + 7w, -5w, w) on p_0 .. p_3:
// (5/16, 15/16, -5/16, 1/16), the cubic's value at t = 1/2, for w = 1/16.
// So cubics are reproduced up to the ends, and linear data for every w. End
// points are kept like every even point; an open polyline needs 4 points.

#include <cmath>
#include <string>

#include "subdiv/core/error.h"
#include "subdiv/curves/curve_scheme.h"

namespace subdiv {

CurveScheme four_point_scheme(double w) {
  if (!std::isfinite(w))
    throw InvalidInputError("four-point scheme: the tension w must be finite, got " + std::to_string(w));
  const bool c1 = w > 0.0 && w < (std::sqrt(5.0) - 1.0) / 8.0;
  const double a = 1.0 / (2.0 * (1.0 - 4.0 * w));
  const double b = -w / (1.0 - 4.0 * w);
  return CurveScheme{
      .name = "four-point",
      .summary = "interpolating, primal; tension w (1/16: reproduces cubics; C1 for small w > 0, not from about 0.1927)",
      .citation =
          "N. Dyn, D. Levin, J. A. Gregory: A 4-point interpolatory subdivision scheme for curve design, Computer "
          "Aided Geometric Design 4(4):257-268, 1987",
      .arity = 2,
      .interpolating = true,
      .dual = false,
      .tension = w,
      .even = {{0, 1.0}},
      .odd = {{-1, -w}, {0, 0.5 + w}, {1, 0.5 + w}, {2, -w}},
      .end = {{{0, 1.0}}, {{0, 0.5 - 3.0 * w}, {1, 0.5 + 7.0 * w}, {2, -5.0 * w}, {3, w}}},
      .end_rule =
          "end points kept; the end edge's point from the cubic extrapolated through p_0 .. p_3 "
          "(5/16, 15/16, -5/16, 1/16 at w = 1/16); at least 4 points",
      .min_open_points = 4,
      .min_closed_points = 3,
      .support_radius = w == 0.0 ? 1.0 : 3.0,
      .limit = {{0, 1.0}},
      .tangent = c1 ? CurveMask{{-2, -b}, {-1, -a}, {1, a}, {2, b}} : CurveMask{},
  };
}

const CurveScheme& four_point_curve_scheme() {
  static const CurveScheme scheme = four_point_scheme(kFourPointTension);
  return scheme;
}

}  // namespace subdiv
