#pragma once
// What the OpenSubdiv-comparison tests share about OpenSubdiv's regression
// shapes (../shared/data/meshes/opensubdiv): their scheme, the features
// Far cannot compare, and the regression harness's boundary mode.

#include <filesystem>
#include <string>
#include <string_view>

#include "subdiv/refine/refine.h"
#include "subdiv/topology/split.h"

namespace subdiv::test {

std::filesystem::path opensubdiv_shape_dir();

/// Why OpenSubdiv's Far (libosd-dev), which has no hierarchical edits,
/// cannot be compared with this shape, or "": its edit tags. Hbr's
/// baselines check those (hbr_baseline_test.cpp).
std::string unsupported_feature(const PolygonMesh& mesh);

/// Why refine() rejects the shape, or "" when it refines it.
std::string rejection(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options);

/// Whether the levels of `mesh` under `split` keep edges apart that join the
/// same two vertices: a face uses a vertex more than once (one level down,
/// the halves of an edge joining a vertex to itself), or, for the triangle
/// split, two triangles lie on the same three vertices (one level down, the
/// two edges inside them). A level's faces alone cannot say that, so the
/// level-by-level comparisons skip such shapes and
/// opensubdiv_coincident_edges_test.cpp compares them, each level refined
/// from the control mesh.
bool levels_keep_coincident_edges(const PolygonMesh& mesh, SplitRule split);

/// What OpenSubdiv's regression harness does with `t interpolateboundary`:
/// absent or 0 means VTX_BOUNDARY_NONE, whose vertex positions are those of
/// edge-only.
BoundaryInterpolation harness_boundary(const Tags& tags);

/// A genuine disagreement with OpenSubdiv: from `level` on, the shape's
/// refinements differ (the levels before it agree).
struct KnownDifference {
  std::string_view shape;
  int level;
  std::string_view why;
};

/// The shape's known difference, or null. The comparison tests fail if it
/// disappears, so that the list stays true.
const KnownDifference* known_difference(const std::string& shape);

/// A shape name as a GoogleTest parameter name (letters, digits and '_').
std::string shape_test_name(const std::string& shape);

}  // namespace subdiv::test
