#pragma once
// Shared pieces of the compiled extension subdiv._subdiv. The package
// python/subdiv wraps it: argument checking, numpy and scipy conversions and
// the documented API live there; this layer converts and calls the library,
// with the GIL released while the library works.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "subdiv/curves/curve_scheme.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::python {

namespace py = pybind11;

/// Meshes are shared between Python objects (a Mesh and the arrays viewing
/// it, a Hierarchy and its levels' meshes).
using MeshPtr = std::shared_ptr<PolygonMesh>;

void bind_errors(py::module_& m);
void bind_mesh(py::module_& m);
void bind_schemes(py::module_& m);
void bind_refine(py::module_& m);
void bind_analysis(py::module_& m);
void bind_depth(py::module_& m);
void bind_curves(py::module_& m);

/// A numpy array of rows x columns values at data (columns = 0: one
/// dimension) that shares the memory and keeps owner alive; read-only unless
/// writable.
template <typename T>
py::array view(const T* data, std::size_t rows, std::size_t columns, py::handle owner, bool writable) {
  py::array array = columns == 0
                        ? py::array(py::dtype::of<T>(), {rows}, {sizeof(T)}, data, owner)
                        : py::array(py::dtype::of<T>(), {rows, columns}, {columns * sizeof(T), sizeof(T)}, data, owner);
  if (!writable) py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

/// A numpy array that owns a copy of the values.
template <typename T>
py::array copy_of(const T* data, std::size_t rows, std::size_t columns = 0) {
  const auto r = static_cast<py::ssize_t>(rows), c = static_cast<py::ssize_t>(columns);
  py::array_t<T> array = columns == 0 ? py::array_t<T>(std::vector<py::ssize_t>{r})
                                      : py::array_t<T>(std::vector<py::ssize_t>{r, c});
  if (rows > 0) std::copy(data, data + rows * std::max<std::size_t>(columns, 1), array.mutable_data());
  return array;
}

/// The registered surface scheme named `name`, with the keyword parameters
/// of the Python call applied (tension; degree, alpha, beta for gcc and
/// midpoint). Throws InvalidInputError for an unknown scheme or parameter,
/// ParameterError for a value outside the scheme's range.
Scheme scheme_with(const std::string& name, const py::dict& parameters);

/// The registered curve scheme `name`, with four-point's tension where
/// given. Throws InvalidInputError for an unknown name, or a tension for a
/// scheme without one.
CurveScheme curve_scheme_with(const std::string& name, std::optional<double> tension);

/// The rule and run options shared by refine, stencils, limit, depth and
/// adaptive, from the Python call's keywords (boundary, boundary_rules,
/// corner_angles, crease_method, flatness, allow_non_manifold, threads,
/// regular_grids). Throws InvalidInputError for an unknown key or value.
RefineOptions refine_options(const py::dict& options);

/// Installs RefineOptions::on_level so that Ctrl-C (any pending Python
/// signal) stops a refinement between levels: the Python exception is raised
/// once the library has unwound.
void interrupt_between_levels(RefineOptions& options);

}  // namespace subdiv::python
