#pragma once
// Curve subdivision schemes as runtime values, and the refinement of
// polylines with them.
//
// A binary scheme's rules are two masks over parent points, each a list of
// (offset, weight) pairs relative to an anchor point i:
//
//   primal schemes (cubic-bspline, four-point): child 2i is the "even"
//     (vertex) point, made around parent point i; child 2i+1 is the "odd"
//     (edge) point, made around the edge (i, i+1).
//   dual schemes (chaikin): both children are cut from the edge (i, i+1):
//     child 2i by the "even" mask (the cut nearer p_i), child 2i+1 by the
//     "odd" mask (the cut nearer p_{i+1}). No child belongs to a parent point.
//
// Everything a scheme weighs is data in its one file (src/curves/<scheme>.cpp):
// the two masks, the end masks of open polylines, the limit and tangent
// masks. refine() and curve_stencils() evaluate the same masks through one
// function, so applying the recorded table is refining ("rules are weights,
// and there is one path").
//
// Child points of one level, for n parent points (indices as above):
//
//   closed: 2n children; child 2i+e is mask e (even 0, odd 1) anchored at i,
//     parent indices taken modulo n.
//   open, primal: 2n-1 children (2i for i in [0, n), 2i+1 for i in [0, n-1)).
//     With E = end.size(), children 0 .. E-1 use end[0 .. E-1] (offsets from
//     p_0) and children 2n-2-c their mirror images (offset o -> point
//     n-1-o); the children between use the generic masks.
//   open, dual: 2(n-1) + 2E children: end[0 .. E-1] first, then the two cuts
//     of each edge i in [0, n-1) (child E+2i+e is mask e anchored at i), then
//     the mirror images of the end masks (child count-1-c mirrors end[c]).
//     Chaikin keeps both end points (E = 1): 2n children.

#include <span>
#include <string_view>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/core/stencil_table.h"

namespace subdiv {

/// One weight of a curve mask: on the parent point anchor + offset.
struct CurveMaskEntry {
  int offset = 0;
  double weight = 0.0;
};
using CurveMask = std::vector<CurveMaskEntry>;

struct CurveScheme {
  std::string_view name;       ///< as users type it: "cubic-bspline"
  std::string_view summary;    ///< one line
  std::string_view citation;   ///< the paper the rules come from
  int arity = 2;               ///< children per parent point (closed); only 2 is supported
  bool interpolating = false;  ///< primal, and the even mask is the identity
  bool dual = false;           ///< both masks cut an edge (see the file comment)
  double tension = 0.0;        ///< the scheme's parameter (four-point's w); 0 if it has none
  CurveMask even;              ///< child 2i
  CurveMask odd;               ///< child 2i+1
  /// Open polylines: the masks of the first children, offsets from p_0,
  /// mirrored at the far end (see the file comment for where they go).
  std::vector<CurveMask> end;
  std::string_view end_rule;  ///< one line: what the end masks do and what the limit does there
  Index min_open_points = 2;
  Index min_closed_points = 3;
  /// The basis function (the limit of refining a unit impulse at one parent
  /// point) vanishes farther than this from the point, in parent edge
  /// lengths: 2 for the cubic B-spline, 1.5 for Chaikin, 3 for four-point.
  /// The local subdivision matrix of a primal scheme spans the
  /// 2 floor(r) + 1 points around a point (5 for the cubic B-spline).
  double support_radius = 0.0;
  /// Closed-form masks on the regular (closed, or interior) neighbourhood,
  /// anchored like the even mask: at point i for primal schemes, at the
  /// midpoint of the edge (i, i+1) for dual ones. Empty when unknown.
  /// limit: the limit point there. tangent: the derivative of the limit
  /// curve with respect to the parameter that puts the parent points at unit
  /// spacing (point i at t = i); refined once, the same mask at child 2i gives
  /// half of it. The survey writes the cubic B-spline's as (-1, 0, 1), twice
  /// ours.
  CurveMask limit;
  CurveMask tangent;
};

/// cubic-bspline: even 1/8 [1 6 1], odd 1/2 [1 1]; ends interpolated.
const CurveScheme& cubic_bspline_curve_scheme();
/// chaikin: corner cutting, 3/4 1/4 and 1/4 3/4 on each edge; ends kept.
const CurveScheme& chaikin_curve_scheme();
/// four-point with the tension w = 1/16 (reproduces cubics): the registry's.
const CurveScheme& four_point_curve_scheme();
inline constexpr double kFourPointTension = 1.0 / 16.0;
/// four-point with tension w: odd (-w, 1/2 + w, 1/2 + w, -w). Named
/// "four-point" whatever w is; `tension` holds w. Throws InvalidInputError for
/// a w that is not finite.
CurveScheme four_point_scheme(double w);

/// The limit mask at the parameter of parent point i (offsets from i) on a
/// closed or interior neighbourhood: the scheme's `limit` for primal
/// schemes; for dual ones the `limit` mask, anchored at the child edge whose
/// midpoint sits at point i's parameter, composed with the two cuts next to
/// point i (odd mask of edge (i-1, i), even mask of edge (i, i+1)): Chaikin's
/// 1/8, 3/4, 1/8. Empty where `limit` is.
CurveMask limit_at_point(const CurveScheme& scheme);

/// Every registered curve scheme: cubic-bspline, chaikin, four-point (w = 1/16).
std::span<const CurveScheme* const> all_curve_schemes();
/// The curve scheme with this name, or nullptr.
const CurveScheme* find_curve_scheme(std::string_view name);

struct Polyline {
  std::vector<Vec3> points;
  bool closed = false;  ///< the last point joins the first
};

/// How many points `levels` refinements of `point_count` points make (see the
/// file comment). Throws InvalidInputError for too few points, levels < 0, a
/// scheme that is not binary, or a count an Index cannot hold.
Index refined_point_count(const CurveScheme& scheme, Index point_count, bool closed, int levels);

/// The polyline refined `levels` times (levels = 0: a copy). Throws
/// InvalidInputError as refined_point_count() does, and for a scheme whose
/// masks reach outside an open polyline.
Polyline refine(const Polyline& polyline, const CurveScheme& scheme, int levels);

/// The table from the `point_count` coarse points to the points of level
/// `levels` (identity for 0), recorded from the same masks as refine() and
/// composed over levels: applying it to the coarse points gives refine()'s
/// points, to rounding (bit for bit for one level).
StencilTable curve_stencils(const CurveScheme& scheme, Index point_count, bool closed, int levels);

}  // namespace subdiv
