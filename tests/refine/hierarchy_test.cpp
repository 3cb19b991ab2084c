// The refinement hierarchy (refine/hierarchy.h): refining one level at a
// time equals refining all levels at once, for every scheme, on open and
// closed meshes with tags, with one and two threads; the levels carry the
// split's state; each child's origin names the parent element it comes from.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/rules/scheme.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

RefineOptions levels(int n, int threads = 0) {
  RefineOptions o;
  o.levels = n;
  o.threads = threads;
  return o;
}

bool takes_triangles(const Scheme& s) {
  return s.traits.needs_triangles || s.split == SplitRule::triangle || s.split == SplitRule::sqrt3 ||
         s.split == SplitRule::quasi_4_8;
}

// An open grid with a semi-sharp crease across it and a corner tag, the
// grid without them, and a closed mesh; triangulated for the schemes of triangle meshes.
std::vector<std::pair<std::string, PolygonMesh>> meshes_for(const Scheme& scheme) {
  PolygonMesh open = takes_triangles(scheme) ? test::triangle_grid(3, 3) : test::quad_grid(3, 3);
  open = test::jittered(std::move(open), 7);
  PolygonMesh untagged = open;  // for the schemes without crease rules
  open.tags.creases.push_back({5, 6, 1.5});
  open.tags.creases.push_back({6, 7, 1.5});
  CornerTag corner;
  corner.vertex = 10;
  corner.sharpness = 2.0;
  open.tags.corners.push_back(corner);
  PolygonMesh closed = test::jittered(test::cube(), 3);
  if (takes_triangles(scheme)) closed = triangulate(closed);
  return {{"open grid with tags", std::move(open)},
          {"open grid", std::move(untagged)},
          {"closed cube", std::move(closed)}};
}

void expect_same_mesh(const PolygonMesh& a, const PolygonMesh& b, const std::string& what) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count()) << what;
  for (Index v = 0; v < a.vertex_count(); ++v) {
    const Vec3 p = a.positions[static_cast<std::size_t>(v)], q = b.positions[static_cast<std::size_t>(v)];
    ASSERT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z) << what << ": vertex " << v;  // bit for bit
  }
  EXPECT_EQ(a.face_offsets, b.face_offsets) << what;
  EXPECT_EQ(a.face_indices, b.face_indices) << what;
  EXPECT_EQ(a.tags.creases, b.tags.creases) << what;
  EXPECT_EQ(a.tags.corners, b.tags.corners) << what;
}

// Tags kept verbatim (hierarchical edits, applied as the levels are made
// where the scheme takes them) name the input's elements by index; every
// level below the input drops them, whatever the split.
TEST(Hierarchy, UninterpretedTagsStayOnTheInputLevel) {
  int checked = 0;
  for (const Scheme* scheme : all_schemes()) {
    PolygonMesh mesh = meshes_for(*scheme).back().second;  // the closed cube
    mesh.tags.other.push_back({"vertexedit", {3, 1, 3, 1}, {0, 0, 0.5}, {"add", "P", "value"}});
    mesh.tags.other.push_back({"faceedit", {2, 0, 1, 1, 0}, {}, {"hole"}});
    try {
      check_refinable(mesh, *scheme, levels(1));
    } catch (const InvalidInputError&) {
      continue;
    }
    const Hierarchy h = refine_hierarchy(mesh, *scheme, levels(2));
    EXPECT_EQ(h.levels[0].mesh.tags.other.size(), 2u) << scheme->name;
    for (std::size_t l = 1; l < h.levels.size(); ++l)
      EXPECT_TRUE(h.levels[l].mesh.tags.other.empty()) << scheme->name << ", level " << l;
    ++checked;
  }
  EXPECT_GE(checked, 15);
}

