#pragma once
/// \file
/// Curve subdivision schemes as runtime values, and the refinement of
/// polylines with them.
///
/// A binary scheme's rules are two masks over parent points, each a list of
/// (offset, weight) pairs relative to an anchor point i:
///
/// - primal schemes (cubic-bspline, four-point): child 2i is the "even"
///     (vertex) point, made around parent point i; child 2i+1 is the "odd"
///     (edge) point, made around the edge (i, i+1).
/// - dual schemes (chaikin): both children are cut from the edge (i, i+1):
///     child 2i by the "even" mask (the cut nearer p_i), child 2i+1 by the
///     "odd" mask (the cut nearer p_{i+1}). No child belongs to a parent point.
///
/// Everything a scheme weighs is data in its one file (`src/curves/<scheme>.cpp`):
/// the two masks, the end masks of open polylines, the limit and tangent
/// masks. refine() and curve_stencils() evaluate the same masks through one
/// function, so applying the recorded table is refining ("rules are weights,
/// and there is one path").
///
/// Child points of one level, for n parent points (indices as above):
///
/// - closed: 2n children; child 2i+e is mask e (even 0, odd 1) anchored at i,
///     parent indices taken modulo n.
/// - open, primal: 2n-1 children (2i for i in [0, n), 2i+1 for i in [0, n-1)).
///     With E = end.size(), children 0 .. E-1 use end[0 .. E-1] (offsets from
///     p_0) and children 2n-2-c their mirror images (offset o -> point
///     n-1-o); the children between use the generic masks.
/// - open, dual: 2(n-1) + 2E children: end[0 .. E-1] first, then the two cuts
///     of each edge i in [0, n-1) (child E+2i+e is mask e anchored at i), then
///     the mirror images of the end masks (child count-1-c mirrors end[c]).
///     Chaikin keeps both end points (E = 1): 2n children.

#include <span>
#include <string_view>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/core/stencil_table.h"

namespace subdiv {

/// One weight of a curve mask: on the parent point anchor + offset.
struct CurveMaskEntry {
  int offset = 0;       ///< the parent point's offset from the anchor
  double weight = 0.0;  ///< its weight in the child
};
/// A curve mask: the weights of one child (or of a limit or tangent
/// functional) on parent points relative to an anchor.
using CurveMask = std::vector<CurveMaskEntry>;

/// A binary curve subdivision scheme as data: its two masks, the end masks of
/// open polylines, and its closed-form limit and tangent masks (see the
/// layout of children above).
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
  Index min_open_points = 2;    ///< fewest points of an open polyline it refines (at least 2 are required)
  Index min_closed_points = 3;  ///< fewest points of a closed polygon it refines (at least 1 is required)
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
  /// The closed-form tangent mask, as described for `limit`; empty when
  /// unknown (four-point where it is not C1).
  CurveMask tangent;
};

/// cubic-bspline: even 1/8 [1 6 1], odd 1/2 [1 1]; ends interpolated.
/// \return The scheme, a static object built on the first call.
/// \throws std::bad_alloc if memory runs out building it on the first call.
const CurveScheme& cubic_bspline_curve_scheme();
/// chaikin: corner cutting, 3/4 1/4 and 1/4 3/4 on each edge; ends kept.
/// \return The scheme, a static object built on the first call.
/// \throws std::bad_alloc if memory runs out building it on the first call.
const CurveScheme& chaikin_curve_scheme();
/// four-point with the tension w = 1/16 (reproduces cubics): the registry's.
/// \return The scheme, a static object built on the first call.
/// \throws std::bad_alloc if memory runs out building it on the first call.
const CurveScheme& four_point_curve_scheme();
/// The four-point scheme's standard tension w = 1/16, with which it
/// reproduces cubics.
inline constexpr double kFourPointTension = 1.0 / 16.0;
/// four-point with tension w: odd (-w, 1/2 + w, 1/2 + w, -w). Named
/// "four-point" whatever w is; `tension` holds w. The tangent mask is given
/// only for 0 < w < (sqrt(5) - 1)/8, where the limit is C1.
/// \param w The tension.
/// \return The scheme, by value.
/// \throws InvalidInputError if \p w is not finite.
/// \throws std::bad_alloc if memory runs out.
CurveScheme four_point_scheme(double w);

