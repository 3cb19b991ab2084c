#include <array>
#include <cmath>
#include <string>

#include "subdiv/core/error.h"
#include "subdiv/curves/curve_scheme.h"

#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/composite.h"
#include "subdiv/rules/doo_sabin.h"
#include "subdiv/rules/four_eight.h"
#include "subdiv/rules/generalized_catmull_clark.h"
#include "subdiv/rules/interpolating_sqrt2.h"
#include "subdiv/rules/interpolatory_sqrt3.h"
#include "subdiv/rules/kobbelt.h"
#include "subdiv/rules/linear.h"
#include "subdiv/rules/loop.h"
#include "subdiv/rules/midedge.h"
#include "subdiv/rules/quasi_4_8.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/rules/sqrt3.h"

namespace subdiv {

const char* to_string(VertexRule r) noexcept {
  switch (r) {
    case VertexRule::smooth: return "smooth";
    case VertexRule::dart: return "dart";
    case VertexRule::crease: return "crease";
    case VertexRule::corner: return "corner";
  }
  return "?";
}

std::span<const Scheme* const> all_schemes() {
  static const std::array<const Scheme*, 20> schemes = {
      &catmull_clark_scheme(), &loop_scheme(),     &loop_warren_scheme(), &butterfly_scheme(),
      &modified_butterfly_scheme(), &doo_sabin_scheme(), &midedge_scheme(), &sqrt3_scheme(),
      &interpolatory_sqrt3_scheme(), &kobbelt_scheme(), &four_eight_scheme(), &generalized_catmull_clark_scheme(),
      &midpoint_scheme(), &bilinear_scheme(), &linear_scheme(), &quasi_4_8_scheme(), &composite_loop_scheme(),
      &composite_sqrt3_scheme(), &composite_sqrt3_kobbelt_scheme(), &interpolating_sqrt2_scheme()};
  return schemes;
}

void check_parameters(const Scheme& scheme) {
  const TensionParameters* tension = tension_parameters(scheme.parameters);
  if (tension && !std::isfinite(tension->tension))
    throw ParameterError(std::string(scheme.name) + ": the tension w = " + std::to_string(tension->tension) +
                         " is not finite");
  if (scheme.parameter_check) scheme.parameter_check(scheme.name, scheme.parameters);
}

std::array<double, 3> boundary_vertex_limit(const Scheme& scheme) {
  if (!scheme.masks.boundary_curve)
    throw InvalidInputError(std::string(scheme.name) + ": its boundary rules follow no curve scheme, so the limit on "
                            "its boundary is not known here");
  std::array<double, 3> weights{};
  for (const CurveMaskEntry& e : limit_at_point(*scheme.masks.boundary_curve)) {
    if (e.offset < -1 || e.offset > 1)
      throw InvalidInputError(std::string(scheme.name) + ": its boundary curve's limit reaches beyond the neighbours");
    weights[static_cast<std::size_t>(e.offset + 1)] += e.weight;
  }
  return weights;
}

const Scheme& default_scheme() { return catmull_clark_scheme(); }

const Scheme* find_scheme(std::string_view name) {
  if (is_composite_spec(name)) return &composite_scheme(name);
  for (const Scheme* s : all_schemes())
    if (s->name == name) return s;
  return nullptr;
}

}  // namespace subdiv
