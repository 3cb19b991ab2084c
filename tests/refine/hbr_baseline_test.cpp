// Refinement reproduces OpenSubdiv's own reference results: the Hbr
// regression baselines of the shared collection
// (../shared/data/meshes/opensubdiv_hbr_baseline/<shape>_refined<k>.obj, the
// shape ../opensubdiv/<shape>.obj after k uniform levels, float32 positions
// in Hbr's vertex order). The comparison ignores order: the same vertex and
// face counts, every vertex of ours within 1e-6 * scale of a baseline vertex
// and vice versa (found through a uniform grid), and, where the vertices
// correspond one to one, the same faces. The scale is the larger of the
// bounding-box diagonal and the largest coordinate magnitude: Hbr computed in
// float32, whose rounding is relative to the coordinates, not to the mesh's
// size (catmark_flap lies about 1.9 from the origin with a 0.29 diagonal;
// there OpenSubdiv's own Far refiner, in float, differs from the same refiner
// in double by 2.5e-7, and Hbr's baseline from either by up to 4e-7).
//
// Boundary interpolation follows OpenSubdiv's regression harness: an absent
// `t interpolateboundary` tag, or 0, refines as edge-only. Shapes with
// hierarchical edits are refined from the control mesh at once, since the
// edits' paths name its faces, less the edits of the level compared (see
// without_edits_on_level()); shapes refine() rejects are skipped, saying
// why. Where Hbr
// itself differs from OpenSubdiv's Sdc/Far rules, which subdiv follows (see
// opensubdiv_agreement_test.cpp), the difference is listed, with what
// differs, in kKnownDifferences.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/refine/hierarchical_edits.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"
#include "support/opensubdiv_shapes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;

constexpr double kRelativeTolerance = 1e-6;  // of the scale (see top); the baselines are float32
constexpr double kRelativeCell = 1e-4;       // grid cell size, relative to the bounding-box diagonal

// Genuine differences, kept under test: from `level` on, the baseline
// differs from subdiv's refinement; the levels before it are compared in
// full. The test fails if the difference disappears, so that this list stays
// true.
struct KnownDifference {
  std::string_view shape;
  int level;
  std::string_view why;
};
constexpr KnownDifference kKnownDifferences[] = {
    // Chaikin creasing; level 1 agrees. Where a vertex's rule changes, Hbr
    // decides and weights the transition with the uniform method's tests
    // even under Chaikin creasing (HbrHalfedge::IsSharp: an edge of sharpness
    // >= 1 stays sharp; HbrVertex::GetFractionalMask averages the edges of
    // sharpness in (0, 1)), Sdc with the Chaikin children that decay to 0:
    // at a level-1 edge-point vertex whose halves have sharpness 1 and 0.25
    // (both decay), Hbr blends in the crease rule with weight 0.25, Sdc with
    // 0.625. (Hbr's Chaikin sharpness also differs from Sdc::Crease's where
    // a semi-sharp edge has no other semi-sharp edge at a vertex: Hbr
    // averages infinitely sharp edges in, or takes 3/4 s - 1 when there is
    // no other sharp edge; Sdc takes s - 1.) subdiv follows Sdc, agreeing
    // with OpenSubdiv's Far refiner to 1e-12 (opensubdiv_agreement_test.cpp);
    // Far itself differs from this baseline by up to 0.033 at level 2 and
    // 0.019 at level 3 (bounding-box diagonal 3.3), as subdiv does.
    {"catmark_chaikin1", 2,
     "Hbr's Chaikin creasing weights rule transitions by the uniform test; Sdc/Far (and subdiv) by the "
     "Chaikin child sharpness"},
};

const KnownDifference* known_difference(const std::string& shape) {
  for (const KnownDifference& k : kKnownDifferences)
    if (k.shape == shape) return &k;
  return nullptr;
}

fs::path shape_dir() { return test::opensubdiv_shape_dir(); }
using test::harness_boundary;
using test::rejection;
fs::path baseline_dir() { return fs::path(test::shared_mesh_dir()) / "opensubdiv_hbr_baseline"; }
fs::path baseline_path(const std::string& shape, int k) {
  return baseline_dir() / (shape + "_refined" + std::to_string(k) + ".obj");
}

