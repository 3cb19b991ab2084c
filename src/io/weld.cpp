#include "weld.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace subdiv::detail {

namespace {

struct Key {
  std::uint64_t x, y, z;
  friend bool operator==(const Key&, const Key&) = default;
};

struct KeyHash {
  std::size_t operator()(const Key& k) const noexcept {
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ULL;
    h ^= (k.y + 0x632BE59BD9B4E019ULL + (h << 6) + (h >> 2));
    h ^= (k.z + 0x85EBCA77C2B2AE63ULL + (h << 6) + (h >> 2));
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// The bits of a coordinate, with -0 read as +0 so that equal values share a key.
std::uint64_t exact_bits(double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); }

// The cell of a coordinate on a grid of the tolerance's spacing, clamped far
// out (points there still compare by distance, so clamping only costs time).
std::int64_t cell(double v, double spacing) {
  constexpr double limit = 4.0e18;
  return static_cast<std::int64_t>(std::clamp(std::floor(v / spacing), -limit, limit));
}

Key cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  return {static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y), static_cast<std::uint64_t>(z)};
}

bool within(Vec3 a, Vec3 b, double tolerance) {
  return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance && std::abs(a.z - b.z) <= tolerance;
}

}  // namespace

std::vector<Index> weld(const std::vector<Vec3>& points, double tolerance, std::vector<Vec3>& vertices) {
  std::vector<Index> vertex_of(points.size());
  const auto append = [&](Vec3 p) {
    vertices.push_back(p);
    return static_cast<Index>(vertices.size() - 1);
  };
  if (tolerance < 0.0) {
    for (std::size_t i = 0; i < points.size(); ++i) vertex_of[i] = append(points[i]);
    return vertex_of;
  }
  if (tolerance == 0.0) {
    std::unordered_map<Key, Index, KeyHash> first;
    first.reserve(points.size() / 4);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3 p = points[i];
      const auto [it, inserted] = first.try_emplace({exact_bits(p.x), exact_bits(p.y), exact_bits(p.z)}, 0);
      if (inserted) it->second = append(p);
      vertex_of[i] = it->second;
    }
    return vertex_of;
  }
  // A grid of cells as wide as the tolerance: a vertex within it lies in one
  // of the 27 cells around the point's. Each cell lists its vertices through
  // `next_in_cell`, newest first.
  std::unordered_map<Key, Index, KeyHash> newest;
  std::vector<Index> next_in_cell;
  const std::size_t base = vertices.size();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    const std::int64_t cx = cell(p.x, tolerance), cy = cell(p.y, tolerance), cz = cell(p.z, tolerance);
    Index found = std::numeric_limits<Index>::max();
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = newest.find(cell_key(cx + dx, cy + dy, cz + dz));
          if (it == newest.end()) continue;
          for (Index v = it->second; v >= 0; v = next_in_cell[static_cast<std::size_t>(v) - base])
            if (v < found && within(vertices[static_cast<std::size_t>(v)], p, tolerance)) found = v;
        }
    if (found != std::numeric_limits<Index>::max()) {
      vertex_of[i] = found;
      continue;
    }
    const Index v = append(p);
    vertex_of[i] = v;
    const auto [it, inserted] = newest.try_emplace(cell_key(cx, cy, cz), v);
    next_in_cell.push_back(inserted ? Index{-1} : it->second);
    it->second = v;
  }
  return vertex_of;
}

}  // namespace subdiv::detail
