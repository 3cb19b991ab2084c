#pragma once
// The camera of a render: a perspective view of the scene's bounding sphere
// from a direction given in degrees, framed so that the sphere fills the
// image's shorter side. y is up (the usual convention of OBJ models).

#include <array>

#include "subdiv/core/types.h"

namespace subdiv::render {

/// Where the camera looks from: azimuth about the y axis (0: from +z,
/// 90: from +x) and elevation above the x-z plane, in degrees.
struct ViewDirection {
  double azimuth = 30.0;
  double elevation = 20.0;
};

/// Column-major 4 x 4 matrices, as OpenGL takes them.
struct Camera {
  std::array<double, 16> projection{};
  std::array<double, 16> view{};
};

/// The camera that frames the sphere (centre, radius) from `direction` in
/// an image of `width` x `height` pixels (30 degrees across its shorter
/// side). A radius of zero frames a unit sphere.
Camera frame_sphere(const Vec3& centre, double radius, const ViewDirection& direction, int width, int height);

/// Where a point lands in the image: pixel x from the left, y from the top.
std::array<double, 2> project(const Camera& camera, const Vec3& point, int width, int height);

}  // namespace subdiv::render
