#pragma once
// Refinement that cannot fit in memory is refused before it starts: the
// output is counted from the control mesh (level_costs), and its peak is
// compared with the memory the machine has available.

#include <cstdint>
#include <optional>
#include <string>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

/// Bytes of memory available to a new allocation (Linux: MemAvailable of
/// /proc/meminfo), or nothing where the system does not say.
std::optional<std::int64_t> available_memory();

/// About how many bytes refining `mesh` `levels` steps with `scheme` holds
/// at its peak: twice the last level's arrays (positions, faces, vertex and
/// face-varying channels), since the level before it and the topology are
/// alive while it is made (measured peaks: 1.8-2.0x; BENCHMARKS.md).
std::int64_t estimated_peak_bytes(const PolygonMesh& mesh, const Scheme& scheme, int levels);

/// About how many bytes adaptive refinement holds when it refines `levels`
/// uniform steps: every level stays alive with its topology and distances,
/// kAdaptivePeakFactor times the levels' mesh arrays together (measured 7.4-8.8x:
/// BENCHMARKS.md, "Memory").
inline constexpr std::int64_t kAdaptivePeakFactor = 9;
std::int64_t estimated_adaptive_peak_bytes(const PolygonMesh& mesh, const Scheme& scheme, int levels);

/// Throws InvalidInputError naming `work` ("refine to level 9"), the bytes
/// `needed` and the available memory when they do not fit; does nothing
/// when `unchecked` or the available memory is unknown.
void check_fits_in_memory(std::int64_t needed, bool unchecked, const std::string& work);

/// Throws InvalidInputError, naming `command`, the estimate and the
/// available memory, when the estimate exceeds it; does nothing when
/// `unchecked` (--no-memory-check) or the available memory is unknown.
void check_fits_in_memory(const PolygonMesh& mesh, const Scheme& scheme, int levels, bool unchecked,
                          const std::string& command);

/// "512 B", "3.4 KiB", "1.2 GiB".
std::string format_bytes(double bytes);

}  // namespace subdiv::cli
