// Interior vertices of valence 2 (two faces sharing both of the vertex's
// edges), which refinement keeps at every level:
// - the analysis reads Catmull-Clark's matrix at interior k = 2 on a ring
//   mesh without a linear layout, naming images by grid points; those
//   names are the linear layout's children wherever that layout exists;
// - its limit mask is the closed form k^2 : 4 : 1 over k (k + 5), derived
//   for every k, at k = 2, and its spectrum has no subdominant pair;
// - limit positions (Catmull-Clark through the analysis, Loop's closed form
//   at two triangles) against refinement, which closes on them at the rate
//   of the one-ring's eigenvalues;
// - depth bounds that hold when the meshes are refined and measured, and
//   adaptive refinement within its accuracy;
// - a configuration with no analysis (two triangles) is refused by depth
//   naming the vertex and its line.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/depth.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

std::string shared(const std::string& name) { return test::shared_mesh_dir() + "/" + name; }

// The shared meshes with interior vertices of valence 2 (refine accepts
// them with Catmull-Clark).
const char* const kValenceTwoMeshes[] = {"opensubdiv/catmark_val2_interior.obj", "common3d/suzanne.obj"};

// Interior vertices with two faces and no sharp edge.
std::vector<Index> smooth_valence_two(const PolygonMesh& mesh) {
  const MeshTopology t(mesh);
  std::vector<char> sharp(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (const CreaseTag& c : mesh.tags.creases) sharp[static_cast<std::size_t>(c.v0)] = sharp[static_cast<std::size_t>(c.v1)] = 1;
  std::vector<Index> out;
  for (Index v = 0; v < t.vertex_count(); ++v)
    if (t.vertex_kind(v) == VertexKind::interior && t.vertex_face_count(v) == 2 && !sharp[static_cast<std::size_t>(v)])
      out.push_back(v);
  return out;
}

// The vertex points of `vertices` after each of `levels` steps (the primal
// splits number vertex points last), level 0 first.
std::vector<std::vector<Vec3>> followed(const PolygonMesh& mesh, const Scheme& scheme, const std::vector<Index>& vertices,
                                        int levels, RefineOptions options = {}) {
  std::vector<std::vector<Vec3>> out(vertices.size());
  std::vector<Index> where = vertices;
  PolygonMesh level = mesh;
  options.levels = 1;
  for (int l = 0; l <= levels; ++l) {
    for (std::size_t i = 0; i < where.size(); ++i) out[i].push_back(level.positions[static_cast<std::size_t>(where[i])]);
    if (l == levels) break;
    PolygonMesh child = refine(level, scheme, options);
    for (Index& w : where) w += child.vertex_count() - level.vertex_count();
    level = std::move(child);
  }
  return out;
}

TEST(ValenceTwo, RingMeshIsTheTwoFaceFan) {
  const RingMesh ring = valence_two_ring_mesh(SplitRule::quad, 3);
  const MeshTopology t(ring.mesh);
  EXPECT_FALSE(ring.linear);
  EXPECT_EQ(ring.mesh.face_count(), 2 * 3 * 3);
  EXPECT_EQ(t.vertex_kind(ring.centre), VertexKind::interior);
  EXPECT_EQ(t.vertex_face_count(ring.centre), 2);
  EXPECT_EQ(t.valence(ring.centre), 2);
  // One to one, and a half turn maps the layout onto itself.
  for (Index a = 0; a < ring.mesh.vertex_count(); ++a) {
    const Vec3 p = ring.mesh.positions[static_cast<std::size_t>(a)];
    int same = 0, turned = 0;
    for (const Vec3& q : ring.mesh.positions) {
      same += norm(q - p) < 1e-9 ? 1 : 0;
      turned += norm(q + p) < 1e-9 ? 1 : 0;
    }
    EXPECT_EQ(same, 1);
    EXPECT_EQ(turned, 1);
  }
  EXPECT_THROW(ring_mesh(SplitRule::quad, {Configuration::Kind::interior, 2}, 2), InvalidInputError);
  EXPECT_THROW(valence_two_ring_mesh(SplitRule::triangle, 2), InvalidInputError);
  EXPECT_THROW(valence_two_ring_mesh(SplitRule::sqrt2, 2), InvalidInputError);
}

// The grid-point names of the images are the linear layout's children (at
// half their layout points) wherever the linear layout exists.
TEST(ValenceTwo, ImageParentsAreTheLinearLayoutsChildren) {
  std::vector<Configuration> configurations;
  for (int k = 3; k <= 6; ++k) configurations.push_back({Configuration::Kind::interior, k});
  for (int k = 1; k <= 4; ++k) configurations.push_back({Configuration::Kind::boundary, k});
  for (int k = 1; k <= 3; ++k) {
    configurations.push_back({Configuration::Kind::corner, k, CornerType::convex});
    configurations.push_back({Configuration::Kind::corner, k, CornerType::concave});
  }
  for (const SplitRule split : {SplitRule::quad, SplitRule::triangle})
    for (const Configuration& c : configurations) {
      SCOPED_TRACE(std::string(to_string(split)) + " " + c.name());
      const RingMesh ring = ring_mesh(split, c, 3);
      const MeshTopology t(ring.mesh);
      const std::vector<Vec3> children = child_layout(split, ring, 1);
      ASSERT_EQ(ring.image_parent.size(), ring.mesh.positions.size());
      const Index faces = split == SplitRule::quad ? t.face_count() : 0;
      for (std::size_t v = 0; v < ring.image_parent.size(); ++v) {
        const ImageParent& p = ring.image_parent[v];
        Index child = kInvalidIndex;
        if (p.kind == ImageParent::Kind::vertex) child = faces + t.edge_count() + p.a;
        if (p.kind == ImageParent::Kind::edge) child = faces + t.find_edge(p.a, p.b);
        if (p.kind == ImageParent::Kind::face) child = p.a;
        ASSERT_TRUE(p.kind != ImageParent::Kind::edge || t.find_edge(p.a, p.b) != kInvalidIndex) << "vertex " << v;
        EXPECT_LT(norm(children[static_cast<std::size_t>(child)] - 0.5 * ring.mesh.positions[v]), 1e-12)
            << "vertex " << v;
      }
    }
}

// The closed form k^2 : 4 : 1 over k (k + 5) is derived from the
// frequency-0 block of the one-ring matrix, which has the same form at
// k = 2 (each edge neighbour is in both faces): the analysis must find it.
// The spectrum: 1, then 1/4 twice (p_1 - p_2 on the edge and on the face
// neighbours) and -1/4 of one magnitude, so no tangent pair.
TEST(ValenceTwo, CatmullClarkMasksAreTheClosedForm) {
  AnalysisOptions options;
  options.characteristic_map = false;
  const ConfigurationAnalysis a = analyze(catmull_clark_scheme(), {Configuration::Kind::interior, 2}, options);
  ASSERT_TRUE(a.matrix.invariant);
  EXPECT_EQ(a.matrix.rings, 1);
  ASSERT_EQ(a.matrix.S.rows(), 5);
  ASSERT_TRUE(a.limit_mask.has_value());
  const double k = 2.0, denominator = k * (k + 5.0);
  for (std::size_t i = 0; i < a.matrix.layout.size(); ++i) {
    const Vec3 p = a.matrix.layout[i];
    // The centre, the edge neighbours (on the rays, angles 0 and pi), and
    // the faces' opposite vertices.
    const bool edge = norm(p) > 0.0 && std::fabs(p.y) < 1e-12;
    const double expected = norm(p) == 0.0 ? k * k / denominator : edge ? 4.0 / denominator : 1.0 / denominator;
    EXPECT_NEAR((*a.limit_mask)[static_cast<Eigen::Index>(i)], expected, 1e-12) << "neighbourhood vertex " << i;
  }
  ASSERT_GE(a.leading.size(), 4u);
  const double expected[] = {1.0, 0.25, 0.25, -0.25};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(a.leading[static_cast<std::size_t>(i)].real(), expected[i], 1e-12);
    EXPECT_NEAR(a.leading[static_cast<std::size_t>(i)].imag(), 0.0, 1e-12);
  }
  EXPECT_FALSE(a.eigenvalue_condition);
  EXPECT_FALSE(a.tangent_masks.has_value());
}

