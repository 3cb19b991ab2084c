// Chaikin's corner cutting: all of its weights.
//
// Source: G. M. Chaikin, "An algorithm for high speed curve generation",
// Computer Graphics and Image Processing 3(4):346-349, 1974; the limit is the
// uniform quadratic B-spline (Riesenfeld, "On Chaikin's algorithm", CGIP
// 4(3):304-310, 1975).
//
// A dual scheme: each edge (p_i, p_{i+1}) gives two children,
//   child 2i     3/4 p_i + 1/4 p_{i+1}   (the "even" mask),
//   child 2i+1   1/4 p_i + 3/4 p_{i+1}   (the "odd" mask),
// and the parent points themselves are not kept. With p_j at parameter j,
// the limit at the edge midpoint i + 1/2 is (p_i + p_{i+1})/2 and the
// tangent there p_{i+1} - p_i per unit parameter; child 2i sits at parameter
// i + 1/4, child 2i+1 at i + 3/4.
//
// Open ends: both end points are kept (the common variant), so an open
// polyline of n points gives 2n: p_0, the 2(n-1) cuts, p_{n-1}. This is pure
// corner cutting of the polygon with its end points doubled (the edge
// (p_0, p_0) cuts to p_0 twice), so the limit is the uniform quadratic
// B-spline of p_0, p_0, p_1, ..., p_{n-1}, p_{n-1}: it interpolates the end
// points, tangent to the end edges.

#include "subdiv/curves/curve_scheme.h"

namespace subdiv {

const CurveScheme& chaikin_curve_scheme() {
  static const CurveScheme scheme{
      .name = "chaikin",
      .summary = "approximating, dual corner cutting; C1 uniform quadratic B-spline; end points kept",
      .citation =
          "G. M. Chaikin: An algorithm for high speed curve generation, Computer Graphics and Image Processing "
          "3(4):346-349, 1974",
      .arity = 2,
      .interpolating = false,
      .dual = true,
      .tension = 0.0,
      .even = {{0, 3.0 / 4.0}, {1, 1.0 / 4.0}},
      .odd = {{0, 1.0 / 4.0}, {1, 3.0 / 4.0}},
      .end = {{{0, 1.0}}},
      .end_rule =
          "end points kept: the quadratic B-spline of the polygon with doubled end points "
          "(interpolated ends, tangent to the end edges)",
      .min_open_points = 2,
      .min_closed_points = 3,
      .support_radius = 1.5,
      .limit = {{0, 0.5}, {1, 0.5}},
      .tangent = {{0, -1.0}, {1, 1.0}},
  };
  return scheme;
}

}  // namespace subdiv
