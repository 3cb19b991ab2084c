#pragma once
/// \file
/// Basis functions of the regular patches of Catmull-Clark and Loop, with
/// their first and second derivatives: the limit surface over a regular face
/// is sum_i w_i(u, v) p_i over the face's control points (their order:
/// analysis/patch_points.h).
///
/// - Catmull-Clark: the uniform bicubic B-spline over a quad whose four
///   corners have valence 4. Control point (i, j), i and j in 0..3, is grid
///   point (i - 1, j - 1) with the face at [0, 1]^2; its weight is
///   N(u)_i N(v)_j, N the uniform cubic B-spline basis.
/// - Loop: the quartic three-direction box spline over a triangle whose
///   three corners have valence 6. The triangle is lattice points (0, 0),
///   (1, 0), (0, 1), parameter (u, v) the point u e1 + v e2; the 12 control
///   points are, in order, lattice points (0,-1) (1,-1) (2,-1) (-1,0) (0,0)
///   (1,0) (2,0) (-1,1) (0,1) (1,1) (-1,2) (0,2) (kBoxSplineLattice). The
///   weights are Stam's polynomials ("Evaluation of Loop subdivision
///   surfaces", SIGGRAPH 1998): a 12 x 15 table over the quartic monomials,
///   differentiated monomial by monomial here. The tests check them against
///   Loop's own refinement and limit masks.
///
/// The *_point functions evaluate a patch over its control points directly,
/// in fewer operations than weights times points (the bicubic one as a
/// tensor product): the evaluators' inner loop.
#include <array>
#include <cstddef>

#include "subdiv/core/types.h"

namespace subdiv {

/// The limit surface and its derivatives at one parameter of a patch.
struct PatchPoint {
  Vec3 position, du, dv, duu, duv, dvv;
};

/// Weights of N control points and their derivatives at one (u, v).
template <int N>
struct PatchWeights {
  std::array<double, N> value{};  ///< w_i
  std::array<double, N> du{};     ///< dw_i / du
  std::array<double, N> dv{};     ///< dw_i / dv
  std::array<double, N> duu{};    ///< d2w_i / du2
  std::array<double, N> duv{};    ///< d2w_i / du dv
  std::array<double, N> dvv{};    ///< d2w_i / dv2
};

/// The lattice point of each box-spline control point (see the file comment).
inline constexpr std::array<std::array<int, 2>, 12> kBoxSplineLattice = {{
    {0, -1}, {1, -1}, {2, -1}, {-1, 0}, {0, 0}, {1, 0}, {2, 0}, {-1, 1}, {0, 1}, {1, 1}, {-1, 2}, {0, 2}}};

/// The bicubic B-spline weights at (u, v); any real (u, v) evaluates the
/// polynomial, the face is [0, 1]^2.
/// \param u the first parameter.
/// \param v the second parameter.
/// \return 16 weights, control point (i, j) at index i + 4 j.
PatchWeights<16> bicubic_bspline_weights(double u, double v) noexcept;

/// The quartic box-spline weights at (u, v); the face is u, v >= 0,
/// u + v <= 1, and any real (u, v) evaluates the polynomial.
/// \param u the first parameter.
/// \param v the second parameter.
/// \return 12 weights in the order of kBoxSplineLattice.
PatchWeights<12> box_spline_weights(double u, double v) noexcept;

/// The uniform cubic B-spline basis at t and its first and second
/// derivatives.
struct CubicBasis {
  std::array<double, 4> value, d1, d2;
};

/// The uniform cubic B-spline basis on [0, 1] (any real t evaluates the
/// polynomials). Inline: the evaluators' inner loop calls it twice.
/// \param t the parameter.
/// \return the four basis functions and their derivatives.
inline CubicBasis cubic_bspline(double t) noexcept {
  constexpr double kSixth = 1.0 / 6.0;
  const double s = 1.0 - t, t2 = t * t, t3 = t2 * t;
  CubicBasis b;
  b.value = {s * s * s * kSixth, (3.0 * t3 - 6.0 * t2 + 4.0) * kSixth, (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) * kSixth,
             t3 * kSixth};
  b.d1 = {-0.5 * s * s, 0.5 * (3.0 * t2 - 4.0 * t), 0.5 * (-3.0 * t2 + 2.0 * t + 1.0), 0.5 * t2};
  b.d2 = {s, 3.0 * t - 2.0, -3.0 * t + 1.0, t};
  return b;
}

/// The bicubic B-spline patch at (u, v) as a tensor product: equal to
/// bicubic_bspline_weights applied to the points, up to rounding.
/// \param point `point(i)` is control point i (0..15, in
///   bicubic_bspline_weights' order); read once each.
/// \param u the first parameter.
/// \param v the second parameter.
/// \return position and derivatives with respect to (u, v).
template <class Points>
PatchPoint bicubic_bspline_point(const Points& point, double u, double v) noexcept {
  const CubicBasis bu = cubic_bspline(u);
  const CubicBasis bv = cubic_bspline(v);
  PatchPoint p{};
  for (std::size_t j = 0; j < 4; ++j) {
    // Row j along u: the curve, its first and its second derivative.
    Vec3 curve{}, d1{}, d2{};
    for (std::size_t i = 0; i < 4; ++i) {
      const Vec3 c = point(i + 4 * j);
      curve += bu.value[i] * c;
      d1 += bu.d1[i] * c;
      d2 += bu.d2[i] * c;
    }
    p.position += bv.value[j] * curve;
    p.du += bv.value[j] * d1;
    p.duu += bv.value[j] * d2;
    p.dv += bv.d1[j] * curve;
    p.duv += bv.d1[j] * d1;
    p.dvv += bv.d2[j] * curve;
  }
  return p;
}

/// The quartic box-spline patch over 12 control points (in
/// kBoxSplineLattice's order) at (u, v): equal to box_spline_weights
/// applied to the points, up to rounding.
/// \param points the 12 control points.
/// \param u the first parameter.
/// \param v the second parameter.
/// \return position and derivatives with respect to (u, v).
PatchPoint box_spline_point(const std::array<Vec3, 12>& points, double u, double v) noexcept;

}  // namespace subdiv