const Scheme* scheme_of(const std::string& shape) {
  if (shape.starts_with("catmark_")) return find_scheme("catmull-clark");
  if (shape.starts_with("loop_")) return find_scheme("loop");
  if (shape.starts_with("bilinear_")) return find_scheme("bilinear");
  return nullptr;
}

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  void add(const std::vector<Vec3>& points) {
    for (const Vec3& p : points)
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], p[i]);
        hi[i] = std::max(hi[i], p[i]);
      }
  }
  double diagonal() const { return lo.x <= hi.x ? norm(hi - lo) : 0.0; }
  double largest_coordinate() const {
    double m = 0.0;
    for (int i = 0; i < 3; ++i) m = std::max({m, std::abs(lo[i]), std::abs(hi[i])});
    return m;
  }
};

// Points bucketed in a uniform grid of cubic cells (hashed, sorted by hash).
// nearest() looks at the 27 cells around a query, so it finds the nearest
// point whenever one lies within a cell size.
class PointGrid {
 public:
  struct Hit {
    Index index = kInvalidIndex;
    double distance = std::numeric_limits<double>::infinity();
  };

  PointGrid(const std::vector<Vec3>& points, double cell) : points_(points), cell_(cell) {
    entries_.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) entries_.push_back({key(cell_of(points[i])), static_cast<Index>(i)});
    std::sort(entries_.begin(), entries_.end());
  }

  Hit nearest(const Vec3& p) const {
    Hit best;
    const auto c = cell_of(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const std::uint64_t k = key({c[0] + dx, c[1] + dy, c[2] + dz});
          auto it = std::lower_bound(entries_.begin(), entries_.end(), Entry{k, 0});
          for (; it != entries_.end() && it->key == k; ++it) consider(p, it->index, best);
        }
    return best;
  }

  // Every point: for a query with nothing near (only to say how far it is).
  Hit nearest_brute_force(const Vec3& p) const {
    Hit best;
    for (std::size_t i = 0; i < points_.size(); ++i) consider(p, static_cast<Index>(i), best);
    return best;
  }

 private:
  struct Entry {
    std::uint64_t key;
    Index index;
    friend bool operator<(const Entry& a, const Entry& b) { return a.key != b.key ? a.key < b.key : a.index < b.index; }
  };

  void consider(const Vec3& p, Index i, Hit& best) const {
    const double d = norm(points_[static_cast<std::size_t>(i)] - p);
    if (d < best.distance || (d == best.distance && i < best.index)) best = {i, d};
  }
  std::array<std::int64_t, 3> cell_of(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / cell_)), static_cast<std::int64_t>(std::floor(p.y / cell_)),
            static_cast<std::int64_t>(std::floor(p.z / cell_))};
  }
  // Different cells may share a key; nearest() measures every candidate anyway.
  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    std::uint64_t h = 0;
    for (const std::int64_t x : c) h = (h ^ static_cast<std::uint64_t>(x)) * 0x9E3779B97F4A7C15ull + (h >> 29);
    return h;
  }

  const std::vector<Vec3>& points_;
  double cell_;
  std::vector<Entry> entries_;
};

struct Matching {
  std::vector<Index> to;        ///< nearest point of the other set, or kInvalidIndex
  double max_distance = 0.0;    ///< over all points (a lower bound once far ones are not measured)
  std::size_t unmatched = 0;    ///< points with nothing within the tolerance
  Index worst = kInvalidIndex;  ///< the point at max_distance
};

// For each of `from`, the nearest point of `grid` (within the tolerance).
Matching match(const std::vector<Vec3>& from, const PointGrid& grid, double tolerance) {
  constexpr std::size_t kMaxBruteForce = 200;
  Matching m;
  m.to.assign(from.size(), kInvalidIndex);
  for (std::size_t i = 0; i < from.size(); ++i) {
    PointGrid::Hit hit = grid.nearest(from[i]);
    if (!(hit.distance <= tolerance)) {
      ++m.unmatched;
      if (hit.index == kInvalidIndex && m.unmatched <= kMaxBruteForce) hit = grid.nearest_brute_force(from[i]);
    } else {
      m.to[i] = hit.index;
    }
    if (!(hit.distance <= m.max_distance)) {
      m.max_distance = hit.distance;
      m.worst = static_cast<Index>(i);
    }
  }
  return m;
}

