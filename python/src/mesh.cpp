// subdiv._subdiv.Mesh over PolygonMesh: arrays in, numpy views out (no
// copies of positions, faces or channels), files in and out, validation,
// and pickling through the OBJ text (lossless for what OBJ holds).

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/io/obj.h"
#include "subdiv/mesh/validation.h"

namespace subdiv::python {

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<Index, py::array::c_style | py::array::forcecast>;

std::size_t rows_of(const py::array& a) { return a.ndim() == 0 ? 0 : static_cast<std::size_t>(a.shape(0)); }

// The arrays come checked for shape and dtype from python/subdiv/_mesh.py;
// what follows re-checks what memory safety depends on.
std::shared_ptr<PolygonMesh> from_arrays(const Doubles& points, const Indices& offsets, const Indices& indices,
                                         const Indices& crease_vertices, const Doubles& crease_sharpness,
                                         const Indices& corner_vertices, const Doubles& corner_sharpness,
                                         const Indices& holes, const py::dict& vertex_channels,
                                         const py::dict& face_varying_channels) {
  auto mesh = std::make_shared<PolygonMesh>();
  if (points.ndim() != 2 || points.shape(1) != 3) throw InvalidInputError("points must be an (n, 3) array");
  const std::size_t n = rows_of(points);
  mesh->positions.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p{points.at(i, 0), points.at(i, 1), points.at(i, 2)};
    if (!is_finite(p)) throw InvalidInputError("point " + std::to_string(i) + " has a non-finite coordinate");
    mesh->positions[i] = p;
  }
  mesh->face_offsets.assign(offsets.data(), offsets.data() + offsets.size());
  mesh->face_indices.assign(indices.data(), indices.data() + indices.size());
  check_face_arrays(*mesh);

  const std::size_t creases = rows_of(crease_vertices);
  if (crease_vertices.ndim() != 2 || crease_vertices.shape(1) != 2 || rows_of(crease_sharpness) != creases)
    throw InvalidInputError("creases must be an (c, 2) array of vertex pairs with c sharpness values");
  for (std::size_t i = 0; i < creases; ++i)
    mesh->tags.creases.push_back({crease_vertices.at(i, 0), crease_vertices.at(i, 1), crease_sharpness.at(i)});
  const std::size_t corners = rows_of(corner_vertices);
  if (rows_of(corner_sharpness) != corners) throw InvalidInputError("corners need one sharpness per vertex");
  for (std::size_t i = 0; i < corners; ++i) {
    CornerTag tag;
    tag.vertex = corner_vertices.at(i);
    tag.sharpness = corner_sharpness.at(i);
    mesh->tags.corners.push_back(tag);
  }
  mesh->tags.holes.assign(holes.data(), holes.data() + holes.size());
  // Tags naming elements the mesh does not have are refused here, as
  // out-of-range face indices are (a file's such tags are validation issues).
  const auto vertices = static_cast<Index>(n);
  for (std::size_t i = 0; i < mesh->tags.creases.size(); ++i) {
    const CreaseTag& tag = mesh->tags.creases[i];
    if (tag.v0 >= vertices || tag.v1 >= vertices)
      throw InvalidInputError("crease " + std::to_string(i) + " refers to vertex " +
                              std::to_string(std::max(tag.v0, tag.v1)) + ", but the mesh has " +
                              std::to_string(n) + " vertices");
  }
  for (std::size_t i = 0; i < mesh->tags.corners.size(); ++i)
    if (mesh->tags.corners[i].vertex >= vertices)
      throw InvalidInputError("corner " + std::to_string(i) + " refers to vertex " +
                              std::to_string(mesh->tags.corners[i].vertex) + ", but the mesh has " +
                              std::to_string(n) + " vertices");
  for (const Index face : mesh->tags.holes)
    if (face >= mesh->face_count())
      throw InvalidInputError("hole refers to face " + std::to_string(face) + ", but the mesh has " +
                              std::to_string(mesh->face_count()) + " faces");

