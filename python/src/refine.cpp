// Refinement from Python: a hierarchy of levels (each level's mesh shared
// with Python, and where each child vertex comes from), stencil tables as
// compressed sparse rows, and limit positions and normals.

#include <pybind11/stl.h>

#include <utility>
#include <vector>

#include "bindings.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/refine/hierarchy.h"

namespace subdiv::python {

namespace {

// One kept level: its mesh shared with Python, its parent-to-child map.
struct PyLevel {
  MeshPtr mesh;
  int level = 0;
  std::optional<SplitMap> map;
};

// Each child vertex's parent element: kind codes (ChildOrigin::Kind) and
// parent indices, or None for the coarsest kept level.
py::object origins_of(const PyLevel& level) {
  if (!level.map) return py::none();
  const auto n = static_cast<std::size_t>(level.mesh->vertex_count());
  py::array_t<std::uint8_t> kinds(n);
  py::array_t<Index> parents(n);
  auto* kind = kinds.mutable_data();
  auto* parent = parents.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    const ChildOrigin origin = origin_of(*level.map, static_cast<Index>(i));
    kind[i] = static_cast<std::uint8_t>(origin.kind);
    parent[i] = origin.parent;
  }
  return py::make_tuple(kinds, parents);
}

std::vector<PyLevel> refine_levels(const PolygonMesh& mesh, const std::string& scheme_name, int levels,
                                   const py::dict& options, const py::dict& parameters, bool keep_all) {
  const Scheme scheme = scheme_with(scheme_name, parameters);
  RefineOptions run = refine_options(options);
  run.levels = levels;
  interrupt_between_levels(run);
  std::vector<PyLevel> kept;
  if (!keep_all) {
    // The finest level alone: refine() itself, with its grid path for the
    // regular regions (which makes no per-level split maps, so no origins).
    PolygonMesh finest;
    {
      py::gil_scoped_release release;
      finest = subdiv::refine(mesh, scheme, run);
    }
    kept.push_back({std::make_shared<PolygonMesh>(std::move(finest)), levels, std::nullopt});
    return kept;
  }
  Hierarchy hierarchy;
  {
    py::gil_scoped_release release;
    hierarchy = refine_hierarchy(mesh, scheme, run, KeepLevels::all);
  }
  for (HierarchyLevel& level : hierarchy.levels)
    kept.push_back({std::make_shared<PolygonMesh>(std::move(level.mesh)), level.level, std::move(level.map)});
  return kept;
}

py::tuple stencils(const PolygonMesh& mesh, const std::string& scheme_name, int levels, const py::dict& options,
                   const py::dict& parameters) {
  const Scheme scheme = scheme_with(scheme_name, parameters);
  RefineOptions refine = refine_options(options);
  refine.levels = levels;
  StencilTable table;
  {
    py::gil_scoped_release release;
    table = refine_stencil_table(mesh, scheme, refine);
  }
  return py::make_tuple(copy_of(table.offsets().data(), table.offsets().size()),
                        copy_of(table.vertices().data(), table.vertices().size()),
                        copy_of(table.weights().data(), table.weights().size()), table.row_count(),
                        table.source_count());
}

const char* source_name(LimitSource source) {
  switch (source) {
    case LimitSource::closed_form: return "closed_form";
    case LimitSource::generic: return "generic";
    case LimitSource::refined_position: return "refined_position";
  }
  return "?";
}

py::dict limit(const PolygonMesh& mesh, const std::string& scheme_name, bool normals, bool generic,
               const py::dict& options, const py::dict& parameters) {
  const Scheme scheme = scheme_with(scheme_name, parameters);
  LimitOptions limit_options;
  limit_options.refine = refine_options(options);
  limit_options.normals = normals;
  limit_options.route = generic ? LimitRoute::generic : LimitRoute::closed_form;
  LimitResult result;
  {
    py::gil_scoped_release release;
    result = limit_positions(mesh, scheme, limit_options);
  }
  py::dict d;
  const std::size_t n = result.positions.size();
  d["positions"] = copy_of(reinterpret_cast<const double*>(result.positions.data()), n, 3);
  d["normals"] = normals ? copy_of(reinterpret_cast<const double*>(result.normals.data()), result.normals.size(), 3)
                         : py::object(py::none());
  py::list sources;
  for (LimitSource s : result.sources) sources.append(source_name(s));
  d["sources"] = sources;
  d["approximated"] = result.approximated;
  d["levels_refined"] = result.levels_refined;
  return d;
}

}  // namespace

void bind_refine(py::module_& m) {
  py::class_<PyLevel>(m, "Level")
      .def_readonly("mesh", &PyLevel::mesh)
      .def_readonly("level", &PyLevel::level)
      .def_property_readonly("origins", &origins_of);
  m.def("refine", &refine_levels);
  m.def("stencils", &stencils);
  m.def("limit", &limit);
}

}  // namespace subdiv::python