// A face up to rotation: rotated to start at its smallest vertex.
std::vector<Index> canonical_face(std::vector<Index> face) {
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
  return face;
}

std::string vec_string(const Vec3& p) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

// Shape name -> refinement levels with a baseline.
std::map<std::string, std::vector<int>> baselines() {
  std::map<std::string, std::vector<int>> out;
  std::error_code ec;
  if (!fs::is_directory(baseline_dir(), ec)) return out;
  // <shape>_refined<k>.obj (no std::regex: GCC 12 warns inside it under the sanitizers)
  const std::string marker = "_refined";
  for (const auto& entry : fs::directory_iterator(baseline_dir(), ec)) {
    if (entry.path().extension() != ".obj") continue;
    const std::string stem = entry.path().stem().string();
    const auto at = stem.rfind(marker);
    if (at == std::string::npos || at == 0) continue;
    const std::string digits = stem.substr(at + marker.size());
    if (digits.empty() || digits.size() > 2 ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    out[stem.substr(0, at)].push_back(std::stoi(digits));
  }
  for (auto& [shape, levels] : out) std::sort(levels.begin(), levels.end());
  return out;
}

std::vector<std::string> baseline_shapes() {
  std::vector<std::string> names;
  for (const auto& [shape, levels] : baselines()) names.push_back(shape);
  if (names.empty()) names.push_back("collection_absent");  // the test skips, saying so
  return names;
}

// Hbr applies a vertex edit lazily, once the vertex's neighbourhood is
// needed to refine further (HbrVertex::GuaranteeNeighbors), and the
// regression harness writes its finest level without that
// (regression/hbr_regression/main.cpp, writeObj): a baseline of level k
// shows the edits of the levels above k only. The mesh without the edit
// tags of level k refines to what it shows; hbr_edits_test.cpp compares
// with Hbr asked for those edits too.
PolygonMesh without_edits_on_level(PolygonMesh mesh, int k) {
  std::size_t rank = 0;
  std::erase_if(mesh.tags.other, [&](const RawTag& t) {
    ++rank;
    return is_hierarchical_edit(t) && hierarchical_edit_level(t, rank, mesh) == k;
  });
  return mesh;
}

class HbrBaseline : public ::testing::TestWithParam<std::string> {};

TEST_P(HbrBaseline, RefinementMatchesTheBaseline) {
  const std::string shape = GetParam();
  const auto all = baselines();
  const auto found = all.find(shape);
  if (found == all.end())
    GTEST_SKIP() << "OpenSubdiv Hbr baselines not found at " << baseline_dir()
                 << " (the shared collection sits beside the repository)";
  const std::vector<int>& levels = found->second;

  const fs::path source = shape_dir() / (shape + ".obj");
  ASSERT_TRUE(fs::exists(source)) << "baseline without its shape: " << source;
  const Scheme* scheme = scheme_of(shape);
  ASSERT_NE(scheme, nullptr) << "no scheme for " << shape << " (expected catmark_, loop_ or bilinear_)";
  PolygonMesh mesh = read_mesh(source).mesh;
  // Hierarchical edits name the control mesh's faces: each level is refined
  // from it in one call.
  const bool edited = std::any_of(mesh.tags.other.begin(), mesh.tags.other.end(), is_hierarchical_edit);

  RefineOptions options;
  options.levels = 1;
  options.boundary = harness_boundary(mesh.tags);
  options.allow_non_manifold = true;
  if (const std::string why = rejection(mesh, *scheme, options); !why.empty())
    GTEST_SKIP() << shape << ": " << why;

  const KnownDifference* known = known_difference(shape);
  PolygonMesh ours = mesh;
  int level = 0;
  for (const int k : levels) {
    SCOPED_TRACE(shape + ", " + std::to_string(k) + " levels");
    ASSERT_GE(k, 1);
    if (edited) {
      options.levels = k;
      ASSERT_NO_THROW(ours = refine(without_edits_on_level(mesh, k), *scheme, options));
    }
    for (; !edited && level < k; ++level) {
      options.start_level = level;  // the level refined is this level of the hierarchy, not a control mesh
      ASSERT_NO_THROW(ours = refine(ours, *scheme, options));
    }
    const PolygonMesh baseline = read_mesh(baseline_path(shape, k)).mesh;
    ASSERT_EQ(ours.vertex_count(), baseline.vertex_count());
    ASSERT_EQ(ours.face_count(), baseline.face_count());

    Box box;
    box.add(ours.positions);
    box.add(baseline.positions);
    const double diagonal = box.diagonal();
    ASSERT_GT(diagonal, 0.0);
    const double tolerance = kRelativeTolerance * std::max(diagonal, box.largest_coordinate());
    // Cells at least as large as the tolerance, so that nearest() sees every match.
    const double cell = std::max(kRelativeCell * diagonal, 2.0 * tolerance);
    const PointGrid our_grid(ours.positions, cell);
    const PointGrid their_grid(baseline.positions, cell);
    const Matching ours_to_theirs = match(ours.positions, their_grid, tolerance);
    const Matching theirs_to_ours = match(baseline.positions, our_grid, tolerance);
    if (known && k >= known->level) {
      if (ours_to_theirs.unmatched != 0 || theirs_to_ours.unmatched != 0) {
        std::cout << "[   NOTE   ] " << shape << ", " << k << " levels: known difference (largest distance "
                  << std::max(ours_to_theirs.max_distance, theirs_to_ours.max_distance) << "): " << known->why
                  << "\n";
        continue;
      }
      ADD_FAILURE() << "known difference no longer observed: remove it from kKnownDifferences (" << known->why << ")";
    }
    EXPECT_EQ(ours_to_theirs.unmatched, 0u)
        << "our vertices without a baseline vertex within " << tolerance << "; largest distance "
        << ours_to_theirs.max_distance << " (" << ours_to_theirs.max_distance / diagonal
        << " of the diagonal) at our vertex " << ours_to_theirs.worst << " "
        << vec_string(ours.positions[static_cast<std::size_t>(ours_to_theirs.worst)]);
    EXPECT_EQ(theirs_to_ours.unmatched, 0u)
        << "baseline vertices without one of ours within " << tolerance << "; largest distance "
        << theirs_to_ours.max_distance << " (" << theirs_to_ours.max_distance / diagonal
        << " of the diagonal) at baseline vertex " << theirs_to_ours.worst << " "
        << vec_string(baseline.positions[static_cast<std::size_t>(theirs_to_ours.worst)]);
    if (ours_to_theirs.unmatched != 0 || theirs_to_ours.unmatched != 0) continue;

    // One to one? Then the faces must be the same too.
    bool bijective = true;
    for (std::size_t i = 0; i < theirs_to_ours.to.size() && bijective; ++i)
      bijective = ours_to_theirs.to[static_cast<std::size_t>(theirs_to_ours.to[i])] == static_cast<Index>(i);
    EXPECT_TRUE(bijective) << "vertices are within the tolerance, but not one to one";
    if (!bijective) continue;
    std::vector<std::vector<Index>> our_faces, their_faces;
    for (Index f = 0; f < ours.face_count(); ++f)
      our_faces.push_back(canonical_face({ours.face(f).begin(), ours.face(f).end()}));
    for (Index f = 0; f < baseline.face_count(); ++f) {
      std::vector<Index> face;
      for (const Index v : baseline.face(f)) face.push_back(theirs_to_ours.to[static_cast<std::size_t>(v)]);
      their_faces.push_back(canonical_face(std::move(face)));
    }
    std::sort(our_faces.begin(), our_faces.end());
    std::sort(their_faces.begin(), their_faces.end());
    std::vector<std::vector<Index>> differing;
    std::set_symmetric_difference(our_faces.begin(), our_faces.end(), their_faces.begin(), their_faces.end(),
                                  std::back_inserter(differing));
    EXPECT_TRUE(differing.empty()) << differing.size() << " faces are not in both meshes";
  }
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) { return test::shape_test_name(info.param); }

INSTANTIATE_TEST_SUITE_P(Shapes, HbrBaseline, ::testing::ValuesIn(baseline_shapes()), param_name);

}  // namespace
}  // namespace subdiv
