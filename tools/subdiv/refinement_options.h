#pragma once
// The options of every command that refines a surface (refine, limit, depth,
// adaptive): the scheme and its parameters, the rules at boundaries, creases
// and corners, how the input is taken, and the worker threads. One
// definition, so that each command reads them the same way.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "rule_options.h"
#include "scheme_option.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

struct RefinementOptionValues {
  std::string scheme = std::string(default_scheme().name);
  std::optional<double> tension;
  DegreeOptionValues degree;
  std::string quasi_boundary;  ///< quasi-4-8: fixed or smoothed
  std::string boundary;        ///< edge-only, edge-and-corner, or empty: the file's tag
  std::string crease_method;   ///< empty: the file's tag
  std::string triangle_rule;   ///< catmark or smooth; empty: the file's tag
  std::string face_varying;    ///< a FaceVaryingInterpolation name; empty: the file's tag
  RuleOptionValues rules;
  std::vector<std::string> creases;  ///< --crease A,B: infinitely sharp edge tags
  bool allow_non_manifold = false;
  bool triangulate = false;
  int threads = 0;
};

/// Registers -s/--scheme and the options above on `cmd`. `scheme_help`
/// describes -s for this command.
void add_refinement_options(CLI::App& cmd, RefinementOptionValues& values, const std::string& scheme_help);

/// The registered surface scheme named by -s with --tension, --degree,
/// --alpha, --beta, --valence-weights and --quasi-boundary applied; throws
/// InvalidInputError naming the option a scheme does not take.
Scheme chosen_scheme(const RefinementOptionValues& values);

/// Triangulates the input when asked (and the scheme reads triangles), adds
/// the --corner and --crease tags to it, and sets the rules, non-manifold
/// handling and threads in `options`. Throws InvalidInputError naming the
/// option for a vertex outside the mesh or a malformed value.
void apply_refinement_options(const RefinementOptionValues& values, const Scheme& scheme, MeshFile& file,
                              RefineOptions& options);

/// The first of these options given that only surface schemes read, for a
/// curve scheme to refuse; nullptr when none is.
const char* surface_option_given(const RefinementOptionValues& values);

}  // namespace subdiv::cli
