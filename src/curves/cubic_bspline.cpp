// The uniform cubic B-spline curve scheme: all of its weights.
//
// Source: J. M. Lane, R. F. Riesenfeld, "A theoretical development for the
// computer generation and display of piecewise polynomial surfaces", IEEE
// Trans. PAMI 2(1):35-46, 1980 (refinement by doubling and averaging); in the
// form of Zorin's survey (SIGGRAPH 2000 course notes, section 2):
//   even (vertex) point  1/8 (p_{i-1} + 6 p_i + p_{i+1});
//   odd (edge) point     1/2 (p_i + p_{i+1});
//   limit point          1/6 (p_{i-1} + 4 p_i + p_{i+1});
//   tangent              1/2 (p_{i+1} - p_{i-1}) per unit parameter (the
//                        survey's (-1, 0, 1), halved; see curve_scheme.h).
// The local subdivision matrix over p_{i-2} .. p_{i+2} is the survey's
// (1/8) [1 6 1 0 0; 0 4 4 0 0; 0 1 6 1 0; 0 0 4 4 0; 0 0 1 6 1].
//
// Open ends: the survey's boundary curve rule, which subdiv's Catmull-Clark
// and Loop use along boundaries and creases with corner ends: the end point
// is kept, and the edge point next to it is the usual midpoint. This is the
// uniform rule applied to the polygon extended by the phantom point
// p_{-1} = 2 p_0 - p_1 (1/8 (2 p_0 - p_1) + 3/4 p_0 + 1/8 p_1 = p_0, and the
// next level's phantom point 2 p_0 - (p_0 + p_1)/2 is the midpoint of p_{-1}
// and p_0, as the uniform rule makes it), so the limit is the uniform cubic
// B-spline of that extended polygon: it interpolates p_0 with tangent
// p_1 - p_0 and zero curvature (a natural end).

#include "subdiv/curves/curve_scheme.h"

namespace subdiv {

const CurveScheme& cubic_bspline_curve_scheme() {
  static const CurveScheme scheme{
      .name = "cubic-bspline",
      .summary = "approximating, primal; C2 uniform cubic B-spline (Lane-Riesenfeld); ends interpolated",
      .citation =
          "J. M. Lane, R. F. Riesenfeld: A theoretical development for the computer generation and display of "
          "piecewise polynomial surfaces, IEEE Trans. PAMI 2(1):35-46, 1980",
      .arity = 2,
      .interpolating = false,
      .dual = false,
      .tension = 0.0,
      .even = {{-1, 1.0 / 8.0}, {0, 6.0 / 8.0}, {1, 1.0 / 8.0}},
      .odd = {{0, 0.5}, {1, 0.5}},
      .end = {{{0, 1.0}}},
      .end_rule =
          "end points kept, midpoints beside them: the cubic B-spline with phantom points 2 p_0 - p_1 "
          "(interpolated end, tangent p_1 - p_0, zero curvature)",
      .min_open_points = 2,
      .min_closed_points = 3,
      .support_radius = 2.0,
      .limit = {{-1, 1.0 / 6.0}, {0, 4.0 / 6.0}, {1, 1.0 / 6.0}},
      .tangent = {{-1, -0.5}, {1, 0.5}},
  };
  return scheme;
}

}  // namespace subdiv
