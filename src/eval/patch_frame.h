#pragma once
// Frames of patches inside a ptex face: a patch's parameter (s, t) is the
// ptex parameter origin + s axis_s + t axis_t. A face's frame has its corner
// 0 at the origin, corner 1 at origin + axis_s and its last corner at
// origin + axis_t (a quad's corner 2 at origin + axis_s + axis_t). Every map
// here keeps the orientation (positive determinant).

#include <array>

#include "subdiv/eval/limit_evaluator.h"

namespace subdiv::detail {

using Frame = LimitEvaluator::Frame;

/// A patch's own parameter.
struct PatchParameter {
  double s = 0.0;
  double t = 0.0;
};

/// The same face's frame with corner `corner` (0..3 of a quad, 0..2 of a
/// triangle) at the origin, its next corner along s and its previous along t.
Frame frame_at_corner(const Frame& face, int corner, bool triangle) noexcept;

/// The frame of child `k` of a quad under the quad split: the child at the
/// quad's corner k, [corner, midpoint to the next, centre, midpoint from the
/// previous].
Frame quad_child_frame(const Frame& face, int k) noexcept;

/// The frame of child `k` of a triangle under the triangle split: children
/// 0..2 at corners 0..2, [corner, midpoint to the next, midpoint from the
/// previous]; child 3 the middle one, [midpoint 01, midpoint 12, midpoint 20].
Frame triangle_child_frame(const Frame& face, int k) noexcept;

/// A frame's inverse, row-major: (s, t) = J ((u, v) - origin). Kept per
/// patch, so that evaluation divides by nothing.
using FrameInverse = std::array<double, 4>;

/// The inverse of `frame` (see FrameInverse).
FrameInverse inverse_of(const Frame& frame) noexcept;

/// (s, t) of the ptex parameter (u, v) in `frame`, whose inverse is `inverse`.
PatchParameter to_patch(const Frame& frame, const FrameInverse& inverse, double u, double v) noexcept;

/// How far (s, t) lies outside the patch's domain (the unit square, or the
/// triangle s, t >= 0, s + t <= 1) in its own parameters; 0 inside.
double distance_outside(PatchParameter at, bool triangle) noexcept;

/// The nearest point of the domain (the point itself inside).
PatchParameter clamp_into(PatchParameter at, bool triangle) noexcept;

/// Turns a patch's point, in place, into the ptex face's: its derivatives
/// with respect to the ptex parameter (chain rule through the frame's
/// inverse), and its normal: the one given where set (an extraordinary
/// corner), else du x dv normalised.
void to_ptex(const FrameInverse& inverse, LimitPoint& point) noexcept;

}  // namespace subdiv::detail
