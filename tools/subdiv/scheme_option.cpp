#include "scheme_option.h"

#include "wording.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "subdiv/core/error.h"
#include "subdiv/rules/generalized_catmull_clark.h"

namespace subdiv::cli {

std::string surface_scheme_names() {
  std::string names;
  for (const Scheme* s : all_schemes()) names += (names.empty() ? "" : ", ") + std::string(s->name);
  return names;
}

std::string curve_scheme_names() {
  std::string names;
  for (const CurveScheme* s : all_curve_schemes()) names += (names.empty() ? "" : ", ") + std::string(s->name);
  return names;
}

namespace {

bool has_degree(const Scheme& s) { return degree_parameters(s.parameters) != nullptr && s.steps != nullptr; }

}  // namespace

std::string names_where(bool (*has)(const Scheme&)) {
  std::vector<std::string> names;
  for (const Scheme* s : all_schemes())
    if (has(*s)) names.emplace_back(s->name);
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return out;
}

void throw_unknown_scheme(const std::string& name, bool curves_too) {
  std::vector<std::string> names;
  for (const Scheme* s : all_schemes()) names.emplace_back(s->name);
  if (curves_too)
    for (const CurveScheme* s : all_curve_schemes()) names.emplace_back(s->name);
  const std::string guess = closest_name(name, names);
  throw InvalidInputError("unknown scheme '" + name + "' (known: " + surface_scheme_names() +
                          (curves_too ? "; curve schemes: " + curve_scheme_names() : std::string()) + ")" +
                          (guess.empty() ? std::string() : "; did you mean '" + guess + "'?"));
}

const Scheme& scheme_named(const std::string& name) {
  if (const Scheme* scheme = find_scheme(name)) return *scheme;
  throw_unknown_scheme(name, false);
}

Scheme with_tension(const Scheme& scheme, std::optional<double> tension) {
  Scheme chosen = scheme;
  if (!tension) return chosen;
  if (!takes_tension(scheme))
    throw InvalidInputError("--tension applies to " + names_where([](const Scheme& s) { return takes_tension(s); }) +
                            " and to curve schemes with a tension, not to " + std::string(scheme.name));
  tension_parameters(chosen.parameters)->tension = *tension;
  try {
    check_parameters(chosen);
  } catch (const ParameterError& e) {
    throw InvalidInputError(fmt::format("--tension {}: {}", *tension, e.what()));
  }
  return chosen;
}

CurveScheme with_tension(const CurveScheme& scheme, std::optional<double> tension) {
  if (!tension) return scheme;
  if (scheme.tension == 0.0)
  {
    std::string with;
    for (const CurveScheme* s : all_curve_schemes())
      if (s->tension != 0.0) with += (with.empty() ? "" : ", ") + std::string(s->name);
    throw InvalidInputError("--tension: the curve scheme " + std::string(scheme.name) + " has no tension (" + with +
                            " has)");
  }
  return four_point_scheme(*tension);
}

namespace {

double parse_number(std::string_view text, const std::string& option) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw InvalidInputError(option + ": '" + std::string(text) + "' is not a number");
  return value;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t at = text.find(separator, start);
    parts.push_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return parts;
    start = at + 1;
  }
}

std::vector<double> parse_list(const std::string& text, const std::string& option) {
  std::vector<double> values;
  for (const std::string_view part : split(text, ',')) values.push_back(parse_number(part, option + " " + text));
  return values;
}

}  // namespace

void add_degree_options(CLI::App& cmd, DegreeOptionValues& values) {
  cmd.add_option("--degree", values.degree, "gcc and midpoint: the degree n >= 2 (default 3)")
      ->check(CLI::Range(2, 64));
  cmd.add_option("--alpha", values.alpha,
                 "gcc: alpha of the smoothing operators B_1..B_r (r = (n-1)/2), one value for all or a comma list")
      ->type_name("A[,A2..]");
  cmd.add_option("--beta", values.beta, "gcc: beta of B_1..B_r, as --alpha (default: Catmull-Clark's 1-3/m, 2/m)")
      ->type_name("B[,B2..]");
  cmd.add_option("--valence-weights", values.valence_weights,
                 "gcc: alpha and beta at one valence M for every B_i (repeatable)")
      ->type_name("M:ALPHA:BETA");
}

Scheme with_degree_options(const Scheme& scheme, const DegreeOptionValues& values) {
  Scheme chosen = scheme;
  const bool weights = !values.alpha.empty() || !values.beta.empty() || !values.valence_weights.empty();
  if (!values.degree && !weights) return chosen;
  const char* option = values.degree ? "--degree" : !values.alpha.empty() ? "--alpha" : !values.beta.empty() ? "--beta" : "--valence-weights";
  if (!has_degree(scheme))
    throw InvalidInputError(std::string(option) + " applies to " + names_where(has_degree) + ", not to " +
                            std::string(scheme.name));
  try {
    if (values.degree) set_degree(chosen, *values.degree);
  } catch (const ParameterError& e) {
    throw InvalidInputError(fmt::format("--degree {}: {}", *values.degree, e.what()));
  }
  if (!weights) return chosen;
  if (values.alpha.empty() != values.beta.empty())
    throw InvalidInputError("--alpha and --beta go together (" + std::string(values.alpha.empty() ? "--beta" : "--alpha") +
                            " without the other)");
  if (!values.alpha.empty()) {
    const std::vector<double> alpha = parse_list(values.alpha, "--alpha"), beta = parse_list(values.beta, "--beta");
    if (alpha.size() != beta.size())
      throw InvalidInputError(fmt::format("--alpha gives {} values and --beta {}: give as many", alpha.size(), beta.size()));
    std::get<DegreeParameters>(chosen.parameters).smoothing.clear();
    for (std::size_t i = 0; i < alpha.size(); ++i) {
      SmoothingWeights w;
      w.alpha = alpha[i];
      w.beta = beta[i];
      std::get<DegreeParameters>(chosen.parameters).smoothing.push_back(w);
    }
  }
  for (const std::string& text : values.valence_weights) {
    const std::vector<std::string_view> parts = split(text, ':');
    const std::string what = "--valence-weights " + text;
    if (parts.size() != 3) throw InvalidInputError(what + ": expected M:ALPHA:BETA");
    const double m = parse_number(parts[0], what);
    if (m != std::floor(m) || m < 3 || m > 1e6) throw InvalidInputError(what + ": the valence must be an integer >= 3");
    for (SmoothingWeights& w : std::get<DegreeParameters>(chosen.parameters).smoothing)
      w.valences.push_back({static_cast<int>(m), parse_number(parts[1], what), parse_number(parts[2], what)});
  }
  try {
    check_parameters(chosen);  // the counts and ranges, before any work
  } catch (const ParameterError& e) {
    throw InvalidInputError(std::string(option) + ": " + e.what());
  }
  return chosen;
}

}  // namespace subdiv::cli