  for (const auto& [key, value] : vertex_channels) {
    const auto values = value.cast<Doubles>();
    if (values.ndim() != 2 || rows_of(values) != n)
      throw InvalidInputError("vertex channel '" + key.cast<std::string>() + "' must have one row per point");
    mesh->vertex_channels.push_back({key.cast<std::string>(), static_cast<int>(values.shape(1)),
                                     std::vector<double>(values.data(), values.data() + values.size())});
  }
  for (const auto& [key, value] : face_varying_channels) {
    const auto pair = value.cast<std::pair<Doubles, Indices>>();
    const Doubles& values = pair.first;
    if (values.ndim() != 2) throw InvalidInputError("face-varying channel '" + key.cast<std::string>() +
                                                    "' needs an (m, c) array of values");
    FaceVaryingChannel channel{key.cast<std::string>(), static_cast<int>(values.shape(1)),
                               std::vector<double>(values.data(), values.data() + values.size()),
                               std::vector<Index>(pair.second.data(), pair.second.data() + pair.second.size())};
    mesh->face_varying_channels.push_back(std::move(channel));
  }
  check_indices(*mesh);
  return mesh;
}

py::array points_view(py::object self) {
  PolygonMesh& mesh = self.cast<PolygonMesh&>();
  return view(reinterpret_cast<const double*>(mesh.positions.data()), mesh.positions.size(), 3, self, true);
}

py::tuple creases_of(const PolygonMesh& mesh) {
  std::vector<Index> vertices;
  std::vector<double> sharpness;
  for (const CreaseTag& tag : mesh.tags.creases) {
    vertices.insert(vertices.end(), {tag.v0, tag.v1});
    sharpness.push_back(tag.sharpness);
  }
  return py::make_tuple(copy_of(vertices.data(), sharpness.size(), 2), copy_of(sharpness.data(), sharpness.size()));
}

py::tuple corners_of(const PolygonMesh& mesh) {
  std::vector<Index> vertices;
  std::vector<double> sharpness;
  for (const CornerTag& tag : mesh.tags.corners) {
    vertices.push_back(tag.vertex);
    sharpness.push_back(tag.sharpness);
  }
  return py::make_tuple(copy_of(vertices.data(), vertices.size()), copy_of(sharpness.data(), sharpness.size()));
}

py::dict vertex_channels_of(py::object self) {
  const PolygonMesh& mesh = self.cast<const PolygonMesh&>();
  py::dict channels;
  for (const VertexChannel& c : mesh.vertex_channels)
    channels[py::str(c.name)] = view(c.values.data(), static_cast<std::size_t>(c.value_count()),
                                     static_cast<std::size_t>(c.components), self, true);
  return channels;
}

py::dict face_varying_channels_of(py::object self) {
  const PolygonMesh& mesh = self.cast<const PolygonMesh&>();
  py::dict channels;
  for (const FaceVaryingChannel& c : mesh.face_varying_channels)
    channels[py::str(c.name)] = py::make_tuple(
        view(c.values.data(), static_cast<std::size_t>(c.value_count()), static_cast<std::size_t>(c.components),
             self, true),
        view(c.indices.data(), c.indices.size(), 0, self, false));
  return channels;
}

py::list polylines_of(const PolygonMesh& mesh) {
  py::list lines;
  for (const MeshPolyline& line : mesh.polylines)
    lines.append(py::make_tuple(copy_of(line.vertices.data(), line.vertices.size()), line.closed));
  return lines;
}

// Pickling: the OBJ text holds positions (shortest round-trip decimals),
// faces, tags, polylines, "color", "uv" and "normal"; a mesh with other
// channels refuses rather than lose them.
py::bytes obj_state(const PolygonMesh& mesh) {
  std::vector<std::string> warnings;
  std::string text;
  {
    py::gil_scoped_release release;
    WriteOptions options;
    options.threads = 1;
    text = format_obj(mesh, options, &warnings);
  }
  if (!warnings.empty()) throw InvalidInputError("cannot pickle this mesh: " + warnings.front());
  return py::bytes(text);
}

