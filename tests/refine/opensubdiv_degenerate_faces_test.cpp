// Faces that repeat a vertex refine as OpenSubdiv refines them, on every
// OpenSubdiv regression shape of the shared collection that has such faces
// (catmark_nonman_edges, catmark_nonman_quadpole8/360, loop_nonman_edges).
//
// OpenSubdiv makes a side joining a vertex to itself an edge of its own, and
// a face's second side along an edge it already runs along a second edge;
// the halves of such an edge one level down join the same two vertices
// without being one edge. A level's faces alone cannot say that, so the
// level-by-level comparison of opensubdiv_agreement_test.cpp does not apply:
// each level here is refined from the control mesh in one call, and
// compared with OpenSubdiv's level of the same depth order-independently
// (the two libraries number vertices differently, and coincident vertices,
// the halves' edge points, cannot be told apart by their neighbours'
// numbering either): the same vertex and face counts, and every vertex of
// ours within 1e-12 of the bounding-box diagonal of a distinct vertex of
// theirs.

#include <gtest/gtest.h>

#include <opensubdiv/far/topologyRefiner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/opensubdiv_refiner.h"
#include "support/opensubdiv_shapes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;
namespace Sdc = OpenSubdiv::Sdc;

constexpr int kLevels = 3;
constexpr double kRelativeTolerance = 1e-12;  // of the level-0 bounding-box diagonal

std::vector<std::string> shapes_with_repeated_vertices() {
  std::vector<std::string> names;
  std::error_code ec;
  if (fs::is_directory(test::opensubdiv_shape_dir(), ec))
    for (const auto& entry : fs::directory_iterator(test::opensubdiv_shape_dir(), ec))
      if (entry.path().extension() == ".obj" && test::repeats_vertices(read_mesh(entry.path()).mesh))
        names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  if (names.empty()) names.push_back("collection_absent");  // the test skips, saying so
  return names;
}

// Pairs each of `ours` with a distinct one of `theirs` within `tolerance`
// (a hash grid of cells wider than the tolerance; coincident points are
// interchangeable). Returns the number of ours left without a partner.
std::size_t unmatched(const std::vector<Vec3>& ours, const std::vector<Vec3>& theirs, double tolerance) {
  const double cell = std::max(tolerance * 16.0, 1e-300);
  auto cell_of = [cell](const Vec3& p) {
    return std::array<long long, 3>{static_cast<long long>(std::floor(p.x / cell)),
                                     static_cast<long long>(std::floor(p.y / cell)),
                                     static_cast<long long>(std::floor(p.z / cell))};
  };
  auto hash = [](const std::array<long long, 3>& c) {
    return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
  };
  std::unordered_map<std::size_t, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < theirs.size(); ++i) grid[hash(cell_of(theirs[i]))].push_back(i);
  std::vector<char> taken(theirs.size(), 0);
  std::size_t missing = 0;
  for (const Vec3& p : ours) {
    const auto c = cell_of(p);
    bool found = false;
    for (long long dx = -1; dx <= 1 && !found; ++dx)
      for (long long dy = -1; dy <= 1 && !found; ++dy)
        for (long long dz = -1; dz <= 1 && !found; ++dz) {
          const auto it = grid.find(hash({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == grid.end()) continue;
          for (const std::size_t j : it->second)
            if (!taken[j] && norm(theirs[j] - p) <= tolerance) {
              taken[j] = 1;
              found = true;
              break;
            }
        }
    missing += !found;
  }
  return missing;
}

class OpenSubdivDegenerateFaces : public ::testing::TestWithParam<std::string> {};

TEST_P(OpenSubdivDegenerateFaces, RefinesLikeOpenSubdiv) {
  const std::string shape = GetParam();
  const fs::path path = test::opensubdiv_shape_dir() / (shape + ".obj");
  if (!fs::exists(path))
    GTEST_SKIP() << "OpenSubdiv regression shapes not found at " << test::opensubdiv_shape_dir()
                 << " (the shared collection sits beside the repository)";
  const bool loop = shape.starts_with("loop_");
  const Scheme& scheme = loop ? loop_scheme() : catmull_clark_scheme();
  PolygonMesh mesh = read_mesh(path).mesh;
  ASSERT_TRUE(test::repeats_vertices(mesh));
  test::round_sharpness_to_float(mesh.tags);

  RefineOptions options;
  options.boundary = test::harness_boundary(mesh.tags);
  options.allow_non_manifold = true;
  ASSERT_EQ(test::rejection(mesh, scheme, options), "");

  const auto refiner =
      test::make_refiner(mesh, loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, kLevels, test::their_boundary(mesh.tags));
  ASSERT_TRUE(refiner) << "OpenSubdiv rejected " << shape;
  const std::vector<std::vector<test::OsdVertex>> theirs = test::their_positions(*refiner, mesh);
  const double tolerance = kRelativeTolerance * test::bbox_diagonal(mesh.positions);

  for (int level = 1; level <= kLevels; ++level) {
    SCOPED_TRACE(shape + ", level " + std::to_string(level));
    options.levels = level;
    PolygonMesh ours;
    ASSERT_NO_THROW(ours = refine(mesh, scheme, options));
    ASSERT_EQ(ours.vertex_count(), refiner->GetLevel(level).GetNumVertices());
    ASSERT_EQ(ours.face_count(), refiner->GetLevel(level).GetNumFaces());
    std::vector<Vec3> their_points;
    for (const test::OsdVertex& t : theirs[static_cast<std::size_t>(level)]) their_points.push_back(t.vec());
    EXPECT_EQ(unmatched(ours.positions, their_points, tolerance), 0u)
        << "of our " << ours.vertex_count() << " vertices, these have no OpenSubdiv vertex within " << tolerance;
  }
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) { return test::shape_test_name(info.param); }

INSTANTIATE_TEST_SUITE_P(Shapes, OpenSubdivDegenerateFaces, ::testing::ValuesIn(shapes_with_repeated_vertices()),
                         param_name);

}  // namespace
}  // namespace subdiv
