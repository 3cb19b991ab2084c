#include "support/opensubdiv_shapes.h"

#include <cctype>

#include "subdiv/core/error.h"
#include "subdiv/mesh/validation.h"
#include "support/test_meshes.h"

namespace subdiv::test {

std::filesystem::path opensubdiv_shape_dir() { return std::filesystem::path(shared_mesh_dir()) / "opensubdiv"; }

std::string unsupported_feature(const PolygonMesh& mesh) {
  for (const RawTag& t : mesh.tags.other)
    if (t.name == "vertexedit" || t.name == "edgeedit" || t.name == "faceedit")
      return "hierarchical edits (t " + t.name + ")";
  return {};
}

std::string rejection(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options) {
  try {
    check_refinable(mesh, scheme, options);
    return {};
  } catch (const ValidationError& e) {
    const ValidationReport& report = e.report();
    if (report.error_count() == report.count(IssueKind::face_too_small) + report.count(IssueKind::repeated_vertex))
      return std::string("degenerate faces, which subdiv does not refine: ") + e.what();
    return std::string("refine() rejects it: ") + e.what();
  } catch (const Error& e) {
    return std::string("refine() rejects it: ") + e.what();
  }
}

BoundaryInterpolation harness_boundary(const Tags& tags) {
  if (!tags.boundary_interpolation_set || tags.boundary_interpolation == BoundaryInterpolation::none)
    return BoundaryInterpolation::edge_only;
  return tags.boundary_interpolation;
}

std::string shape_test_name(const std::string& shape) {
  std::string name = shape;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

}  // namespace subdiv::test