// Limit positions at the valence-2 vertices against refinement: the vertex
// points close on them by the one-ring's 1/4, 1/4, -1/4 per step, so over
// two steps by 1/16, and reach them (a wrong mask would leave a distance
// that does not shrink).
TEST(ValenceTwo, CatmullClarkLimitIsWhereRefinementGoes) {
  for (const char* name : kValenceTwoMeshes) {
    if (!std::filesystem::exists(shared(name))) GTEST_SKIP() << "shared mesh collection absent: " << shared(name);
    SCOPED_TRACE(name);
    const PolygonMesh mesh = read_mesh(shared(name)).mesh;
    const std::vector<Index> vertices = smooth_valence_two(mesh);
    ASSERT_FALSE(vertices.empty());
    for (const LimitRoute route : {LimitRoute::closed_form, LimitRoute::generic}) {
      LimitOptions options;
      options.route = route;
      const LimitResult limit = limit_positions(mesh, catmull_clark_scheme(), options);
      const auto path = followed(mesh, catmull_clark_scheme(), vertices, 6);
      for (std::size_t i = 0; i < vertices.size(); ++i) {
        const auto v = static_cast<std::size_t>(vertices[i]);
        SCOPED_TRACE("vertex " + std::to_string(v));
        EXPECT_EQ(limit.sources[v], LimitSource::generic);
        EXPECT_EQ(norm(limit.normals[v]), 0.0);  // no tangent pair
        std::vector<double> d;
        for (const Vec3& p : path[i]) d.push_back(norm(p - limit.positions[v]));
        ASSERT_GT(d[0], 0.0);
        // Within 10%: the faster eigenvalues' parts are still dying off.
        for (std::size_t l = 2; l + 2 < d.size(); ++l) EXPECT_LE(d[l + 2], 1.1 * d[l] / 16.0 + 1e-14) << "level " << l;
        EXPECT_LE(d[6], d[0] / 1000.0);
      }
    }
  }
}

