// The scheme registry from Python: names, descriptions and traits, and a
// scheme with the call's keyword parameters applied; the rule and run
// options shared by the refining calls; Ctrl-C between levels.

#include <pybind11/stl.h>

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bindings.h"
#include "subdiv/core/error.h"
#include "subdiv/rules/generalized_catmull_clark.h"
#include "subdiv/topology/split.h"

namespace subdiv::python {

namespace {

std::string known_schemes() {
  std::string names;
  for (const Scheme* s : all_schemes()) names += (names.empty() ? "" : ", ") + std::string(s->name);
  return names;
}

// The enum value whose to_string() is `name` (the library's spelling, as on
// the command line).
template <typename Enum>
Enum enum_named(const std::string& key, const std::string& name, std::span<const Enum> values) {
  std::string known;
  for (Enum value : values) {
    if (name == to_string(value)) return value;
    known += (known.empty() ? "" : ", ") + std::string(to_string(value));
  }
  throw InvalidInputError(key + "='" + name + "': expected one of " + known);
}

template <typename Enum>
Enum enum_named(const std::string& key, const std::string& name, std::initializer_list<Enum> values) {
  return enum_named(key, name, std::span<const Enum>(values.begin(), values.size()));
}

std::vector<double> numbers(const py::handle value) {
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) return {value.cast<double>()};
  return value.cast<std::vector<double>>();
}

py::dict describe(const Scheme& s) {
  py::dict d;
  d["name"] = std::string(s.name);
  d["summary"] = std::string(s.summary);
  d["citation"] = std::string(s.citation);
  d["split"] = to_string(s.split);
  d["primal"] = is_primal(s.split);
  d["interpolating"] = s.traits.interpolating;
  d["needs_triangles"] = s.traits.needs_triangles;
  d["needs_quads"] = s.traits.needs_quads;
  d["needs_closed_mesh"] = s.traits.needs_closed_mesh;
  d["composite"] = s.steps != nullptr;
  d["limit_masks"] = s.limit_masks != nullptr;
  py::list parameters;
  if (takes_tension(s)) parameters.append("tension");
  if (degree_parameters(s.parameters) != nullptr) {
    for (const char* name : {"degree", "alpha", "beta", "valence_weights"}) parameters.append(name);
  }
  d["parameters"] = parameters;
  if (const TensionParameters* t = tension_parameters(s.parameters)) d["tension"] = t->tension;
  if (const DegreeParameters* p = degree_parameters(s.parameters)) d["degree"] = p->degree;
  return d;
}

}  // namespace

Scheme scheme_with(const std::string& name, const py::dict& parameters) {
  const Scheme* registered = find_scheme(name);
  if (registered == nullptr)
    throw InvalidInputError("unknown scheme '" + name + "' (the schemes: " + known_schemes() + ")");
  Scheme scheme = *registered;
  std::optional<std::vector<double>> alpha, beta;
  for (const auto& [key_handle, value] : parameters) {
    if (value.is_none()) continue;
    const std::string key = key_handle.cast<std::string>();
    if (key == "tension") {
      TensionParameters* t = tension_parameters(scheme.parameters);
      if (t == nullptr) throw InvalidInputError("tension: " + name + " takes no tension");
      t->tension = value.cast<double>();
    } else if (key == "degree" || key == "alpha" || key == "beta" || key == "valence_weights") {
      if (degree_parameters(scheme.parameters) == nullptr)
        throw InvalidInputError(key + ": only gcc and midpoint take a degree and smoothing weights, not " + name);
      if (key == "degree") set_degree(scheme, value.cast<int>());
      if (key == "alpha") alpha = numbers(value);
      if (key == "beta") beta = numbers(value);
    } else {
      throw InvalidInputError("unknown scheme parameter '" + key + "' (tension; degree, alpha, beta, valence_weights)");
    }
  }
  if (DegreeParameters* p = degree_parameters(scheme.parameters)) {
    if (alpha.has_value() != beta.has_value()) throw InvalidInputError("alpha and beta go together");
    if (alpha) {
      if (alpha->size() != beta->size()) throw InvalidInputError("alpha and beta need as many values");
      p->smoothing.clear();
      for (std::size_t i = 0; i < alpha->size(); ++i) {
        SmoothingWeights w;
        w.alpha = (*alpha)[i];
        w.beta = (*beta)[i];
        p->smoothing.push_back(w);
      }
    }
    if (parameters.contains("valence_weights") && !parameters["valence_weights"].is_none()) {
      for (const auto& [m, weights] : parameters["valence_weights"].cast<py::dict>()) {
        const auto [a, b] = weights.cast<std::pair<double, double>>();
        for (SmoothingWeights& w : p->smoothing) w.valences.push_back({m.cast<int>(), a, b});
      }
    }
  }
  check_parameters(scheme);
  return scheme;
}

RefineOptions refine_options(const py::dict& options) {
  RefineOptions o;
  for (const auto& [key_handle, value] : options) {
    if (value.is_none()) continue;
    const std::string key = key_handle.cast<std::string>();
    if (key == "boundary") {
      o.boundary = enum_named(key, value.cast<std::string>(),
                              {BoundaryInterpolation::edge_only, BoundaryInterpolation::edge_and_corner});
    } else if (key == "boundary_rules") {
      o.boundary_rules = enum_named(key, value.cast<std::string>(),
                                    {BoundaryRules::standard, BoundaryRules::piecewise_smooth});
    } else if (key == "corner_angles") {
      o.corner_angles = enum_named(key, value.cast<std::string>(), {CornerAngles::fixed, CornerAngles::measured});
    } else if (key == "crease_method") {
      o.crease_method = enum_named(key, value.cast<std::string>(), {CreaseMethod::uniform, CreaseMethod::chaikin});
    } else if (key == "triangle_subdivision") {
      o.triangle_subdivision = enum_named(key, value.cast<std::string>(),
                                          {TriangleSubdivision::catmark, TriangleSubdivision::smooth});
    } else if (key == "face_varying") {
      o.face_varying = enum_named(key, value.cast<std::string>(),
                                  std::span<const FaceVaryingInterpolation>(kFaceVaryingInterpolations));
    } else if (key == "flatness") {
      o.flatness = value.cast<double>();
    } else if (key == "allow_non_manifold") {
      o.allow_non_manifold = value.cast<bool>();
    } else if (key == "threads") {
      o.threads = value.cast<int>();
      if (o.threads < 0) throw InvalidInputError("threads must be >= 0 (0: all cores)");
    } else if (key == "regular_grids") {
      o.regular_grids = value.cast<bool>();
    } else {
      throw InvalidInputError("unknown option '" + key +
                              "' (boundary, boundary_rules, corner_angles, crease_method, triangle_subdivision, face_varying, flatness, "
                              "allow_non_manifold, threads, regular_grids)");
    }
  }
  return o;
}

void interrupt_between_levels(RefineOptions& options) {
  options.on_level = [](int, const PolygonMesh&) {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
}

void bind_schemes(py::module_& m) {
  m.def("schemes", [] {
    py::list list;
    for (const Scheme* s : all_schemes()) list.append(describe(*s));
    return list;
  });
  m.def("scheme", [](const std::string& name, const py::dict& parameters) {
    return describe(scheme_with(name, parameters));
  });
}

}  // namespace subdiv::python
