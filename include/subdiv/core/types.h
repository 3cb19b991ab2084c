#pragma once
/// \file
/// Basic value types shared by every module.

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
  double x = 0.0;  ///< first coordinate
  double y = 0.0;  ///< second coordinate
  double z = 0.0;  ///< third coordinate

  /// Coordinate access by number.
  /// \param i 0 for x, 1 for y; any other value selects z.
  /// \return a reference to the coordinate.
  constexpr double& operator[](int i) noexcept { return i == 0 ? x : (i == 1 ? y : z); }
  /// Coordinate access by number.
  /// \param i 0 for x, 1 for y; any other value selects z.
  /// \return the coordinate's value.
  constexpr double operator[](int i) const noexcept { return i == 0 ? x : (i == 1 ? y : z); }

  /// Component-wise sum.
  /// \param a first summand.
  /// \param b second summand.
  /// \return a + b.
  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  /// Component-wise difference.
  /// \param a minuend.
  /// \param b subtrahend.
  /// \return a - b.
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  /// Scaling by a scalar.
  /// \param s the factor.
  /// \param a the vector.
  /// \return s a.
  friend constexpr Vec3 operator*(double s, Vec3 a) noexcept { return {s * a.x, s * a.y, s * a.z}; }
  /// Scaling by a scalar.
  /// \param a the vector.
  /// \param s the factor.
  /// \return s a.
  friend constexpr Vec3 operator*(Vec3 a, double s) noexcept { return s * a; }
  /// Adds \p b component-wise.
  /// \param b the vector to add.
  /// \return *this.
  constexpr Vec3& operator+=(Vec3 b) noexcept { x += b.x; y += b.y; z += b.z; return *this; }
  /// Exact component-wise equality (so 0.0 == -0.0, and NaN differs from everything).
  /// \param a first vector.
  /// \param b second vector.
  /// \return whether all three coordinates compare equal.
  friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

/// Dot product.
/// \param a first vector.
/// \param b second vector.
/// \return a . b.
constexpr double dot(Vec3 a, Vec3 b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// Cross product (right-handed).
/// \param a first vector.
/// \param b second vector.
/// \return a x b.
constexpr Vec3 cross(Vec3 a, Vec3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Euclidean length.
/// \param a the vector.
/// \return |a|, computed as sqrt(dot(a, a)) (may overflow to infinity for huge coordinates).
inline double norm(Vec3 a) noexcept { return std::sqrt(dot(a, a)); }
/// Whether every coordinate is finite.
/// \param a the vector.
/// \return false if any coordinate is NaN or infinite.
inline bool is_finite(Vec3 a) noexcept {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace subdiv