// Loop's closed form at two triangles (a closed pillow; or, in a mesh, at a
// non-manifold edge), 8/21 and 13/42 twice, against refinement (1/8 per
// step after 1: the one-ring's 1/8 on p_1 - p_2 and 1/64).
TEST(ValenceTwo, LoopLimitOfTwoTrianglesIsWhereRefinementGoes) {
  PolygonMesh pillow;
  pillow.positions = {{0.0, 0.0, 0.0}, {1.0, 0.2, 0.1}, {0.3, 1.0, -0.4}};
  pillow.add_face({0, 1, 2});
  pillow.add_face({0, 2, 1});
  // Refined, the pillow's two centre triangles share their three edge points,
  // so each level has a non-manifold edge opposite each valence-2 vertex.
  LimitOptions options;
  options.refine.allow_non_manifold = true;
  const LimitResult limit = limit_positions(pillow, loop_scheme(), options);
  ASSERT_EQ(limit.approximated, 0);
  const Vec3 expected = (8.0 / 21.0) * pillow.positions[0] + (13.0 / 42.0) * (pillow.positions[1] + pillow.positions[2]);
  EXPECT_LT(norm(limit.positions[0] - expected), 1e-15);
  EXPECT_EQ(norm(limit.normals[0]), 0.0);
  const auto path = followed(pillow, loop_scheme(), {0, 1, 2}, 8, options.refine);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t l = 1; l + 1 < path[i].size(); ++l)
      EXPECT_LE(norm(path[i][l + 1] - limit.positions[i]), norm(path[i][l] - limit.positions[i]) / 8.0 * (1.0 + 1e-6) + 1e-15);
    EXPECT_LT(norm(path[i].back() - limit.positions[i]), 1e-7);
  }

  const std::string name = shared("opensubdiv/loop_val2_interior.obj");
  if (!std::filesystem::exists(name)) GTEST_SKIP() << "shared mesh collection absent: " << name;
  const PolygonMesh mesh = read_mesh(name).mesh;
  const LimitResult at = limit_positions(mesh, loop_scheme(), options);
  const std::vector<Index> vertices = smooth_valence_two(mesh);
  ASSERT_FALSE(vertices.empty());
  const auto refined = followed(mesh, loop_scheme(), vertices, 8, options.refine);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto v = static_cast<std::size_t>(vertices[i]);
    EXPECT_EQ(at.sources[v], LimitSource::closed_form) << "vertex " << v;
    EXPECT_LT(norm(refined[i].back() - at.positions[v]), 1e-6 * norm(refined[i].front() - at.positions[v]))
        << "vertex " << v;
  }
}

// The depth bound, whose extraordinary term now includes interior k = 2
// (rate 1/4), holds at every level when the mesh is refined and measured;
// adaptive refinement keeps every vertex within its accuracy.
TEST(ValenceTwo, DepthBoundHoldsAndAdaptiveRefinementIsWithinItsAccuracy) {
  for (const char* name : kValenceTwoMeshes) {
    if (!std::filesystem::exists(shared(name))) GTEST_SKIP() << "shared mesh collection absent: " << shared(name);
    SCOPED_TRACE(name);
    const PolygonMesh mesh = read_mesh(shared(name)).mesh;
    const DepthBound bound = depth_bound(mesh, catmull_clark_scheme());
    for (int level = bound.start; level <= 4; ++level) {
      const DepthCheck check = check_depth(mesh, catmull_clark_scheme(), bound, level);
      EXPECT_EQ(check.approximated, 0) << "level " << level;
      EXPECT_LE(check.measured, check.bound) << "level " << level;
    }
    const AdaptiveResult adaptive = adaptive_refine(mesh, catmull_clark_scheme(), 0.01);
    for (const double d : adaptive.distances) EXPECT_LE(d, 0.01);
  }
}

// Two triangles around an interior vertex have no configuration: depth
// refuses, naming the vertex and its line.
TEST(ValenceTwo, DepthNamesAVertexOfTwoTriangles) {
  const std::string name = shared("opensubdiv/loop_val2_interior.obj");
  if (!std::filesystem::exists(name)) GTEST_SKIP() << "shared mesh collection absent: " << name;
  const MeshFile file = read_mesh(name);
  DepthOptions options;
  options.refine.allow_non_manifold = true;
  const Index v = smooth_valence_two(file.mesh).front();
  const std::string where = name + ":" + std::to_string(SourceLines::at(file.lines.vertex_lines, v)) + ": vertex " +
                            std::to_string(v) + ": no depth bound";
  try {
    depth_bound(file.mesh, loop_scheme(), options, &file.lines);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace subdiv