std::shared_ptr<PolygonMesh> from_obj_state(const py::bytes& state) {
  const std::string text = state;
  py::gil_scoped_release release;
  return std::make_shared<PolygonMesh>(parse_obj(text, "<pickle>").mesh);
}

py::list issues_of(const ValidationReport& report) {
  py::list issues;
  for (const ValidationIssue& issue : report.issues)
    issues.append(py::make_tuple(to_string(issue.kind), issue.severity == Severity::error ? "error" : "warning",
                                 issue.element, format_issue(issue, {})));
  return issues;
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<PolygonMesh, MeshPtr>(m, "Mesh")
      .def_static("_from_arrays", &from_arrays)
      .def_static("_from_obj_state", &from_obj_state)
      .def("_obj_state", &obj_state)
      .def("_copy", [](const PolygonMesh& mesh) { return std::make_shared<PolygonMesh>(mesh); })
      .def_property_readonly("points", &points_view)
      .def_property_readonly("face_offsets",
                             [](py::object self) {
                               const PolygonMesh& mesh = self.cast<const PolygonMesh&>();
                               return view(mesh.face_offsets.data(), mesh.face_offsets.size(), 0, self, false);
                             })
      .def_property_readonly("face_indices",
                             [](py::object self) {
                               const PolygonMesh& mesh = self.cast<const PolygonMesh&>();
                               return view(mesh.face_indices.data(), mesh.face_indices.size(), 0, self, false);
                             })
      .def_property_readonly("vertex_count", &PolygonMesh::vertex_count)
      .def_property_readonly("face_count", &PolygonMesh::face_count)
      .def_property_readonly("corner_count", &PolygonMesh::corner_count)
      .def_property_readonly("creases", &creases_of)
      .def_property_readonly("corners", &corners_of)
      .def_property_readonly("holes",
                             [](const PolygonMesh& mesh) {
                               return copy_of(mesh.tags.holes.data(), mesh.tags.holes.size());
                             })
      .def_property_readonly("boundary_interpolation",
                             [](const PolygonMesh& mesh) { return to_string(mesh.tags.boundary_interpolation); })
      .def_property_readonly("vertex_channels", &vertex_channels_of)
      .def_property_readonly("face_varying_channels", &face_varying_channels_of)
      .def_property_readonly("polylines", &polylines_of);

  m.def("read", [](const std::string& path, double weld_tolerance) {
    MeshFile file;
    {
      py::gil_scoped_release release;
      ReadOptions options;
      options.weld_tolerance = weld_tolerance;
      file = read_mesh(path, options);
    }
    return py::make_tuple(std::make_shared<PolygonMesh>(std::move(file.mesh)), file.warnings);
  });
  m.def("write", [](const PolygonMesh& mesh, const std::string& path, bool ascii, bool write_tags,
                    bool write_channels, bool hole_faces_as_faces, int threads) {
    WriteOptions options;
    options.ply_encoding = ascii ? PlyEncoding::ascii : PlyEncoding::binary_little_endian;
    options.stl_encoding = ascii ? StlEncoding::ascii : StlEncoding::binary;
    options.write_tags = write_tags;
    options.write_channels = write_channels;
    options.hole_faces_as_faces = hole_faces_as_faces;
    options.threads = threads;
    py::gil_scoped_release release;
    return write_mesh(mesh, path, options);
  });
  m.def("validate", [](const PolygonMesh& mesh) {
    ValidationReport report;
    {
      py::gil_scoped_release release;
      report = validate(mesh);
    }
    return issues_of(report);
  });
}

}  // namespace subdiv::python
