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
#include <array>

namespace subdiv {

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

}  // namespace subdiv
