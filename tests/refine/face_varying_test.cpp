// Smooth face-varying refinement (refine/face_varying.h), by invariants and
// against the engine's own positions; agreement with OpenSubdiv in each
// option is opensubdiv_face_varying_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

constexpr FaceVaryingInterpolation kSmoothModes[] = {
    FaceVaryingInterpolation::none,          FaceVaryingInterpolation::corners_only,
    FaceVaryingInterpolation::corners_plus1, FaceVaryingInterpolation::corners_plus2,
    FaceVaryingInterpolation::boundaries,
};

// A channel holding each corner's vertex position: continuous, no seam.
FaceVaryingChannel positions_channel(const PolygonMesh& mesh) {
  FaceVaryingChannel ch{"P", 3, {}, mesh.face_indices};
  for (const Vec3& p : mesh.positions) ch.values.insert(ch.values.end(), {p.x, p.y, p.z});
  return ch;
}

// A channel giving every face corner a value of its own (a seam along every
// edge), value i = (i, 2i) scaled.
FaceVaryingChannel per_corner_channel(const PolygonMesh& mesh) {
  FaceVaryingChannel ch{"uv", 2, {}, {}};
  for (std::size_t c = 0; c < mesh.face_indices.size(); ++c) {
    ch.indices.push_back(static_cast<Index>(c));
    ch.values.insert(ch.values.end(), {0.1 * static_cast<double>(c), 0.2 * static_cast<double>(c % 7)});
  }
  return ch;
}

double largest_channel_difference_from_positions(const PolygonMesh& refined) {
  const FaceVaryingChannel& ch = refined.face_varying_channels.at(0);
  double worst = 0.0;
  for (std::size_t c = 0; c < refined.face_indices.size(); ++c) {
    const Vec3& p = refined.positions[static_cast<std::size_t>(refined.face_indices[c])];
    const std::size_t v = static_cast<std::size_t>(ch.indices[c]) * 3;
    worst = std::max(worst, norm(Vec3{ch.values[v], ch.values[v + 1], ch.values[v + 2]} - p));
  }
  return worst;
}

PolygonMesh refined(PolygonMesh mesh, const Scheme& scheme, FaceVaryingInterpolation mode, int levels) {
  mesh.tags.face_varying_interpolation = mode;
  RefineOptions options;
  options.levels = levels;
  return refine(mesh, scheme, options);
}

// Where the channel is continuous, the masks are the scheme's own: a channel
// carrying the positions follows them exactly, in every smooth option, on
// closed meshes (every value matches its vertex) and on open ones under
// edge-and-corner boundaries (the options sharpen only what the boundary
// rules already keep) — except `boundaries`, linear along the boundary.
TEST(FaceVarying, ContinuousChannelFollowsThePositions) {
  struct Case {
    std::string name;
    PolygonMesh mesh;
    const Scheme* scheme;
  };
  const std::vector<Case> cases = {
      {"cube", test::cube(), &catmull_clark_scheme()},
      {"creased cube", test::creased_cube(), &catmull_clark_scheme()},
      {"jittered grid", test::jittered(test::quad_grid(4, 3), 3), &catmull_clark_scheme()},
      {"tetrahedron", test::tetrahedron(), &loop_scheme()},
      {"bipyramid", test::bipyramid(5), &loop_scheme()},
      {"triangle grid", test::jittered(test::triangle_grid(4, 3), 5), &loop_scheme()},
  };
  for (const Case& c : cases) {
    PolygonMesh mesh = c.mesh;
    mesh.face_varying_channels = {positions_channel(mesh)};
    const MeshTopology topology(mesh);
    const bool open = !topology.boundary_loops().empty();
    for (const FaceVaryingInterpolation mode : kSmoothModes) {
      SCOPED_TRACE(c.name + ", " + to_string(mode));
      const PolygonMesh out = refined(mesh, *c.scheme, mode, 3);
      const double d = largest_channel_difference_from_positions(out);
      if (open && mode == FaceVaryingInterpolation::boundaries) EXPECT_GT(d, 1e-3);
      else EXPECT_LE(d, 1e-14 * test::radius(mesh));
    }
    // `all` is linear within the faces: not the surface.
    SCOPED_TRACE(c.name + ", all");
    EXPECT_GT(largest_channel_difference_from_positions(refined(mesh, *c.scheme, FaceVaryingInterpolation::all, 2)),
              1e-3);
  }
}