/// The limit mask at the parameter of parent point i (offsets from i) on a
/// closed or interior neighbourhood: the scheme's `limit` for primal
/// schemes; for dual ones the `limit` mask, anchored at the child edge whose
/// midpoint sits at point i's parameter, composed with the two cuts next to
/// point i (odd mask of edge (i-1, i), even mask of edge (i, i+1)): Chaikin's
/// 1/8, 3/4, 1/8. Empty where `limit` is.
/// \param scheme The curve scheme.
/// \return The mask, offsets from point i, by increasing offset for dual
///         schemes (zero weights dropped).
/// \throws std::bad_alloc if memory runs out.
CurveMask limit_at_point(const CurveScheme& scheme);

/// Every registered curve scheme: cubic-bspline, chaikin, four-point (w = 1/16).
/// \return The schemes, in that order; static storage.
/// \throws std::bad_alloc if memory runs out building the schemes on the
///         first call.
std::span<const CurveScheme* const> all_curve_schemes();
/// The curve scheme with this name, or nullptr.
/// \param name The name as users type it ("cubic-bspline").
/// \return The registered scheme, or nullptr when none has that name.
/// \throws std::bad_alloc if memory runs out building the schemes on the
///         first call.
const CurveScheme* find_curve_scheme(std::string_view name);

/// A polyline: open, or closed into a polygon.
struct Polyline {
  std::vector<Vec3> points;  ///< the points in order
  bool closed = false;  ///< the last point joins the first
};

/// How many points \p levels refinements of \p point_count points make:
/// per level 2n for closed polygons, 2n - 1 for open primal polylines,
/// 2(n - 1) + 2 end.size() for open dual ones.
/// \param scheme The curve scheme.
/// \param point_count The number of coarse points.
/// \param closed Whether the points form a closed polygon.
/// \param levels The number of refinement steps, at least 0.
/// \return The number of points after \p levels steps.
/// \throws InvalidInputError if there are fewer points than the scheme needs
///         (min_open_points, at least 2; min_closed_points, at least 1), a
///         primal scheme's end masks do not fit the open polyline,
///         \p levels < 0, the scheme is not binary or has an empty mask, or
///         the count exceeds what an Index can hold.
Index refined_point_count(const CurveScheme& scheme, Index point_count, bool closed, int levels);

/// The polyline refined \p levels times (levels = 0: a copy, still checked).
/// \param polyline The coarse polyline.
/// \param scheme The curve scheme.
/// \param levels The number of refinement steps, at least 0.
/// \return The refined polyline, closed as \p polyline is.
/// \throws InvalidInputError as refined_point_count() does, if the polyline
///         has more points than an Index can count, and for a scheme whose
///         masks reach outside an open polyline.
/// \throws std::bad_alloc if memory runs out.
Polyline refine(const Polyline& polyline, const CurveScheme& scheme, int levels);

/// The table from the \p point_count coarse points to the points of level
/// \p levels (identity for 0), recorded from the same masks as refine() and
/// composed over levels: applying it to the coarse points gives refine()'s
/// points, to rounding (bit for bit for one level).
/// \param scheme The curve scheme.
/// \param point_count The number of coarse points.
/// \param closed Whether the points form a closed polygon.
/// \param levels The number of refinement steps, at least 0.
/// \return The composed table, refined_point_count() rows over
///         \p point_count sources.
/// \throws InvalidInputError as refined_point_count() does, and for a scheme
///         whose masks reach outside an open polyline.
/// \throws std::bad_alloc if memory runs out.
StencilTable curve_stencils(const CurveScheme& scheme, Index point_count, bool closed, int levels);

}  // namespace subdiv
