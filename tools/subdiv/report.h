#pragma once
// Human-readable descriptions of a mesh, for `subdiv info`.

#include <string>

#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/mesh_stats.h"
#include "subdiv/mesh/validation.h"

namespace subdiv::cli {

std::string format_stats(const MeshStats& stats);
std::string format_channels(const PolygonMesh& mesh);
std::string format_tags(const Tags& tags);
/// The validation summary and up to `max_listed` itemised issues.
std::string format_validation(const ValidationReport& report, const std::string& path, std::size_t max_listed);

}  // namespace subdiv::cli
