#pragma once
// Basic value types shared by every module.

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace subdiv {

/// Index of a vertex, face, edge or face corner. 32 bits keep index arrays
/// compact; readers reject inputs that would overflow it.
using Index = std::int32_t;

/// Marks "no element" (a missing edge, a ring that could not be ordered...).
inline constexpr Index kInvalidIndex = -1;

/// Largest element count a mesh may hold.
inline constexpr std::int64_t kMaxElements = std::numeric_limits<Index>::max();

/// Sharpness of an infinitely sharp crease or corner. OpenSubdiv treats any
/// sharpness >= 10 as infinite; we keep the value the user gave and compare
/// against this threshold.
inline constexpr double kInfiniteSharpness = 10.0;

/// A point or vector in 3-space, double precision.
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return s * a; }
  constexpr Vec3& operator+=(Vec3 b) { x += b.x; y += b.y; z += b.z; return *this; }
  friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline bool is_finite(Vec3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace subdiv
