#include "scheme_option.h"

#include "subdiv/core/error.h"

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

const Scheme& scheme_named(const std::string& name) {
  if (const Scheme* scheme = find_scheme(name)) return *scheme;
  throw InvalidInputError("unknown scheme '" + name + "' (known: " + surface_scheme_names() + ")");
}

Scheme with_tension(const Scheme& scheme, std::optional<double> tension) {
  Scheme chosen = scheme;
  if (!tension) return chosen;
  if (!scheme.takes_tension)
    throw InvalidInputError("--tension applies to butterfly and the curve scheme four-point, not to " +
                            std::string(scheme.name));
  chosen.parameters.tension = *tension;
  return chosen;
}

CurveScheme with_tension(const CurveScheme& scheme, std::optional<double> tension) {
  if (!tension) return scheme;
  if (scheme.tension == 0.0)
    throw InvalidInputError("--tension: the curve scheme " + std::string(scheme.name) +
                            " has no tension (four-point has)");
  return four_point_scheme(*tension);
}

}  // namespace subdiv::cli