// Every mask sums to one: a constant stays constant, across every seam.
TEST(FaceVarying, ConstantValuesStayConstant) {
  for (const Scheme* scheme : {&catmull_clark_scheme(), &loop_scheme()}) {
    PolygonMesh mesh = scheme == &loop_scheme() ? test::triangle_grid(3, 3) : test::creased_cube();
    FaceVaryingChannel ch = per_corner_channel(mesh);
    for (std::size_t i = 0; i < ch.values.size(); i += 2) {
      ch.values[i] = 0.25;
      ch.values[i + 1] = -3.0;
    }
    mesh.face_varying_channels = {ch};
    for (const FaceVaryingInterpolation mode : kFaceVaryingInterpolations) {
      SCOPED_TRACE(std::string(scheme->name) + ", " + to_string(mode));
      const PolygonMesh out = refined(mesh, *scheme, mode, 3);
      for (const double value : out.face_varying_channels.at(0).values)
        ASSERT_TRUE(std::abs(value - 0.25) < 1e-15 || std::abs(value + 3.0) < 1e-14) << value;
    }
  }
}

// Along a seam the two sides refine independently: changing the values on
// one side of every seam leaves the other side's values alone.
TEST(FaceVarying, SeamSidesAreIndependent) {
  PolygonMesh mesh = test::quad_grid(4, 4);
  // Two UV islands: faces left of x = 2 and right of it, each with its own values.
  FaceVaryingChannel ch{"uv", 2, {}, {}};
  std::vector<Index> left(static_cast<std::size_t>(mesh.vertex_count()), -1), right = left;
  auto value_for = [&](std::vector<Index>& island, Index v, double shift) {
    Index& id = island[static_cast<std::size_t>(v)];
    if (id < 0) {
      id = static_cast<Index>(ch.values.size() / 2);
      const Vec3& p = mesh.positions[static_cast<std::size_t>(v)];
      ch.values.insert(ch.values.end(), {p.x * p.x + shift, p.y});
    }
    return id;
  };
  std::vector<double> centre_x;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    double x = 0.0;
    for (const Index v : mesh.face(f)) x += mesh.positions[static_cast<std::size_t>(v)].x / mesh.face_size(f);
    centre_x.push_back(x);
  }
  const double split = 0.5 * (*std::min_element(centre_x.begin(), centre_x.end()) +
                              *std::max_element(centre_x.begin(), centre_x.end()));
  for (Index f = 0; f < mesh.face_count(); ++f)
    for (const Index v : mesh.face(f))
      ch.indices.push_back(centre_x[static_cast<std::size_t>(f)] < split ? value_for(left, v, 0.0)
                                                                           : value_for(right, v, 0.0));
  mesh.face_varying_channels = {ch};
  for (const FaceVaryingInterpolation mode : kSmoothModes) {
    SCOPED_TRACE(to_string(mode));
    const PolygonMesh a = refined(mesh, catmull_clark_scheme(), mode, 2);
    PolygonMesh moved = mesh;
    for (const Index id : right)
      if (id >= 0) moved.face_varying_channels[0].values[2 * static_cast<std::size_t>(id)] += 5.0;
    const PolygonMesh b = refined(moved, catmull_clark_scheme(), mode, 2);
    const FaceVaryingChannel& ca = a.face_varying_channels[0];
    const FaceVaryingChannel& cb = b.face_varying_channels[0];
    ASSERT_EQ(ca.indices, cb.indices);
    int unchanged = 0, shifted = 0;
    for (std::size_t c = 0; c < ca.indices.size(); ++c) {
      const double d = cb.values[2 * static_cast<std::size_t>(cb.indices[c])] -
                       ca.values[2 * static_cast<std::size_t>(ca.indices[c])];
      if (std::abs(d) < 1e-12) ++unchanged;
      else if (std::abs(d - 5.0) < 1e-12) ++shifted;
    }
    EXPECT_EQ(unchanged + shifted, static_cast<int>(ca.indices.size())) << "a value mixes the two islands";
    EXPECT_GT(unchanged, 0);
    EXPECT_GT(shifted, 0);
  }
}

