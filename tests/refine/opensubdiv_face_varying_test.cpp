// Face-varying refinement agrees with OpenSubdiv's
// (Far::PrimvarRefiner::InterpolateFaceVarying, double precision) in each of
// its six face-varying interpolation options, on every OpenSubdiv
// regression shape with texture coordinates (catmark_ and loop_), over 3
// uniform levels: every child face corner's value within 1e-12 of the
// values' bounding-box diagonal. The levels are matched as in the position
// agreement test (support/opensubdiv_refiner.h); a corner is compared with
// OpenSubdiv's corner at the same vertex of the matched face.
//
// The shapes are refined as the position agreement test refines them
// (OpenSubdiv's harness boundary mode, sharpness rounded to float, non-
// manifold meshes allowed), skipped where it skips them, and compared up to
// their known difference (test::known_difference()).

#include <gtest/gtest.h>

// GCC flags a false "maybe uninitialized" inside OpenSubdiv's
// interpFVarFromEdges (its edge weights are set whenever they are read).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "support/opensubdiv_refiner.h"
#include "support/opensubdiv_shapes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

constexpr int kLevels = 3;
constexpr double kRelativeTolerance = 1e-12;  // of the values' bounding-box diagonal

// PrimvarRefiner's value interface: up to four doubles.
struct OsdValue {
  std::array<double, 4> v{};
  void Clear() { v.fill(0.0); }
  void AddWithWeight(const OsdValue& src, double w) {
    for (std::size_t i = 0; i < v.size(); ++i) v[i] += w * src.v[i];
  }
};

struct Case {
  std::string shape;
  FaceVaryingInterpolation mode = FaceVaryingInterpolation::all;
};

// Shapes whose first face-varying channel exists, in every mode.
std::vector<Case> cases() {
  std::vector<Case> out;
  const fs::path dir = test::opensubdiv_shape_dir();
  std::error_code ec;
  std::vector<std::string> shapes;
  if (fs::is_directory(dir, ec))
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string stem = entry.path().stem().string();
      if (entry.path().extension() != ".obj" || !(stem.starts_with("catmark_") || stem.starts_with("loop_"))) continue;
      try {
        if (!read_mesh(entry.path()).mesh.face_varying_channels.empty()) shapes.push_back(stem);
      } catch (const std::exception&) {  // the position agreement test reports unreadable shapes
      }
    }
  std::sort(shapes.begin(), shapes.end());
  for (const std::string& s : shapes)
    for (const FaceVaryingInterpolation mode : kFaceVaryingInterpolations) out.push_back({s, mode});
  if (out.empty()) out.push_back({"collection_absent", FaceVaryingInterpolation::all});  // the test skips
  return out;
}

double diagonal(const FaceVaryingChannel& ch) {
  const auto k = static_cast<std::size_t>(ch.components);
  double sum = 0.0;
  for (std::size_t c = 0; c < k; ++c) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = c; i < ch.values.size(); i += k) {
      lo = std::min(lo, ch.values[i]);
      hi = std::max(hi, ch.values[i]);
    }
    if (hi >= lo) sum += (hi - lo) * (hi - lo);
  }
  return std::sqrt(sum);
}

