#include "memory_guard.h"

#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "subdiv/core/error.h"
#include "subdiv/depth/depth.h"

namespace subdiv::cli {

std::optional<std::int64_t> available_memory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    std::istringstream in(line);
    std::string key;
    std::int64_t kib = 0;
    if (in >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  return std::nullopt;
}

namespace {

// The sizes of the levels up to `steps` refinement steps: level_costs counts
// a scheme that takes two steps at once in levels of two.
std::vector<LevelCost> costs_up_to(const PolygonMesh& mesh, const Scheme& scheme, int steps) {
  return level_costs(mesh, scheme, scheme.fast_path.two_steps ? (steps + 1) / 2 : steps);
}

}  // namespace

std::int64_t estimated_peak_bytes(const PolygonMesh& mesh, const Scheme& scheme, int levels) {
  const LevelCost last = costs_up_to(mesh, scheme, levels).back();
  std::int64_t bytes = last.bytes;
  for (const VertexChannel& c : mesh.vertex_channels) bytes += last.vertices * c.components * 8;
  for (const FaceVaryingChannel& c : mesh.face_varying_channels) bytes += last.corners * (4 + c.components * 8);
  return 2 * bytes;
}

std::int64_t estimated_adaptive_peak_bytes(const PolygonMesh& mesh, const Scheme& scheme, int levels) {
  std::int64_t bytes = 0;
  for (const LevelCost& level : costs_up_to(mesh, scheme, levels)) bytes += level.bytes;
  return kAdaptivePeakFactor * bytes;
}

void check_fits_in_memory(std::int64_t needed, bool unchecked, const std::string& work) {
  if (unchecked) return;
  const std::optional<std::int64_t> available = available_memory();
  if (!available || needed <= *available) return;
  throw InvalidInputError(fmt::format("{} needs about {} of memory, but {} is available; ask for less, or run it "
                                      "anyway with --no-memory-check",
                                      work, format_bytes(static_cast<double>(needed)),
                                      format_bytes(static_cast<double>(*available))));
}

void check_fits_in_memory(const PolygonMesh& mesh, const Scheme& scheme, int levels, bool unchecked,
                          const std::string& command) {
  if (unchecked || levels <= 0) return;
  check_fits_in_memory(estimated_peak_bytes(mesh, scheme, levels), false,
                       fmt::format("{} to level {}", command, levels));
}

std::string format_bytes(double bytes) {
  static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  return unit == 0 ? fmt::format("{:.0f} B", bytes) : fmt::format("{:.1f} {}", bytes, kUnits[unit]);
}

}  // namespace subdiv::cli
