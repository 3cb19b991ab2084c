// Hierarchical edits against OpenSubdiv's Hbr itself (libosd-dev installs
// its headers; support/hbr_refiner.h), refined as OpenSubdiv's regression harness refines
// (regression/hbr_regression/main.cpp): OpenSubdiv's shapes with edits, and
// random edits of every kind on closed meshes with quads, triangles and a
// pentagon; the finest level's own edits count (hbr_baseline_test.cpp
// compares without them). The comparison ignores vertex order: every vertex of ours
// within 1e-6 of the scale of a distinct one of Hbr's (float32).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/hierarchical_edits.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "support/hbr_refiner.h"
#include "support/opensubdiv_shapes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

test::hbr::Edit::Operation hbr_operation(EditOperation op) {
  switch (op) {
    case EditOperation::set: return test::hbr::Edit::Operation::set;
    case EditOperation::add: return test::hbr::Edit::Operation::add;
    case EditOperation::subtract: return test::hbr::Edit::Operation::subtract;
  }
  return test::hbr::Edit::Operation::set;
}

// `mesh` and its edits as Hbr's input.
test::hbr::Input hbr_input(const PolygonMesh& mesh, BoundaryInterpolation boundary) {
  using test::hbr::Edit;
  test::hbr::Input in;
  for (const Vec3& p : mesh.positions) in.positions.insert(in.positions.end(), {p.x, p.y, p.z});
  for (Index f = 0; f < mesh.face_count(); ++f) {
    in.face_sizes.push_back(static_cast<int>(mesh.face_size(f)));
    for (const Index v : mesh.face(f)) in.face_vertices.push_back(static_cast<int>(v));
  }
  in.edge_only = boundary == BoundaryInterpolation::edge_only;
  const HierarchicalEdits edits = read_hierarchical_edits(mesh.tags, mesh);
  auto path_of = [](Edit& e, const EditPath& path) {
    e.face = static_cast<int>(path.face);
    e.subfaces = path.subfaces;
  };
  for (const VertexValueEdit& v : edits.values) {
    Edit e;
    path_of(e, v.path);
    e.operation = hbr_operation(v.operation);
    e.corner = v.corner;
    e.value[0] = v.value.x;
    e.value[1] = v.value.y;
    e.value[2] = v.value.z;
    in.edits.push_back(e);
  }
  for (const SharpnessEdit& s : edits.sharpnesses) {
    Edit e;
    e.kind = s.edge ? Edit::Kind::edge_sharpness : Edit::Kind::corner_sharpness;
    path_of(e, s.path);
    e.operation = hbr_operation(s.operation);
    e.corner = s.corner;
    e.sharpness = s.sharpness;
    in.edits.push_back(e);
  }
  for (const EditPath& path : edits.holes) {
    Edit e;
    e.kind = Edit::Kind::hole;
    path_of(e, path);
    in.edits.push_back(e);
  }
  return in;
}

