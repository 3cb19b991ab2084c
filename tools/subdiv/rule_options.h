#pragma once
// The options that choose the rules at boundaries, creases and corners,
// shared by refine and limit: --boundary-rules, --corner-angles, --flatness
// and --corner (corner tags given on the command line).

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

struct RuleOptionValues {
  std::string boundary_rules = "standard";
  std::string corner_angles = "fixed";
  std::optional<double> flatness;
  std::vector<std::string> corners;  ///< V[:convex|concave[:DEGREES]]
};

void add_rule_options(CLI::App& cmd, RuleOptionValues& values);

/// Sets the rules in `options` and adds the --corner tags to `mesh` (a tag
/// given there replaces the file's tag on the same vertex). Throws
/// InvalidInputError naming the option for a vertex outside the mesh or a
/// malformed value.
void apply_rule_options(const RuleOptionValues& values, PolygonMesh& mesh, RefineOptions& options);

}  // namespace subdiv::cli