// The option reaches the refined levels' tags, and overrides the mesh's.
TEST(FaceVarying, OptionOverridesTheTag) {
  PolygonMesh mesh = test::cube();
  mesh.face_varying_channels = {per_corner_channel(mesh)};
  RefineOptions options;
  options.levels = 2;
  options.face_varying = FaceVaryingInterpolation::none;
  const PolygonMesh by_option = refine(mesh, catmull_clark_scheme(), options);
  EXPECT_EQ(by_option.tags.face_varying_interpolation, FaceVaryingInterpolation::none);
  EXPECT_TRUE(by_option.tags.face_varying_interpolation_set);
  const PolygonMesh by_tag = refined(mesh, catmull_clark_scheme(), FaceVaryingInterpolation::none, 2);
  EXPECT_EQ(by_option.face_varying_channels[0].values, by_tag.face_varying_channels[0].values);
  EXPECT_NE(by_option.face_varying_channels[0].values,
            refined(mesh, catmull_clark_scheme(), FaceVaryingInterpolation::all, 2).face_varying_channels[0].values);
}

// A file's tag chooses the option (tests/data/uv_seams.obj: corners-plus1,
// with a seam, a semi-sharp crease and a corner).
TEST(FaceVarying, TheFilesTagChoosesTheOption) {
  const PolygonMesh mesh = read_mesh(test::data_path("uv_seams.obj")).mesh;
  ASSERT_EQ(mesh.tags.face_varying_interpolation, FaceVaryingInterpolation::corners_plus1);
  RefineOptions options;
  options.levels = 3;
  const PolygonMesh by_tag = refine(mesh, catmull_clark_scheme(), options);
  options.face_varying = FaceVaryingInterpolation::corners_plus1;
  EXPECT_EQ(by_tag.face_varying_channels.at(0).values, refine(mesh, catmull_clark_scheme(), options).face_varying_channels.at(0).values);
  options.face_varying = FaceVaryingInterpolation::all;
  EXPECT_NE(by_tag.face_varying_channels.at(0).values, refine(mesh, catmull_clark_scheme(), options).face_varying_channels.at(0).values);
}

// Schemes without the trait refine face-varying channels linearly whatever
// the option says.
TEST(FaceVarying, OtherSchemesStayLinear) {
  PolygonMesh mesh = test::bipyramid(5);
  mesh.face_varying_channels = {positions_channel(mesh)};
  const PolygonMesh linear = refined(mesh, butterfly_scheme(), FaceVaryingInterpolation::all, 2);
  const PolygonMesh asked = refined(mesh, butterfly_scheme(), FaceVaryingInterpolation::none, 2);
  EXPECT_EQ(linear.face_varying_channels[0].values, asked.face_varying_channels[0].values);
  EXPECT_EQ(linear.face_varying_channels[0].indices, asked.face_varying_channels[0].indices);
}

// The hierarchy carries the tags level to level as a single refinement
// does: its last level equals refine()'s.
TEST(FaceVarying, HierarchyEqualsRefine) {
  PolygonMesh mesh = test::creased_cube();
  mesh.face_varying_channels = {per_corner_channel(mesh)};
  mesh.tags.face_varying_interpolation = FaceVaryingInterpolation::corners_plus1;
  RefineOptions options;
  options.levels = 3;
  const Hierarchy h = refine_hierarchy(mesh, catmull_clark_scheme(), options, KeepLevels::all);
  const PolygonMesh once = refine(mesh, catmull_clark_scheme(), options);
  EXPECT_EQ(h.finest().mesh.face_varying_channels[0].values, once.face_varying_channels[0].values);
  EXPECT_EQ(h.finest().mesh.face_varying_channels[0].indices, once.face_varying_channels[0].indices);
}

}  // namespace
}  // namespace subdiv