// Refines `mesh` (its first face-varying channel, under `mode`) with both
// libraries over kLevels levels and expects every child face corner's value
// to agree, up to `known`'s level where given.
void expect_agreement(const std::string& name, const PolygonMesh& mesh, const Scheme& scheme,
                      FaceVaryingInterpolation mode, const RefineOptions& options,
                      const test::KnownDifference* known) {
  const FaceVaryingChannel& channel = mesh.face_varying_channels.at(0);
  ASSERT_GT(channel.components, 0);
  ASSERT_LE(channel.components, 4);
  const bool loop = scheme.split == SplitRule::triangle;
  const auto refiner =
      test::make_refiner(mesh, loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, kLevels, test::their_boundary(mesh.tags),
                         &channel, mode);
  ASSERT_TRUE(refiner) << "OpenSubdiv rejected " << name;

  // Their values, level by level.
  std::vector<std::vector<OsdValue>> theirs(kLevels + 1);
  const auto k = static_cast<std::size_t>(channel.components);
  for (int l = 0; l <= kLevels; ++l)
    theirs[static_cast<std::size_t>(l)].resize(static_cast<std::size_t>(refiner->GetLevel(l).GetNumFVarValues(0)));
  for (std::size_t i = 0; i < theirs[0].size(); ++i)
    for (std::size_t j = 0; j < k; ++j) theirs[0][i].v[j] = channel.values[i * k + j];
  const Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int l = 1; l <= kLevels; ++l) {
    const OsdValue* src = theirs[static_cast<std::size_t>(l) - 1].data();
    OsdValue* dst = theirs[static_cast<std::size_t>(l)].data();
    primvar.InterpolateFaceVarying(l, src, dst, 0);
  }

  RefineOptions ours_options = options;
  ours_options.levels = kLevels;
  ours_options.face_varying = mode;
  const Hierarchy ours = refine_hierarchy(mesh, scheme, ours_options, KeepLevels::all);
  ASSERT_EQ(ours.levels.size(), static_cast<std::size_t>(kLevels + 1));
  const double tolerance = kRelativeTolerance * std::max(1.0, diagonal(channel));

  test::Correspondence correspondence = test::Correspondence::identity(mesh);
  for (int l = 1; l <= kLevels; ++l) {
    SCOPED_TRACE(name + ", level " + std::to_string(l));
    const PolygonMesh& parent = ours.levels[static_cast<std::size_t>(l) - 1].mesh;
    const PolygonMesh& child = ours.levels[static_cast<std::size_t>(l)].mesh;
    const Far::TopologyLevel& their_child = refiner->GetLevel(l);
    if (known && l >= known->level) {  // the position agreement test checks that it persists
      std::cout << "[   NOTE   ] " << name << ": known difference from level " << known->level << " (compared levels 1-"
                << l - 1 << "): " << known->why << "\n";
      return;
    }
    test::Correspondence child_map;
    ASSERT_EQ(test::child_correspondence(parent, scheme.split, child, refiner->GetLevel(l - 1), their_child,
                                         correspondence, child_map),
              "");
    ASSERT_EQ(child.face_varying_channels.size(), 1u);
    const FaceVaryingChannel& got = child.face_varying_channels[0];
    double worst = 0.0;
    std::string where;
    for (Index f = 0; f < child.face_count(); ++f) {
      const Far::Index tf = child_map.faces[static_cast<std::size_t>(f)];
      const Far::ConstIndexArray their_vertices = their_child.GetFaceVertices(tf);
      const Far::ConstIndexArray their_values = their_child.GetFaceFVarValues(tf, 0);
      const auto face = child.face(f);
      for (std::size_t j = 0; j < face.size(); ++j) {
        const Far::Index tv = child_map.vertices[static_cast<std::size_t>(face[j])];
        int r = 0;
        while (r < their_vertices.size() && their_vertices[r] != tv) ++r;
        ASSERT_LT(r, their_vertices.size());
        const OsdValue& want = theirs[static_cast<std::size_t>(l)][static_cast<std::size_t>(their_values[r])];
        const std::size_t corner = static_cast<std::size_t>(child.face_offsets[static_cast<std::size_t>(f)]) + j;
        const std::size_t ours_at = static_cast<std::size_t>(got.indices[corner]) * k;
        double d2 = 0.0;
        for (std::size_t i = 0; i < k; ++i)
          d2 += (got.values[ours_at + i] - want.v[i]) * (got.values[ours_at + i] - want.v[i]);
        const double d = std::sqrt(d2);
        if (!(d <= worst)) {
          worst = d;
          where = "face " + std::to_string(f) + " corner " + std::to_string(j) + " (vertex " +
                  std::to_string(face[j]) + "): ours (" + std::to_string(got.values[ours_at]) + ", " +
                  std::to_string(got.values[ours_at + 1]) + "), OpenSubdiv's (" + std::to_string(want.v[0]) + ", " +
                  std::to_string(want.v[1]) + ")";
        }
      }
    }
    EXPECT_LE(worst, tolerance) << "largest difference at our " << where << ", mode " << to_string(mode);
    correspondence = std::move(child_map);
  }
}

class OpenSubdivFaceVarying : public ::testing::TestWithParam<Case> {};

TEST_P(OpenSubdivFaceVarying, RefinesLikeOpenSubdiv) {
  const Case& c = GetParam();
  const fs::path path = test::opensubdiv_shape_dir() / (c.shape + ".obj");
  if (!fs::exists(path))
    GTEST_SKIP() << "OpenSubdiv regression shapes not found at " << test::opensubdiv_shape_dir();
  const Scheme& scheme = c.shape.starts_with("loop_") ? loop_scheme() : catmull_clark_scheme();
  PolygonMesh mesh = read_mesh(path).mesh;
  if (const std::string why = test::unsupported_feature(mesh); !why.empty())
    GTEST_SKIP() << c.shape << ": " << why;
  if (test::levels_keep_coincident_edges(mesh, scheme.split))
    GTEST_SKIP() << c.shape << ": its levels keep edges apart that join the same two vertices, which a level's faces "
                 << "alone lose, so opensubdiv_coincident_edges_test.cpp compares it, each level refined at once (its face-varying values are compared in the linear option only)";
  test::round_sharpness_to_float(mesh.tags);
  mesh.face_varying_channels.resize(1);
  RefineOptions options;
  options.boundary = test::harness_boundary(mesh.tags);
  options.allow_non_manifold = true;
  if (const std::string why = test::rejection(mesh, scheme, options); !why.empty())
    GTEST_SKIP() << c.shape << ": " << why;
  expect_agreement(c.shape, mesh, scheme, c.mode, options, test::known_difference(c.shape));
}

