#include "support/opensubdiv_shapes.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>

#include "subdiv/core/error.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/hierarchical_edits.h"
#include "support/test_meshes.h"

namespace subdiv::test {

std::filesystem::path opensubdiv_shape_dir() { return std::filesystem::path(shared_mesh_dir()) / "opensubdiv"; }

std::string unsupported_feature(const PolygonMesh& mesh) {
  for (const RawTag& t : mesh.tags.other)
    if (is_hierarchical_edit(t))
      return "hierarchical edits (t " + t.name + "), which OpenSubdiv's Far does not have (Hbr's baselines check them)";
  return {};
}

std::string rejection(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options) {
  try {
    check_refinable(mesh, scheme, options);
    return {};
  } catch (const Error& e) {
    return std::string("refine() rejects it: ") + e.what();
  }
}

namespace {

bool repeats_vertices(const PolygonMesh& mesh) {
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 0; i < face.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (face[i] == face[j]) return true;
  }
  return false;
}

bool doubles_triangles(const PolygonMesh& mesh) {
  std::set<std::array<Index, 3>> seen;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    if (face.size() != 3) continue;
    std::array<Index, 3> key{face[0], face[1], face[2]};
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) return true;
  }
  return false;
}

}  // namespace

bool levels_keep_coincident_edges(const PolygonMesh& mesh, SplitRule split) {
  return repeats_vertices(mesh) || (split == SplitRule::triangle && doubles_triangles(mesh));
}

namespace {

// None at present (a shape whose levels keep edges apart that join the same
// two vertices is compared by opensubdiv_coincident_edges_test.cpp).
constexpr std::array<KnownDifference, 0> kKnownDifferences{};

}  // namespace

const KnownDifference* known_difference(const std::string& shape) {
  for (const KnownDifference& k : kKnownDifferences)
    if (k.shape == shape) return &k;
  return nullptr;
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
