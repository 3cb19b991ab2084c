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

/// Throws InvalidInputError, naming `command`, the estimate and the
/// available memory, when the estimate exceeds it; does nothing when
/// `unchecked` (--no-memory-check) or the available memory is unknown.
void check_fits_in_memory(const PolygonMesh& mesh, const Scheme& scheme, int levels, bool unchecked,
                          const std::string& command);

/// "512 B", "3.4 KiB", "1.2 GiB".
std::string format_bytes(double bytes);

}  // namespace subdiv::cli
