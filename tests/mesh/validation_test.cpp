#include "subdiv/mesh/validation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

ValidationReport validate_file(const std::string& name, MeshFile* out = nullptr) {
  MeshFile file = read_mesh(test::data_path(name));
  ValidationReport report = validate(file.mesh, &file.lines);
  if (out) *out = std::move(file);
  return report;
}

const ValidationIssue& only_issue(const ValidationReport& r, IssueKind kind) {
  for (const auto& issue : r.issues)
    if (issue.kind == kind) return issue;
  static const ValidationIssue none{kind, Severity::error, -1, 0, "<none>"};
  ADD_FAILURE() << "no issue of kind " << to_string(kind);
  return none;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(Validation, CleanMeshesPass) {
  EXPECT_TRUE(validate(test::cube()).ok());
  EXPECT_TRUE(validate(test::quad_grid(3, 3)).ok());
  EXPECT_TRUE(validate(test::tetrahedron()).ok());
  EXPECT_EQ(validate(test::cube()).issues.size(), 0u);
}

TEST(Validation, NonManifoldEdge) {
  const auto r = validate_file("nonmanifold_edge.obj");
  EXPECT_EQ(r.count(IssueKind::non_manifold_edge), 1u);
  const auto& issue = only_issue(r, IssueKind::non_manifold_edge);
  EXPECT_TRUE(contains(issue.message, "edge 0-1 is shared by 3 faces (0, 1, 2)")) << issue.message;
  EXPECT_EQ(issue.line, 9u);  // the third face's line
  EXPECT_FALSE(r.ok());
}

TEST(Validation, NonManifoldVertex) {
  const auto r = validate_file("nonmanifold_vertex.obj");
  EXPECT_EQ(r.count(IssueKind::non_manifold_vertex), 1u);
  const auto& issue = only_issue(r, IssueKind::non_manifold_vertex);
  EXPECT_EQ(issue.element, 0);
  EXPECT_EQ(issue.line, 2u);
  EXPECT_TRUE(contains(issue.message, "vertex 0 is non-manifold: its faces form 2 separate fans")) << issue.message;
}

TEST(Validation, RepeatedVertex) {
  const auto r = validate_file("repeated_vertex.obj");
  EXPECT_EQ(r.count(IssueKind::repeated_vertex), 1u);
  const auto& issue = only_issue(r, IssueKind::repeated_vertex);
  EXPECT_EQ(issue.element, 1);
  EXPECT_EQ(issue.line, 6u);
  EXPECT_EQ(format_issue(issue, "m.obj"), "m.obj:6: face 1 uses a vertex more than once");
}

TEST(Validation, FaceTooSmall) {
  const auto r = validate_file("face_too_small.obj");
  EXPECT_EQ(r.count(IssueKind::face_too_small), 1u);
  EXPECT_EQ(only_issue(r, IssueKind::face_too_small).message, "face 1 has 2 vertices; a face needs at least 3");
  EXPECT_EQ(only_issue(r, IssueKind::face_too_small).line, 5u);
}

TEST(Validation, NonFiniteCoordinates) {
  const auto r = validate_file("nan_coordinate.obj");
  EXPECT_EQ(r.count(IssueKind::non_finite_coordinate), 2u);
  EXPECT_EQ(r.issues[0].message, "vertex 1 has a NaN or infinite coordinate");
  EXPECT_EQ(r.issues[0].line, 2u);
  EXPECT_EQ(r.issues[1].line, 3u);
}

TEST(Validation, InconsistentOrientation) {
  const auto r = validate_file("flipped_face.obj");
  EXPECT_EQ(r.count(IssueKind::inconsistent_orientation), 1u);
  const auto& issue = only_issue(r, IssueKind::inconsistent_orientation);
  EXPECT_TRUE(contains(issue.message, "faces 0 and 1 traverse their shared edge 1-4 in the same direction"))
      << issue.message;
  EXPECT_EQ(issue.line, 9u);
}

TEST(Validation, IsolatedVertexIsOnlyAWarning) {
  const auto r = validate_file("isolated_vertex.obj");
  EXPECT_EQ(r.count(IssueKind::isolated_vertex), 1u);
  EXPECT_EQ(r.warning_count(), 1u);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(only_issue(r, IssueKind::isolated_vertex).severity, Severity::warning);
  EXPECT_EQ(only_issue(r, IssueKind::isolated_vertex).line, 4u);
}

TEST(Validation, CreaseOnAMissingEdge) {
  const auto r = validate_file("bad_crease_tag.obj");
  EXPECT_EQ(r.count(IssueKind::invalid_tag), 1u);
  const auto& issue = only_issue(r, IssueKind::invalid_tag);
  EXPECT_EQ(issue.line, 6u);
  EXPECT_TRUE(contains(issue.message, "crease tag 0 (edge 0-2) names an edge the mesh does not have")) << issue.message;
}

TEST(Validation, BadTagValues) {
  PolygonMesh mesh = test::cube();
  mesh.tags.creases.push_back({0, 1, -1.0});
  mesh.tags.corners.push_back({12, 10.0, CornerType::unspecified, std::nullopt});
  mesh.tags.corners.push_back({0, 10.0, CornerType::concave, 7.0});
  mesh.tags.holes.push_back(6);
  const auto r = validate(mesh);
  EXPECT_EQ(r.count(IssueKind::invalid_tag), 4u);
  ASSERT_EQ(r.issues.size(), 4u);
  EXPECT_TRUE(contains(r.issues[0].message, "sharpness -1")) << r.issues[0].message;
  EXPECT_TRUE(contains(r.issues[1].message, "vertex outside [0, 8)")) << r.issues[1].message;
  EXPECT_TRUE(contains(r.issues[2].message, "outside (0, 2 pi)")) << r.issues[2].message;
  EXPECT_TRUE(contains(r.issues[3].message, "hole tag 0 refers to face 6")) << r.issues[3].message;
}

TEST(Validation, ChannelsThatDoNotFitTheMesh) {
  PolygonMesh mesh = test::cube();
  mesh.vertex_channels.push_back({"color", 3, std::vector<double>(21, 0.0)});
  mesh.face_varying_channels.push_back({"uv", 2, {0, 0, 1, 1}, std::vector<Index>(24, 0)});
  mesh.face_varying_channels.back().indices[5] = 2;
  mesh.face_varying_channels.push_back({"st", 2, {0, 0}, std::vector<Index>(23, 0)});
  const auto r = validate(mesh);
  EXPECT_EQ(r.count(IssueKind::invalid_channel), 3u);
  ASSERT_EQ(r.issues.size(), 3u);
  EXPECT_EQ(r.issues[0].message, "vertex channel 'color' has 21 values for 8 vertices of 3 components");
  EXPECT_EQ(r.issues[1].message, "face-varying channel 'uv' corner 5 refers to value 2, outside [0, 2)");
  EXPECT_EQ(r.issues[2].message, "face-varying channel 'st' has 23 indices for 24 face corners");
}

TEST(Validation, OutOfRangeIndicesAreReportedNotThrown) {
  PolygonMesh mesh = test::cube();
  mesh.face_indices[3] = 100;
  ValidationReport r;
  ASSERT_NO_THROW(r = validate(mesh));
  EXPECT_EQ(r.count(IssueKind::index_out_of_range), 1u);
  EXPECT_TRUE(contains(r.issues[0].message, "face 0 refers to vertex 100, but the mesh has 8 vertices"));
  mesh.face_offsets = {0, 5, 3};
  ASSERT_NO_THROW(r = validate(mesh));
  EXPECT_FALSE(r.ok());
}

TEST(Validation, CapsItemisedIssuesButCountsAll) {
  PolygonMesh mesh;
  for (int i = 0; i < 50; ++i) mesh.positions.push_back({double(i), 0, 0});
  mesh.add_face({0, 1, 2});
  ValidationOptions options;
  options.max_issues_per_kind = 5;
  const auto r = validate(mesh, nullptr, options);
  EXPECT_EQ(r.count(IssueKind::isolated_vertex), 47u);
  EXPECT_EQ(r.issues.size(), 5u);
}

TEST(Validation, RequireValidThrowsWithTheFirstError) {
  MeshFile file;
  const auto r = validate_file("nonmanifold_edge.obj", &file);
  try {
    require_valid(r, "x.obj");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_TRUE(contains(e.what(), "x.obj:9: edge 0-1 is shared by 3 faces")) << e.what();
    EXPECT_EQ(e.report().count(IssueKind::non_manifold_edge), 1u);
  }
  EXPECT_NO_THROW(require_valid(validate(test::cube())));
}

TEST(Validation, RequireValidNamesAnErrorThatWasNotListed) {
  MeshFile file;
  ValidationOptions options;
  options.max_issues_per_kind = 0;
  file = read_mesh(test::data_path("nonmanifold_edge.obj"));
  const auto r = validate(file.mesh, &file.lines, options);
  ASSERT_TRUE(r.issues.empty());
  try {
    require_valid(r, "x.obj");
    FAIL();
  } catch (const ValidationError& e) {
    EXPECT_STREQ(e.what(), "x.obj: 1 x non-manifold edge (not listed)");
  }
}

TEST(Validation, TopologyOverloadAgrees) {
  const auto mesh = test::quad_grid(2, 2);
  const MeshTopology t(mesh);
  EXPECT_EQ(validate(mesh, t).counts, validate(mesh).counts);
}

}  // namespace
}  // namespace subdiv
