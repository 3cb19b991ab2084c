#include "patch_frame.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace subdiv::detail {

namespace {

using Point = std::array<double, 2>;

Point at(const Frame& f, double s, double t) {
  return {f.origin[0] + s * f.axis_s[0] + t * f.axis_t[0], f.origin[1] + s * f.axis_s[1] + t * f.axis_t[1]};
}

// The frame with origin a, s running to b and t to c, at `scale` of those steps.
Frame frame_of(Point a, Point b, Point c, double scale) {
  Frame f;
  for (int i = 0; i < 2; ++i) {
    f.origin[i] = a[static_cast<std::size_t>(i)];
    f.axis_s[i] = scale * (b[static_cast<std::size_t>(i)] - a[static_cast<std::size_t>(i)]);
    f.axis_t[i] = scale * (c[static_cast<std::size_t>(i)] - a[static_cast<std::size_t>(i)]);
  }
  return f;
}

// The face's corners in the frame's parameters.
std::array<Point, 4> quad_corners(const Frame& f) { return {at(f, 0, 0), at(f, 1, 0), at(f, 1, 1), at(f, 0, 1)}; }
std::array<Point, 3> triangle_corners(const Frame& f) { return {at(f, 0, 0), at(f, 1, 0), at(f, 0, 1)}; }

Point midpoint(Point a, Point b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])}; }

}  // namespace

Frame frame_at_corner(const Frame& face, int corner, bool triangle) noexcept {
  if (triangle) {
    const auto p = triangle_corners(face);
    const auto k = static_cast<std::size_t>(corner);
    return frame_of(p[k], p[(k + 1) % 3], p[(k + 2) % 3], 1.0);
  }
  const auto p = quad_corners(face);
  const auto k = static_cast<std::size_t>(corner);
  return frame_of(p[k], p[(k + 1) % 4], p[(k + 3) % 4], 1.0);
}

Frame quad_child_frame(const Frame& face, int k) noexcept {
  const auto p = quad_corners(face);
  const auto i = static_cast<std::size_t>(k);
  return frame_of(p[i], p[(i + 1) % 4], p[(i + 3) % 4], 0.5);
}

Frame triangle_child_frame(const Frame& face, int k) noexcept {
  const auto p = triangle_corners(face);
  if (k == 3) return frame_of(midpoint(p[0], p[1]), midpoint(p[1], p[2]), midpoint(p[2], p[0]), 1.0);
  const auto i = static_cast<std::size_t>(k);
  return frame_of(p[i], p[(i + 1) % 3], p[(i + 2) % 3], 0.5);
}

FrameInverse inverse_of(const Frame& frame) noexcept {
  const double det = frame.axis_s[0] * frame.axis_t[1] - frame.axis_t[0] * frame.axis_s[1];
  return {frame.axis_t[1] / det, -frame.axis_t[0] / det, -frame.axis_s[1] / det, frame.axis_s[0] / det};
}

PatchParameter to_patch(const Frame& frame, const FrameInverse& inverse, double u, double v) noexcept {
  const double du = u - frame.origin[0], dv = v - frame.origin[1];
  return {inverse[0] * du + inverse[1] * dv, inverse[2] * du + inverse[3] * dv};
}

double distance_outside(PatchParameter at, bool triangle) noexcept {
  const double below = std::max({0.0, -at.s, -at.t});
  const double above = triangle ? std::max(0.0, at.s + at.t - 1.0) : std::max({0.0, at.s - 1.0, at.t - 1.0});
  return std::max(below, above);
}

PatchParameter clamp_into(PatchParameter at, bool triangle) noexcept {
  at.s = std::clamp(at.s, 0.0, 1.0);
  at.t = std::clamp(at.t, 0.0, 1.0);
  if (triangle && at.s + at.t > 1.0) {
    const double excess = 0.5 * (at.s + at.t - 1.0);
    at.s = std::max(0.0, at.s - excess);
    at.t = 1.0 - at.s;
  }
  return at;
}

void to_ptex(const FrameInverse& inverse, LimitPoint& p) noexcept {
  // d/du = ds/du d/ds + dt/du d/dt, and so on: k_ij the inverse's entries.
  const auto [k00, k01, k10, k11] = inverse;
  if (!(k00 == 1.0 && k01 == 0.0 && k10 == 0.0 && k11 == 1.0)) {  // else the ptex face itself
    const Vec3 du = p.du, dv = p.dv, duu = p.duu, duv = p.duv, dvv = p.dvv;
    p.du = k00 * du + k10 * dv;
    p.dv = k01 * du + k11 * dv;
    p.duu = (k00 * k00) * duu + (2.0 * k00 * k10) * duv + (k10 * k10) * dvv;
    p.duv = (k00 * k01) * duu + (k00 * k11 + k01 * k10) * duv + (k10 * k11) * dvv;
    p.dvv = (k01 * k01) * duu + (2.0 * k01 * k11) * duv + (k11 * k11) * dvv;
  }
  if (p.normal == Vec3{}) {
    const Vec3 n = cross(p.du, p.dv);
    const double length = norm(n);
    if (length > 1e-140 && length < 1e140) {
      p.normal = (1.0 / length) * n;
    } else {
      // Each derivative scaled to its largest coordinate first: very close
      // to an extraordinary corner they can lie beyond what squares hold.
      const auto scaled = [](Vec3 d) {
        const double largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        return largest > 0.0 ? (1.0 / largest) * d : d;
      };
      const Vec3 m = cross(scaled(p.du), scaled(p.dv));
      const double l = norm(m);
      if (l > 0.0) p.normal = (1.0 / l) * m;
    }
  }
}

}  // namespace subdiv::detail
