// A curve scheme on a polyline: a closed square refined by a scheme chosen
// by name (cubic-bspline, chaikin, four-point), with the limit point of
// each corner where the scheme has a limit mask.
//
//   refine_curve four-point 1

#include <cstdio>
#include <cstdlib>

#include "subdiv/core/error.h"
#include "subdiv/curves/curve_scheme.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: refine_curve SCHEME LEVELS\n");
    return 1;
  }
  const subdiv::CurveScheme* scheme = subdiv::find_curve_scheme(argv[1]);
  if (scheme == nullptr) {
    std::fprintf(stderr, "unknown curve scheme '%s'\n", argv[1]);
    return 1;
  }
  subdiv::Polyline square;
  square.points = {{1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
  square.closed = true;
  try {
    const subdiv::Polyline refined = subdiv::refine(square, *scheme, std::atoi(argv[2]));
    std::printf("%s: %zu points -> %zu points\n", argv[1], square.points.size(), refined.points.size());
    for (std::size_t i = 0; i < refined.points.size(); ++i) {
      const subdiv::Vec3 p = refined.points[i];
      std::printf("point %zu: (%.6f, %.6f, %.6f)\n", i, p.x, p.y, p.z);
    }
    // The limit mask is anchored at a control point (offsets wrap around the
    // closed polyline).
    const subdiv::CurveMask limit = subdiv::limit_at_point(*scheme);
    const auto n = static_cast<int>(square.points.size());
    for (int i = 0; i < n && !limit.empty(); ++i) {
      subdiv::Vec3 p{0, 0, 0};
      for (const subdiv::CurveMaskEntry& entry : limit) {
        const subdiv::Vec3 q = square.points[static_cast<std::size_t>(((i + entry.offset) % n + n) % n)];
        p.x += entry.weight * q.x;
        p.y += entry.weight * q.y;
        p.z += entry.weight * q.z;
      }
      std::printf("limit at corner %d: (%.6f, %.6f, %.6f)\n", i, p.x, p.y, p.z);
    }
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "refine_curve: %s\n", e.what());
    return 1;
  }
  return 0;
}
