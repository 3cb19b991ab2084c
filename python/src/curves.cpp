// Curve schemes on polylines from Python.

#include <pybind11/stl.h>

#include <string>

#include "bindings.h"
#include "subdiv/core/error.h"
#include "subdiv/curves/curve_scheme.h"

namespace subdiv::python {

CurveScheme curve_scheme_with(const std::string& name, std::optional<double> tension) {
  const CurveScheme* registered = find_curve_scheme(name);
  if (registered == nullptr) {
    std::string known;
    for (const CurveScheme* s : all_curve_schemes()) known += (known.empty() ? "" : ", ") + std::string(s->name);
    throw InvalidInputError("unknown curve scheme '" + name + "' (the curve schemes: " + known + ")");
  }
  if (!tension) return *registered;
  if (registered->name != "four-point") throw InvalidInputError("tension: " + name + " takes no tension");
  return four_point_scheme(*tension);
}

namespace {

// points: (n, 3) float64, checked by the package.
py::array refine_curve(const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
                       const std::string& name, int levels, bool closed, std::optional<double> tension) {
  const CurveScheme scheme = curve_scheme_with(name, tension);
  if (points.ndim() != 2 || points.shape(1) != 3) throw InvalidInputError("points must be an (n, 3) array");
  Polyline polyline;
  polyline.closed = closed;
  const auto n = static_cast<std::size_t>(points.shape(0));
  for (std::size_t i = 0; i < n; ++i) polyline.points.push_back({points.at(i, 0), points.at(i, 1), points.at(i, 2)});
  Polyline refined;
  {
    py::gil_scoped_release release;
    refined = refine(polyline, scheme, levels);
  }
  return copy_of(reinterpret_cast<const double*>(refined.points.data()), refined.points.size(), 3);
}

py::list curve_schemes() {
  py::list list;
  for (const CurveScheme* s : all_curve_schemes()) {
    py::dict d;
    d["name"] = std::string(s->name);
    d["summary"] = std::string(s->summary);
    d["citation"] = std::string(s->citation);
    d["interpolating"] = s->interpolating;
    d["dual"] = s->dual;
    d["end_rule"] = std::string(s->end_rule);
    if (s->name == "four-point") d["tension"] = s->tension;
    list.append(d);
  }
  return list;
}

}  // namespace

void bind_curves(py::module_& m) {
  m.def("refine_curve", &refine_curve);
  m.def("curve_schemes", &curve_schemes);
}

}  // namespace subdiv::python