double distance(Vec3 a, Vec3 b) {
  const Vec3 d = a - b;
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

// How many of `ours` have no distinct partner in `theirs` within `tolerance`.
std::size_t unmatched(const std::vector<Vec3>& ours, const std::vector<Vec3>& theirs, double tolerance) {
  std::vector<char> taken(theirs.size(), 0);
  std::size_t missing = 0;
  for (const Vec3& p : ours) {
    bool found = false;
    for (std::size_t j = 0; j < theirs.size() && !found; ++j)
      if (!taken[j] && distance(p, theirs[j]) <= tolerance) {
        taken[j] = 1;
        found = true;
      }
    missing += !found;
  }
  return missing;
}

// Ours and Hbr's, `levels` down, with the mesh's edits; `what` names the case.
void expect_like_hbr(const PolygonMesh& mesh, BoundaryInterpolation boundary, int levels, const std::string& what) {
  RefineOptions options;
  options.levels = levels;
  options.boundary = boundary;
  const PolygonMesh ours = refine(mesh, catmull_clark_scheme(), options);
  const test::hbr::Level theirs = test::hbr::refine_catmark(hbr_input(mesh, boundary), levels);
  std::vector<Vec3> their_positions;
  for (std::size_t i = 0; i + 2 < theirs.positions.size(); i += 3)
    their_positions.push_back({theirs.positions[i], theirs.positions[i + 1], theirs.positions[i + 2]});
  ASSERT_EQ(ours.positions.size(), their_positions.size()) << what;
  ASSERT_EQ(static_cast<std::size_t>(ours.face_count()), theirs.faces) << what;
  std::vector<Index> holes = ours.tags.holes;
  std::sort(holes.begin(), holes.end());
  holes.erase(std::unique(holes.begin(), holes.end()), holes.end());
  EXPECT_EQ(holes.size(), theirs.holes) << what;
  double scale = 0.0;
  for (const Vec3& p : ours.positions) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  EXPECT_EQ(unmatched(ours.positions, their_positions, 1e-6 * std::max(scale, 1.0)), 0u) << what;
}

TEST(HbrEdits, OpenSubdivShapesWithEdits) {
  const std::filesystem::path dir = test::opensubdiv_shape_dir();
  if (!std::filesystem::exists(dir))
    GTEST_SKIP() << "OpenSubdiv regression shapes not found at " << dir
                 << " (the shared collection sits beside the repository)";
  int shapes = 0;
  for (const char* name : {"catmark_square_hedit0", "catmark_square_hedit1", "catmark_square_hedit2",
                           "catmark_square_hedit4"}) {
    const PolygonMesh mesh = read_mesh(dir / (std::string(name) + ".obj")).mesh;
    ASSERT_FALSE(read_hierarchical_edits(mesh.tags, mesh).empty()) << name;
    for (int levels = 1; levels <= 3; ++levels)
      expect_like_hbr(mesh, test::harness_boundary(mesh.tags), levels, std::string(name) + ", level " +
                                                                            std::to_string(levels));
    ++shapes;
  }
  EXPECT_EQ(shapes, 4);
}

// A closed mesh of two triangles, a pentagon and quads: a pentagonal prism
// with one side split into two triangles.
PolygonMesh prism() {
  PolygonMesh mesh;
  for (int ring = 0; ring < 2; ++ring)
    for (int i = 0; i < 5; ++i) {
      const double a = 2.0 * 3.14159265358979 * i / 5.0;
      mesh.positions.push_back({std::cos(a) * (1.0 + 0.1 * i), std::sin(a), ring * 1.5 + 0.05 * i});
    }
  auto add = [&](std::vector<Index> face) {
    mesh.face_indices.insert(mesh.face_indices.end(), face.begin(), face.end());
    mesh.face_offsets.push_back(static_cast<Index>(mesh.face_indices.size()));
  };
  add({4, 3, 2, 1, 0});
  add({5, 6, 7, 8, 9});
  for (Index i = 0; i < 4; ++i) add({i, static_cast<Index>(i + 1), static_cast<Index>(i + 6), static_cast<Index>(i + 5)});
  add({4, 0, 5});
  add({4, 5, 9});
  return mesh;
}

// Random edits of every kind and operation, on paths down to level 2, on
// closed meshes (where both libraries start sharpness from 0), refined
// three levels.
TEST(HbrEdits, RandomEditsRefineAsHbrRefines) {
  std::mt19937 rng(20261207);
  const std::vector<std::pair<std::string, PolygonMesh>> meshes{{"cube", test::cube()}, {"prism", prism()}};
  int cases = 0;
  for (const auto& [name, base] : meshes) {
    for (int trial = 0; trial < 40; ++trial) {
      PolygonMesh mesh = base;
      const int count = 1 + static_cast<int>(rng() % 4);
      for (int e = 0; e < count; ++e) {
        const auto face = static_cast<Index>(rng() % static_cast<unsigned>(mesh.face_count()));
        const int depth = static_cast<int>(rng() % 3);
        std::vector<long long> path{face};
        for (int d = 0; d < depth; ++d)
          path.push_back(static_cast<long long>(rng() % (d == 0 ? static_cast<unsigned>(mesh.face_size(face)) : 4u)));
        const unsigned corners = depth == 0 ? static_cast<unsigned>(mesh.face_size(face)) : 4u;
        const std::vector<std::string> ops{"set", "add", "subtract"};
        const std::string op = ops[rng() % 3];
        std::uniform_real_distribution<double> value(-0.5, 0.5);
        const unsigned kind = rng() % 4;
        std::vector<long long> ints{static_cast<long long>(path.size() + (kind == 3 ? 0 : 1))};
        ints.insert(ints.end(), path.begin(), path.end());
        if (kind != 3) ints.push_back(static_cast<long long>(rng() % corners));
        if (kind == 0)
          mesh.tags.other.push_back({"vertexedit", ints, {value(rng), value(rng), value(rng)}, {op, "P", "value"}});
        else if (kind == 1)
          mesh.tags.other.push_back({"vertexedit", ints, {std::floor(value(rng) * 8.0 + 4.0)}, {op, "P", "sharpness"}});
        else if (kind == 2)
          mesh.tags.other.push_back({"edgeedit", ints, {std::floor(value(rng) * 8.0 + 4.0)}, {op, "P", "sharpness"}});
        else
          mesh.tags.other.push_back({"faceedit", ints, {}, {"hole"}});
      }
      expect_like_hbr(mesh, BoundaryInterpolation::edge_and_corner, 3, name + ", trial " + std::to_string(trial));
      ++cases;
    }
  }
  EXPECT_EQ(cases, 80);
}

}  // namespace
}  // namespace subdiv