// The shapes with seams again, with random semi-sharp creases and corners
// added (sharpness 0.5 to 3.75, dyadic; at most two semi-sharp features at a
// vertex, so that OpenSubdiv's float averages of decaying sharpness are
// exact), in every option: the semi-sharp and dependent-sharpness rules on
// seams beyond what the regression shapes tag.
TEST(OpenSubdivFaceVaryingRandomSharpness, RefinesLikeOpenSubdiv) {
  const char* shapes[] = {"catmark_fvar_bound0", "catmark_fvar_bound1", "catmark_fvar_bound2",
                          "catmark_fvar_project0", "catmark_quadstrips", "loop_fvar_bound0",
                          "loop_fvar_bound1", "loop_fvar_bound3"};
  constexpr double kSharpness[] = {0.5, 1.0, 1.5, 2.0, 2.5, 3.75};
  int compared = 0;
  for (const char* shape : shapes) {
    const fs::path path = test::opensubdiv_shape_dir() / (std::string(shape) + ".obj");
    if (!fs::exists(path)) continue;
    const Scheme& scheme = std::string(shape).starts_with("loop_") ? loop_scheme() : catmull_clark_scheme();
    for (unsigned seed = 1; seed <= 2; ++seed) {
      PolygonMesh mesh = read_mesh(path).mesh;
      mesh.face_varying_channels.resize(1);
      std::mt19937 random(seed);
      const MeshTopology topology(mesh);
      // Semi-sharp features per vertex; vertices and edges the shape tags
      // already get no new tag (its sharpness need not be dyadic).
      std::vector<int> features(static_cast<std::size_t>(mesh.vertex_count()), 0);
      std::vector<char> tagged(static_cast<std::size_t>(topology.edge_count()), 0);
      for (const CreaseTag& c : mesh.tags.creases) {
        features[static_cast<std::size_t>(c.v0)] = features[static_cast<std::size_t>(c.v1)] = 2;
        if (const Index e = topology.find_edge(c.v0, c.v1); e != kInvalidIndex) tagged[static_cast<std::size_t>(e)] = 1;
      }
      for (const CornerTag& c : mesh.tags.corners) features[static_cast<std::size_t>(c.vertex)] = 2;
      for (Index e = 0; e < topology.edge_count(); ++e) {
        const auto [a, b] = topology.edge_vertices(e);
        if (random() % 4 != 0 || tagged[static_cast<std::size_t>(e)] || features[static_cast<std::size_t>(a)] >= 2 ||
            features[static_cast<std::size_t>(b)] >= 2)
          continue;
        mesh.tags.creases.push_back({a, b, kSharpness[random() % std::size(kSharpness)]});
        ++features[static_cast<std::size_t>(a)];
        ++features[static_cast<std::size_t>(b)];
      }
      for (Index v = 0; v < mesh.vertex_count(); ++v)
        if (random() % 8 == 0 && features[static_cast<std::size_t>(v)] < 2) {
          CornerTag corner;
          corner.vertex = v;
          corner.sharpness = kSharpness[random() % std::size(kSharpness)];
          mesh.tags.corners.push_back(corner);
          ++features[static_cast<std::size_t>(v)];
        }
      test::round_sharpness_to_float(mesh.tags);  // the shape's own tags (0.9, 2.1, 0.1 on catmark_fvar_bound2)
      RefineOptions options;
      options.boundary = test::harness_boundary(mesh.tags);
      for (const FaceVaryingInterpolation mode : kFaceVaryingInterpolations) {
        expect_agreement(std::string(shape) + " (seed " + std::to_string(seed) + ", " + to_string(mode) + ")", mesh,
                         scheme, mode, options, nullptr);
        ++compared;
      }
    }
  }
  if (compared == 0) GTEST_SKIP() << "OpenSubdiv regression shapes not found at " << test::opensubdiv_shape_dir();
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string mode = to_string(info.param.mode);
  std::replace(mode.begin(), mode.end(), '-', '_');
  return test::shape_test_name(info.param.shape) + "_" + mode;
}

INSTANTIATE_TEST_SUITE_P(Shapes, OpenSubdivFaceVarying, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace subdiv
