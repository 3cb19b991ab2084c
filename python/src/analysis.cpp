// A scheme's analysis from Python: the JSON document of `subdiv analyze
// --json` (tools/subdiv/analysis_report.cpp, the same function), which the
// package turns into dictionaries with numpy arrays.

#include <pybind11/stl.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "analysis_report.h"
#include "bindings.h"
#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/curve_analysis.h"
#include "subdiv/core/error.h"
#include "subdiv/curves/curve_scheme.h"

namespace subdiv::python {

namespace {

std::string analyze_json(const std::string& scheme_name, const std::vector<int>& ks, const std::string& kind,
                         const std::string& corner, std::optional<double> angle_degrees, bool characteristic_map,
                         const std::string& boundary_rules, std::optional<double> flatness,
                         const py::dict& parameters) {
  const Scheme scheme = scheme_with(scheme_name, parameters);
  if (scheme.split == SplitRule::quasi_4_8)
    throw InvalidInputError("quasi-4-8 has no canonical neighbourhoods: `subdiv analyze -s quasi-4-8` runs its "
                            "n-gon experiment");
  Configuration base;
  if (kind == "boundary") {
    base.kind = Configuration::Kind::boundary;
  } else if (kind == "corner") {
    base.kind = Configuration::Kind::corner;
    if (corner != "convex" && corner != "concave")
      throw InvalidInputError("corner='" + corner + "': expected convex or concave");
    base.corner = corner == "concave" ? CornerType::concave : CornerType::convex;
  } else if (kind != "interior") {
    throw InvalidInputError("configuration='" + kind + "': expected interior, boundary or corner");
  }
  if (angle_degrees) {
    if (base.kind != Configuration::Kind::corner) throw InvalidInputError("angle applies to corner configurations");
    if ((base.corner == CornerType::convex) != (*angle_degrees < 180.0))
      throw InvalidInputError("angle: a " + corner + " corner's angle must be " +
                              (base.corner == CornerType::convex ? "below" : "above") + " 180 degrees");
    base.angle = *angle_degrees * std::numbers::pi / 180.0;
  }
  if (scheme.steps && base.kind != Configuration::Kind::interior)
    throw InvalidInputError(std::string(scheme.name) + " is analysed at interior configurations only");
  if (flatness && boundary_rules != "piecewise-smooth")
    throw InvalidInputError("flatness applies to boundary_rules='piecewise-smooth'");
  const int smallest = base.kind == Configuration::Kind::interior ? 3 : 1;
  for (int k : ks)
    if (k < smallest || k > 1000)
      throw InvalidInputError("k=" + std::to_string(k) + ": expected " + std::to_string(smallest) + "..1000 for " +
                              kind + " configurations");

  AnalysisOptions options;
  options.characteristic_map = characteristic_map;
  if (boundary_rules == "piecewise-smooth") {
    options.rules.boundary_rules = BoundaryRules::piecewise_smooth;
  } else if (boundary_rules != "standard") {
    throw InvalidInputError("boundary_rules='" + boundary_rules + "': expected standard or piecewise-smooth");
  }
  options.rules.flatness = flatness;
  std::vector<ConfigurationAnalysis> results;
  {
    py::gil_scoped_release release;
    for (int k : ks) {
      Configuration c = base;
      c.k = k;
      results.push_back(analyze(scheme, c, options));
    }
  }
  return cli::analysis_json(scheme.name, results);
}

std::string analyze_curve_json(const std::string& name, std::optional<double> tension) {
  const CurveScheme scheme = curve_scheme_with(name, tension);
  CurveAnalysis a;
  {
    py::gil_scoped_release release;
    a = analyze_curve(scheme);
  }
  return cli::curve_analysis_json(scheme.name, a);
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("analyze_json", &analyze_json);
  m.def("analyze_curve_json", &analyze_curve_json);
}

}  // namespace subdiv::python