TEST(Hierarchy, OneLevelAtATimeEqualsAllAtOnce) {
  int checked = 0;
  for (const Scheme* scheme : all_schemes()) {
    for (auto& [name, mesh] : meshes_for(*scheme)) {
      const std::string what = std::string(scheme->name) + ", " + name;
      try {
        check_refinable(mesh, *scheme, levels(1));
      } catch (const InvalidInputError&) {
        continue;  // the scheme refuses this input (boundaries, tags): refine() would too
      }
      for (const int threads : {1, 2}) {
        const Hierarchy at_once = refine_hierarchy(mesh, *scheme, levels(2, threads));
        ASSERT_EQ(at_once.levels.size(), 3u) << what;
        Hierarchy stepwise = refine_hierarchy(mesh, *scheme, levels(1, threads));
        refine_further(stepwise, *scheme, 1, levels(0, threads));
        ASSERT_EQ(stepwise.levels.size(), 3u) << what;
        for (std::size_t l = 0; l < 3; ++l) {
          EXPECT_EQ(stepwise.levels[l].level, static_cast<int>(l)) << what;
          expect_same_mesh(stepwise.levels[l].mesh, at_once.levels[l].mesh, what + ", level " + std::to_string(l));
        }
        // Keeping the last level only: the same finest mesh, and refine()'s
        // for schemes that take single steps.
        Hierarchy last = refine_hierarchy(mesh, *scheme, levels(1, threads), KeepLevels::last);
        refine_further(last, *scheme, 1, levels(0, threads), KeepLevels::last);
        ASSERT_EQ(last.levels.size(), 1u);
        EXPECT_EQ(last.finest().level, 2) << what;
        if (!scheme->fast_path.two_steps) {
          expect_same_mesh(last.finest().mesh, at_once.finest().mesh, what + ", last only");
          expect_same_mesh(refine(mesh, *scheme, levels(2, threads)), at_once.finest().mesh, what + ", refine()");
        }
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 35);
}

// The wrong answer the hierarchy removes: sqrt3's boundary steps alternate,
// so a level-1 mesh refined again as if it were a control mesh differs from
// two levels at once; told its level, it agrees.
TEST(Hierarchy, Sqrt3ContinuesItsParity) {
  const Scheme& sqrt3 = *find_scheme("sqrt3");
  const PolygonMesh grid = test::triangle_grid(3, 3);
  const PolygonMesh two = refine(grid, sqrt3, levels(2));
  const PolygonMesh one = refine(grid, sqrt3, levels(1));
  const PolygonMesh restarted = refine(one, sqrt3, levels(1));
  EXPECT_NE(restarted.vertex_count(), two.vertex_count());
  RefineOptions continued = levels(1);
  continued.start_level = 1;
  expect_same_mesh(refine(one, sqrt3, continued), two, "start_level 1");
  EXPECT_THROW(refine(one, sqrt3, [] {
                 RefineOptions o;
                 o.start_level = -1;
                 return o;
               }()),
               InvalidInputError);
}

// Each child's origin, checked by geometry: the bilinear and linear rules put
// a face point at its face's centroid, an edge point at its edge's midpoint
// and a vertex point on its vertex, with the parent level's own topology.
TEST(Hierarchy, ChildOriginsNameTheirParentElements) {
  for (const char* name : {"bilinear", "linear"}) {
    const Scheme& scheme = *find_scheme(name);
    const PolygonMesh mesh = std::string(name) == "linear" ? triangulate(test::jittered(test::cube(), 5))
                                                           : test::jittered(test::cube(), 5);
    const Hierarchy h = refine_hierarchy(mesh, scheme, levels(2));
    for (std::size_t l = 1; l < h.levels.size(); ++l) {
      const PolygonMesh& parent = h.levels[l - 1].mesh;
      const MeshTopology topology(parent);
      ASSERT_TRUE(h.levels[l].map) << name;
      const PolygonMesh& child = h.levels[l].mesh;
      int kinds[3] = {0, 0, 0};
      for (Index c = 0; c < child.vertex_count(); ++c) {
        const ChildOrigin o = origin_of(*h.levels[l].map, c);
        Vec3 expected;
        if (o.kind == ChildOrigin::Kind::vertex) {
          expected = parent.positions[static_cast<std::size_t>(o.parent)];
          ++kinds[0];
        } else if (o.kind == ChildOrigin::Kind::edge) {
          const auto ends = topology.edge_vertices(o.parent);
          expected = 0.5 * (parent.positions[static_cast<std::size_t>(ends[0])] +
                            parent.positions[static_cast<std::size_t>(ends[1])]);
          ++kinds[1];
        } else {
          ASSERT_EQ(o.kind, ChildOrigin::Kind::face) << name;
          const auto face = topology.face_vertices(o.parent);
          for (const Index v : face) expected += parent.positions[static_cast<std::size_t>(v)];
          expected = (1.0 / static_cast<double>(face.size())) * expected;
          ++kinds[2];
        }
        EXPECT_LT(norm(child.positions[static_cast<std::size_t>(c)] - expected), 1e-12) << name << " child " << c;
      }
      EXPECT_EQ(kinds[0], parent.vertex_count()) << name;
      EXPECT_EQ(kinds[1], topology.edge_count()) << name;
      EXPECT_EQ(kinds[2], std::string(name) == "linear" ? 0 : parent.face_count()) << name;
    }
    EXPECT_THROW(origin_of(*h.levels[1].map, h.levels[1].mesh.vertex_count()), InvalidInputError);
  }
}

// Quasi 4-8 runs in the engine like every scheme: its levels carry the
// bisection's map, whose split points lie between the ends of the parent
// edge they split (both ends are their neighbours in the child), and whose
// other children are the parent's vertices, numbered as they were.
TEST(Hierarchy, QuasiFourEightLevelsCarryTheBisection) {
  const Scheme& scheme = *find_scheme("quasi-4-8");
  const Hierarchy h = refine_hierarchy(test::jittered(test::triangle_grid(3, 3), 11), scheme, levels(3));
  ASSERT_EQ(h.levels.size(), 4u);
  for (std::size_t l = 1; l < h.levels.size(); ++l) {
    ASSERT_TRUE(h.levels[l].map);
    const SplitMap& map = *h.levels[l].map;
    EXPECT_EQ(map.rule, SplitRule::quasi_4_8);
    const MeshTopology parent(h.levels[l - 1].mesh), child(h.levels[l].mesh);
    EXPECT_EQ(map.child_vertex_count, h.levels[l].mesh.vertex_count());
    EXPECT_EQ(map.edge_points, h.levels[l - 1].mesh.vertex_count());
    EXPECT_FALSE(map.split_edges.empty());
    for (Index c = 0; c < map.child_vertex_count; ++c) {
      const ChildOrigin o = origin_of(map, c);
      if (c < map.edge_points) {
        EXPECT_EQ(o.kind, ChildOrigin::Kind::vertex);
        EXPECT_EQ(o.parent, c);
        continue;
      }
      ASSERT_EQ(o.kind, ChildOrigin::Kind::edge);
      for (const Index end : parent.edge_vertices(o.parent))
        EXPECT_NE(child.find_edge(c, end), kInvalidIndex) << "level " << l << ", split point " << c;
    }
  }
}

}  // namespace
}  // namespace subdiv
