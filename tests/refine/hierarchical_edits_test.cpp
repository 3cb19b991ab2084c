// Hierarchical edits: read from OpenSubdiv's tag syntax, followed down the
// quad split's levels and applied to each level. Hbr's baselines of
// catmark_square_hedit0..2 (hbr_baseline_test.cpp) check the whole against
// OpenSubdiv; these tests check the parts: the paths against a restatement of
// Hbr's child numbering in positions, the sharpness and hole edits through
// the rules they feed, and the engine's paths (grids, hierarchy) against each
// other.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/io/obj.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/hierarchical_edits.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

RefineOptions levels(int n, bool grids = true) {
  RefineOptions options;
  options.levels = n;
  options.regular_grids = grids;
  return options;
}

RawTag value_edit(std::vector<long long> path, Vec3 offset, const std::string& op = "add") {
  std::vector<long long> ints{static_cast<long long>(path.size())};
  ints.insert(ints.end(), path.begin(), path.end());
  return {"vertexedit", ints, {offset.x, offset.y, offset.z}, {op, "P", "value"}};
}

double distance(Vec3 a, Vec3 b) {
  const Vec3 d = a - b;
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

Vec3 mid(Vec3 a, Vec3 b) { return 0.5 * (a + b); }

// Hbr's child i of a face, as corner points (hbr/catmark.h, Refine): the
// parent's vertex i, the point of the edge leaving it, the face point, the
// point of the edge entering it; a quad's child is rotated so that the
// parent's vertex stays at corner i. Under the bilinear scheme those points
// are the corners, the edges' midpoints and the centroid.
std::vector<Vec3> hbr_child(const std::vector<Vec3>& face, int i) {
  const auto n = static_cast<int>(face.size());
  Vec3 centroid;
  for (const Vec3& p : face) centroid = centroid + (1.0 / n) * p;
  const std::array<Vec3, 4> corners{face[i], mid(face[i], face[(i + 1) % n]), centroid, mid(face[(i + n - 1) % n], face[i])};
  std::vector<Vec3> child(4);
  const int rotation = n == 4 ? i : 0;
  for (int j = 0; j < 4; ++j) child[(j + rotation) % 4] = corners[j];
  return child;
}

// The vertex a path names, found by where it lies: every path of depth 1
// and 2 on a quad and on a pentagon, each edited alone by a bilinear
// refinement of its depth; exactly one vertex moves, by the offset, from
// where Hbr's numbering puts it.
TEST(HierarchicalEdits, PathsNameTheVertexHbrNames) {
  const std::vector<std::vector<Vec3>> faces{
      {{0, 0, 0}, {4, 0.5, 1}, {5, 3, -1}, {-0.5, 4, 0.5}},
      {{0, 0, 0}, {3, 0, 0.5}, {4, 2, 1}, {1.5, 4, -0.5}, {-1, 2, 0}}};
  const Vec3 offset{0.125, -0.25, 2};
  int checked = 0;
  for (const auto& corners : faces) {
    PolygonMesh mesh;
    mesh.positions = corners;
    mesh.face_offsets = {0, static_cast<Index>(corners.size())};
    for (Index v = 0; v < static_cast<Index>(corners.size()); ++v) mesh.face_indices.push_back(v);
    const auto n = static_cast<int>(corners.size());
    for (int depth = 1; depth <= 2; ++depth) {
      const PolygonMesh plain = refine(mesh, bilinear_scheme(), levels(depth));
      for (int path = 0; path < n * 4 * (depth == 2 ? 4 : 1); ++path) {
        std::vector<long long> ints{0};
        std::vector<Vec3> face = corners;
        int rest = path;
        for (int d = 0; d < depth; ++d) {
          const int bound = d == 0 ? n : 4;
          const int child = rest % bound;
          rest /= bound;
          ints.push_back(child);
          face = hbr_child(face, child);
        }
        const int corner = rest;
        ints.push_back(corner);
        PolygonMesh edited = mesh;
        edited.tags.other.push_back(value_edit(ints, offset));
        const PolygonMesh ours = refine(edited, bilinear_scheme(), levels(depth));
        ASSERT_EQ(ours.vertex_count(), plain.vertex_count());
        int moved = 0;
        for (std::size_t v = 0; v < ours.positions.size(); ++v) {
          if (distance(ours.positions[v], plain.positions[v]) == 0.0) continue;
          ++moved;
          EXPECT_LT(distance(plain.positions[v], face[static_cast<std::size_t>(corner)]), 1e-12)
              << n << "-gon, path " << path << ": the edited vertex is not where Hbr's corner " << corner << " is";
          EXPECT_LT(distance(ours.positions[v], plain.positions[v] + offset), 1e-12);
        }
        EXPECT_EQ(moved, 1) << n << "-gon, path " << path;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 4 * 4 + 4 * 4 * 4 + 5 * 4 + 5 * 4 * 4);
}

// A 3x3 grid of quads; face 4 is the middle one.
PolygonMesh grid() { return test::quad_grid(3, 3); }

// The vertex of `mesh` nearest to `p`.
Index nearest(const PolygonMesh& mesh, Vec3 p) {
  Index best = 0;
  for (Index v = 1; v < mesh.vertex_count(); ++v)
    if (distance(mesh.positions[static_cast<std::size_t>(v)], p) <
        distance(mesh.positions[static_cast<std::size_t>(best)], p))
      best = v;
  return best;
}

// Set, add and subtract; a level-0 edit moves the control vertex itself;
// values are refined on from the edited positions.
TEST(HierarchicalEdits, OperationsOnValues) {
  PolygonMesh mesh = grid();
  const Index v = mesh.face(4)[0];
  const Vec3 at = mesh.positions[static_cast<std::size_t>(v)];
  PolygonMesh moved = mesh;
  moved.positions[static_cast<std::size_t>(v)] = at + Vec3{0, 0, 1};
  for (const auto& [op, value] : std::vector<std::pair<std::string, Vec3>>{
           {"add", {0, 0, 1}}, {"subtract", {0, 0, -1}}, {"set", at + Vec3{0, 0, 1}}}) {
    PolygonMesh edited = mesh;
    edited.tags.other.push_back(value_edit({4, 0}, value, op));
    const PolygonMesh ours = refine(edited, catmull_clark_scheme(), levels(2));
    const PolygonMesh theirs = refine(moved, catmull_clark_scheme(), levels(2));
    ASSERT_EQ(ours.positions.size(), theirs.positions.size());
    for (std::size_t i = 0; i < ours.positions.size(); ++i)
      EXPECT_EQ(distance(ours.positions[i], theirs.positions[i]), 0.0) << op << ", vertex " << i;
  }
}

// A corner sharpness set on level 1 is a corner tag there, and the vertex
// stays where it is on level 2 (the corner rule); an edge sharpness is a
// crease tag, and the edge's point on level 2 is its midpoint (the crease
// rule). Add clamps at infinitely sharp; subtract from an untagged vertex
// leaves it smooth.
TEST(HierarchicalEdits, SharpnessEditsFeedTheRules) {
  PolygonMesh mesh = test::with_random_heights(grid(), 7);
  mesh.tags.other.push_back({"vertexedit", {3, 4, 1, 3}, {10}, {"set", "P", "sharpness"}});
  mesh.tags.other.push_back({"edgeedit", {3, 4, 3, 0, 3, 4, 3, 0}, {4, 8}, {"add", "P", "sharpness"}});
  mesh.tags.other.push_back({"vertexedit", {3, 4, 2, 2}, {3}, {"subtract", "P", "sharpness"}});
  const Hierarchy h = refine_hierarchy(mesh, catmull_clark_scheme(), levels(2));
  ASSERT_EQ(h.levels.size(), 3u);
  const PolygonMesh& one = h.levels[1].mesh;
  const PolygonMesh& two = h.levels[2].mesh;
  const SplitMap& map = *h.levels[1].map;
  const MeshTopology topology(mesh);
  const auto f = mesh.face(4);

  // Child 1 of the middle quad, Hbr's corner 3: its face point (hbr_child).
  const Index corner = map.face_point(4);
  ASSERT_EQ(one.tags.corners.size(), 1u) << "the subtract edit left a tag";
  EXPECT_EQ(one.tags.corners[0].vertex, corner);
  EXPECT_EQ(one.tags.corners[0].sharpness, kInfiniteSharpness);
  const Vec3 at = one.positions[static_cast<std::size_t>(corner)];
  EXPECT_LT(distance(two.positions[static_cast<std::size_t>(nearest(two, at))], at), 1e-12)
      << "the corner moved";

  // Child 3, Hbr's corners 0 and 1: the point of the parent's edge 3-0 and
  // the face point; 4 + 8 is clamped to infinitely sharp.
  ASSERT_EQ(one.tags.creases.size(), 1u);
  EXPECT_EQ(one.tags.creases[0].sharpness, kInfiniteSharpness);
  const Index edge_point = map.edge_point(topology.find_edge(f[3], f[0]));
  const Index v0 = std::min(one.tags.creases[0].v0, one.tags.creases[0].v1);
  const Index v1 = std::max(one.tags.creases[0].v0, one.tags.creases[0].v1);
  EXPECT_EQ(std::make_pair(std::min(edge_point, corner), std::max(edge_point, corner)), std::make_pair(v0, v1)) << "the crease is not the edge Hbr names";
  const Vec3 crease_point = mid(one.positions[static_cast<std::size_t>(v0)], one.positions[static_cast<std::size_t>(v1)]);
  EXPECT_LT(distance(two.positions[static_cast<std::size_t>(nearest(two, crease_point))], crease_point), 1e-12)
      << "the crease's point is not its midpoint";
}

// A hole on level 1 is that face's hole tag; its children are holes on level 2.
TEST(HierarchicalEdits, HolesAreTaggedOnTheirLevel) {
  PolygonMesh mesh = grid();
  mesh.tags.other.push_back({"faceedit", {2, 4, 2}, {}, {"hole"}});
  const Hierarchy h = refine_hierarchy(mesh, catmull_clark_scheme(), levels(2));
  EXPECT_TRUE(h.levels[0].mesh.tags.holes.empty());
  ASSERT_EQ(h.levels[1].mesh.tags.holes.size(), 1u);
  const PolygonMesh& one = h.levels[1].mesh;
  const Index hole = one.tags.holes[0];
  Vec3 centroid;
  for (const Index v : mesh.face(4)) centroid = centroid + 0.25 * mesh.positions[static_cast<std::size_t>(v)];
  const Vec3 corner2 = mesh.positions[static_cast<std::size_t>(mesh.face(4)[2])];
  // Hbr's child 2 of the middle quad holds its corner 2 and the face point.
  bool has_corner = false, has_centre = false;
  for (const Index v : one.face(hole)) {
    has_centre = has_centre || distance(one.positions[static_cast<std::size_t>(v)], centroid) < 1e-12;
    has_corner = has_corner || distance(one.positions[static_cast<std::size_t>(v)], corner2) < 1e-12;
  }
  EXPECT_TRUE(has_centre && has_corner);
  EXPECT_EQ(h.levels[2].mesh.tags.holes.size(), 4u);
}

// The engine's routes agree with edits: the grid path (which starts below
// the deepest edit) and the masks everywhere; refine() and each level of the
// hierarchy.
TEST(HierarchicalEdits, EveryRouteGivesTheSameLevels) {
  PolygonMesh mesh = test::with_random_heights(test::quad_grid(4, 4), 3);
  mesh.tags.other.push_back(value_edit({5, 2, 1}, {0.1, 0.2, 0.3}));
  mesh.tags.other.push_back(value_edit({9, 0, 3, 2}, {0, 0, -0.5}));
  mesh.tags.other.push_back({"edgeedit", {3, 10, 1, 0}, {2.5}, {"set", "P", "sharpness"}});
  const Hierarchy h = refine_hierarchy(mesh, catmull_clark_scheme(), levels(4));
  for (int k = 1; k <= 4; ++k) {
    const PolygonMesh by_grids = refine(mesh, catmull_clark_scheme(), levels(k, true));
    const PolygonMesh by_masks = refine(mesh, catmull_clark_scheme(), levels(k, false));
    const PolygonMesh& level = h.levels[static_cast<std::size_t>(k)].mesh;
    ASSERT_EQ(by_grids.positions.size(), level.positions.size());
    ASSERT_EQ(by_masks.positions.size(), level.positions.size());
    for (std::size_t i = 0; i < level.positions.size(); ++i) {
      EXPECT_LT(distance(by_grids.positions[i], level.positions[i]), 1e-14) << "level " << k << ", vertex " << i;
      EXPECT_EQ(distance(by_masks.positions[i], level.positions[i]), 0.0) << "level " << k << ", vertex " << i;
    }
  }
  // The edits did something at each depth.
  PolygonMesh plain = mesh;
  plain.tags.other.clear();
  const PolygonMesh without = refine(plain, catmull_clark_scheme(), levels(4));
  double largest = 0.0;
  for (std::size_t i = 0; i < without.positions.size(); ++i)
    largest = std::max(largest, distance(without.positions[i], h.levels[4].mesh.positions[i]));
  EXPECT_GT(largest, 0.1);
}

// Schemes off the quad split keep ignoring the edit tags.
TEST(HierarchicalEdits, OtherSplitsIgnoreThem) {
  EXPECT_TRUE(applies_hierarchical_edits(catmull_clark_scheme()));
  EXPECT_TRUE(applies_hierarchical_edits(bilinear_scheme()));
  EXPECT_FALSE(applies_hierarchical_edits(loop_scheme()));
  PolygonMesh mesh = test::tetrahedron();
  PolygonMesh edited = mesh;
  edited.tags.other.push_back(value_edit({0, 1, 2}, {0, 0, 1}));
  const PolygonMesh a = refine(mesh, loop_scheme(), levels(2));
  const PolygonMesh b = refine(edited, loop_scheme(), levels(2));
  EXPECT_EQ(a.positions, b.positions);
}

TEST(HierarchicalEdits, ReadsHbrTags) {
  const PolygonMesh mesh = grid();
  Tags tags;
  // catmark_square_hedit0's first tag: 24 floats for 4 paths of stride 3 (Hbr reads the first 12).
  tags.other.push_back({"vertexedit",
                        {3, 0, 1, 0, 3, 0, 1, 1, 3, 0, 1, 2, 3, 0, 1, 3},
                        std::vector<double>(24, 0.0),
                        {"add", "P", "value"}});
  tags.other[0].floats[2] = 1;
  tags.other.push_back({"vertexedit", {3, 4, 1, 0}, {0, 0, 1, 10}, {"add", "P", "value", "set", "P", "sharpness"}});
  tags.other.push_back({"faceedit", {3, 4, 1, 1}, {}, {"hole"}});
  tags.other.push_back({"creaseedit", {1}, {}, {}});  // not an edit: kept as is
  const HierarchicalEdits edits = read_hierarchical_edits(tags, mesh);
  ASSERT_EQ(edits.values.size(), 5u);
  EXPECT_EQ(edits.values[0].path, (EditPath{0, {1}}));
  EXPECT_EQ(edits.values[0].corner, 0);
  EXPECT_EQ(edits.values[0].value.z, 1.0);
  EXPECT_EQ(edits.values[3].corner, 3);
  EXPECT_EQ(edits.values[3].value.z, 0.0);
  EXPECT_EQ(edits.values[4].path, (EditPath{4, {1}}));
  ASSERT_EQ(edits.sharpnesses.size(), 1u);
  EXPECT_EQ(edits.sharpnesses[0].sharpness, 10.0);
  EXPECT_EQ(edits.sharpnesses[0].operation, EditOperation::set);
  EXPECT_FALSE(edits.sharpnesses[0].edge);
  ASSERT_EQ(edits.holes.size(), 1u);
  EXPECT_EQ(edits.holes[0], (EditPath{4, {1, 1}}));
  EXPECT_EQ(edits.deepest_level(), 2);
}

TEST(HierarchicalEdits, MalformedTagsAreRefusedNamingThem) {
  const PolygonMesh mesh = grid();
  const std::vector<std::pair<RawTag, std::string>> cases{
      {{"vertexedit", {1, 4}, {0, 0, 1}, {"add", "P", "value"}}, "vertexedit tag 1: path 1 has length 1"},
      {{"vertexedit", {3, 4, 1}, {0, 0, 1}, {"add", "P", "value"}}, "path 1 runs past the integer arguments"},
      {{"vertexedit", {2, 9, 0}, {0, 0, 1}, {"add", "P", "value"}}, "face 9 is not a face of the mesh (9 faces)"},
      {{"vertexedit", {3, 4, 4, 0}, {0, 0, 1}, {"add", "P", "value"}}, "child 4 of face 4's path is not in 0..3"},
      {{"vertexedit", {3, 4, 0, 5}, {0, 0, 1}, {"add", "P", "value"}}, "corner 5 on face 4's path is not in 0..3"},
      {{"vertexedit", {3, 4, 0, 1}, {0, 0}, {"add", "P", "value"}}, "has 2 float arguments, path 1 needs 3"},
      {{"vertexedit", {3, 4, 0, 1}, {0, 0, 1}, {"add", "uv", "value"}}, "only P is supported"},
      {{"vertexedit", {3, 4, 0, 1}, {0, 0, 1}, {"scale", "P", "value"}}, "unknown operation 'scale'"},
      {{"edgeedit", {3, 4, 0, 1}, {0, 0, 1}, {"add", "P", "value"}}, "cannot edit 'value'"},
      {{"vertexedit", {3, 4, 0, 1}, {0, 0, 1}, {"add", "P"}}, "operations of three strings"},
      {{"faceedit", {2, 4, 0}, {}, {"attributes"}}, "only the face edit 'hole'"},
      {{"faceedit", {3, 4, 0}, {}, {"hole"}}, "past the integer arguments"},
  };
  for (const auto& [tag, message] : cases) {
    Tags tags;
    tags.other.push_back(tag);
    try {
      (void)read_hierarchical_edits(tags, mesh);
      ADD_FAILURE() << "accepted: " << message;
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
    PolygonMesh edited = mesh;
    edited.tags = tags;
    EXPECT_THROW(refine(edited, catmull_clark_scheme(), levels(1)), InvalidInputError) << message;
  }
}

}  // namespace
}  // namespace subdiv
