#include "overflow_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "subdiv/core/error.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::detail {

namespace {

// Whether every coordinate in [begin, end) is finite: one comparison per
// coordinate, with no early exit, so the loop vectorizes (NaN compares false).
bool block_is_finite(const Vec3* begin, const Vec3* end) {
  constexpr double kMax = std::numeric_limits<double>::max();
  unsigned finite = 1;
  for (const Vec3* p = begin; p != end; ++p)
    finite &= static_cast<unsigned>(std::abs(p->x) <= kMax) & static_cast<unsigned>(std::abs(p->y) <= kMax) &
              static_cast<unsigned>(std::abs(p->z) <= kMax);
  return finite != 0;
}

}  // namespace

Index first_non_finite(const std::vector<Vec3>& positions) {
  const auto n = static_cast<Index>(positions.size());
  const Index found = tbb::parallel_reduce(
      tbb::blocked_range<Index>(0, n, Index{1} << 15), n,
      [&](const tbb::blocked_range<Index>& r, Index first) {
        const Vec3* base = positions.data();
        if (block_is_finite(base + r.begin(), base + r.end())) return first;
        for (Index v = r.begin(); v < r.end(); ++v)
          if (!is_finite(positions[static_cast<std::size_t>(v)])) return std::min(first, v);
        return first;
      },
      [](Index a, Index b) { return std::min(a, b); });
  return found == n ? Index{-1} : found;
}

void refuse_overflow(const std::vector<Vec3>& positions, const Scheme& scheme, int level) {
  const Index v = first_non_finite(positions);
  if (v < 0) return;
  throw InvalidInputError(std::string(scheme.name) + " overflowed the double range: vertex " + std::to_string(v) + " of level " +
                          std::to_string(level) + " is not finite (the input's coordinates are too large for this scheme's weights; "
                          "scale the mesh down)");
}

}  // namespace subdiv::detail
