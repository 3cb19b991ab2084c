// Depth for an accuracy and adaptive refinement from Python.

#include <pybind11/stl.h>

#include <string>

#include "bindings.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/depth.h"

namespace subdiv::python {

namespace {

py::dict depth(const PolygonMesh& mesh, const std::string& scheme_name, double eps, bool verify,
               const py::dict& options, const py::dict& parameters) {
  const Scheme scheme = scheme_with(scheme_name, parameters);
  DepthOptions depth_options;
  depth_options.refine = refine_options(options);
  DepthBound bound;
  int levels = 0;
  DepthCheck check;
  {
    py::gil_scoped_release release;
    bound = depth_bound(mesh, scheme, depth_options);
    levels = bound.depth_for(eps);
    if (verify) check = check_depth(mesh, scheme, bound, levels, depth_options);
  }
  py::dict d;
  d["depth"] = levels;
  d["bound"] = bound.at(levels);
  d["source"] = bound.source;
  d["start"] = bound.start;
  d["steps_per_level"] = bound.steps_per_level;
  d["measure"] = to_string(bound.measure);
  py::list terms;
  for (const DepthTerm& term : bound.terms) {
    py::dict t;
    t["what"] = term.what;
    t["amplitude"] = term.amplitude;
    t["rate"] = term.rate;
    terms.append(t);
  }
  d["terms"] = terms;
  if (verify) {
    py::dict v;
    v["measured"] = check.measured;
    v["measured_previous"] = check.has_previous ? py::object(py::float_(check.measured_previous)) : py::none();
    v["approximated"] = check.approximated;
    d["verified"] = v;
  }
  return d;
}

py::dict adaptive(const PolygonMesh& mesh, const std::string& scheme_name, double eps, int max_level,
                  const py::dict& options, const py::dict& parameters) {
  const Scheme scheme = scheme_with(scheme_name, parameters);
  AdaptiveOptions adaptive_options;
  adaptive_options.depth.refine = refine_options(options);
  adaptive_options.max_level = max_level;
  AdaptiveResult result;
  {
    py::gil_scoped_release release;
    result = adaptive_refine(mesh, scheme, eps, adaptive_options);
  }
  const std::size_t n = result.sources.size();
  py::array_t<int> levels(n);
  py::array_t<Index> indices(n);
  for (std::size_t i = 0; i < n; ++i) {
    levels.mutable_data()[i] = result.sources[i].level;
    indices.mutable_data()[i] = result.sources[i].index;
  }
  py::dict d;
  d["mesh"] = std::make_shared<PolygonMesh>(std::move(result.mesh));
  d["source_levels"] = levels;
  d["source_indices"] = indices;
  d["distances"] = copy_of(result.distances.data(), result.distances.size());
  d["uniform_depth"] = result.uniform_depth;
  d["uniform_faces"] = result.uniform_faces;
  d["transition_faces"] = result.transition_faces;
  d["approximated"] = result.approximated;
  d["steps_per_level"] = result.steps_per_level;
  d["measure"] = std::string(to_string(result.measure));
  d["largest_displacement"] = result.largest_displacement;
  d["displacement_threshold"] = result.displacement_threshold;
  return d;
}

}  // namespace

void bind_depth(py::module_& m) {
  m.def("depth", &depth);
  m.def("adaptive", &adaptive);
}

}  // namespace subdiv::python
