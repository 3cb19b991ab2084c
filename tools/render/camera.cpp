#include "camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace subdiv::render {

namespace {

constexpr double kFieldOfView = 30.0;  // degrees across the shorter side

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
Vec3 unit(const Vec3& a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

// gluLookAt's matrix.
std::array<double, 16> look_at(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 f = unit(target - eye);
  const Vec3 s = unit(cross(f, up));
  const Vec3 u = cross(s, f);
  return {s.x, u.x, -f.x, 0.0, s.y, u.y, -f.y, 0.0, s.z, u.z, -f.z, 0.0,
          -dot(s, eye), -dot(u, eye), dot(f, eye), 1.0};
}

// gluPerspective's matrix.
std::array<double, 16> perspective(double fovy_degrees, double aspect, double near, double far) {
  const double f = 1.0 / std::tan(radians(fovy_degrees) / 2.0);
  return {f / aspect, 0.0, 0.0, 0.0, 0.0, f, 0.0, 0.0, 0.0, 0.0, (far + near) / (near - far), -1.0,
          0.0, 0.0, 2.0 * far * near / (near - far), 0.0};
}

}  // namespace

Camera frame_sphere(const Vec3& centre, double radius, const ViewDirection& direction, int width, int height) {
  if (!(radius > 0.0)) radius = 1.0;
  const double aspect = static_cast<double>(width) / static_cast<double>(height);
  // 30 degrees across the shorter side; the vertical field follows.
  const double half_short = radians(kFieldOfView) / 2.0;
  const double fovy = aspect >= 1.0 ? kFieldOfView : 2.0 * std::atan(std::tan(half_short) / aspect) * 180.0 / std::numbers::pi;
  const double distance = 1.04 * radius / std::sin(half_short);
  const double az = radians(direction.azimuth), el = radians(direction.elevation);
  const Vec3 toward_eye{std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
  // Looking straight down or up, y cannot be the up direction.
  const Vec3 up = std::abs(std::cos(el)) < 1e-6 ? Vec3{-std::sin(az), 0.0, -std::cos(az)} * (el > 0 ? 1.0 : -1.0)
                                                 : Vec3{0.0, 1.0, 0.0};
  Camera camera;
  camera.view = look_at(centre + distance * toward_eye, centre, up);
  camera.projection = perspective(fovy, aspect, std::max(distance - 1.5 * radius, 1e-3 * distance),
                                  distance + 1.5 * radius);
  return camera;
}

std::array<double, 2> project(const Camera& camera, const Vec3& point, int width, int height) {
  const auto apply = [](const std::array<double, 16>& m, const std::array<double, 4>& v) {
    std::array<double, 4> r{};
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) r[row] += m[k * 4 + row] * v[k];
    return r;
  };
  const auto clip = apply(camera.projection, apply(camera.view, {point.x, point.y, point.z, 1.0}));
  const double x = clip[0] / clip[3], y = clip[1] / clip[3];
  return {(x + 1.0) / 2.0 * width, (1.0 - y) / 2.0 * height};
}

}  // namespace subdiv::render
