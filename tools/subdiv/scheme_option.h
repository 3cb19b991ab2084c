#pragma once
// The -s/--scheme and --tension options shared by refine, limit, analyze,
// depth and adaptive.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "subdiv/curves/curve_scheme.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

/// The registered surface schemes' names, comma-separated.
std::string surface_scheme_names();

/// The names of the registered surface schemes for which `has` holds, as
/// "a, b and c".
std::string names_where(bool (*has)(const Scheme&));

/// Throws InvalidInputError for a scheme name no registry knows: the known
/// names (the curve schemes' too where `curves_too`), and the closest one.
[[noreturn]] void throw_unknown_scheme(const std::string& name, bool curves_too);
/// The curve schemes' names, comma-separated.
std::string curve_scheme_names();

/// The registered scheme with this name; throws InvalidInputError naming
/// the known schemes otherwise.
const Scheme& scheme_named(const std::string& name);

/// `scheme` with the --tension given, if any; throws InvalidInputError when
/// the scheme takes none.
Scheme with_tension(const Scheme& scheme, std::optional<double> tension);
/// The same for a curve scheme (four-point has a tension).
CurveScheme with_tension(const CurveScheme& scheme, std::optional<double> tension);

/// The generalized Catmull-Clark options of refine and analyze.
struct DegreeOptionValues {
  std::optional<int> degree;
  std::string alpha;  ///< one value, or one per smoothing operator, comma-separated
  std::string beta;
  std::vector<std::string> valence_weights;  ///< M:ALPHA:BETA, for every operator
};

/// --degree, --alpha, --beta, --valence-weights.
void add_degree_options(CLI::App& cmd, DegreeOptionValues& values);

/// `scheme` with those options; throws InvalidInputError naming the option
/// when the scheme has no degree (only gcc and midpoint have) or a value is
/// malformed or outside the paper's range.
Scheme with_degree_options(const Scheme& scheme, const DegreeOptionValues& values);

}  // namespace subdiv::cli
