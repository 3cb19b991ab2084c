// Refinement agrees with OpenSubdiv (Far::TopologyRefiner + PrimvarRefiner,
// double precision) on every OpenSubdiv regression shape of the shared
// collection (../shared/data/meshes/opensubdiv), for 1, 2 and 3 uniform
// levels: same vertex, face and edge-point counts, the same child faces, and
// positions (and a vertex channel carrying the positions) within 1e-12 of the
// bounding-box diagonal.
//
// The two libraries number child vertices differently (both list face, edge
// and vertex points, but in different orders and edges are numbered
// differently), so the comparison follows the correspondence level by level:
// our level-0 vertices and faces are theirs; a child of our parent face f is
// the child of their face map(f), a child of our parent edge (a, b) the child
// of their edge FindEdge(map(a), map(b)), a child of our parent vertex v the
// child of their vertex map(v). Child faces are matched by their vertices.
//
// OpenSubdiv's regression harness reads `t interpolateboundary` 0/1/2 as
// VTX_BOUNDARY_NONE / EDGE_AND_CORNER / EDGE_ONLY and uses Sdc::Options'
// default (NONE) when the tag is absent; NONE refines vertex positions as
// EDGE_ONLY does, which is what we refine with in those cases.
//
// `t creasemethod` selects OpenSubdiv's creasing method (uniform, or Chaikin:
// catmark_chaikin1) for both libraries.
//
// Skipped shapes (the test says why): hierarchical edits (not implemented by
// subdiv), smooth-triangle Catmull-Clark (likewise), and meshes refine()
// rejects (degenerate faces). Non-manifold meshes are refined with
// allow_non_manifold, as OpenSubdiv refines them natively. Genuine
// disagreements are listed, with what differs, in kKnownDifferences.
//
// OpenSubdiv stores sharpness as float; the tags are rounded to float before
// both libraries see them, so that both refine the same values. (Its Chaikin
// child sharpness is computed in float too, subdiv's in double: the same on
// catmark_chaikin1, whose sharpnesses stay dyadic fractions with at most
// three semi-sharp edges at a vertex, so that every average is exact.)

#include <gtest/gtest.h>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/validation.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"
#include "support/opensubdiv_shapes.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;
namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

constexpr int kLevels = 3;
constexpr double kRelativeTolerance = 1e-12;  // of the level-0 bounding-box diagonal

// Genuine disagreements, kept under test: from `level` on, the shape's
// refinements differ; the levels before it are compared in full. The test
// fails if the difference disappears, so that this list stays true.
struct KnownDifference {
  std::string_view shape;
  int level;
  std::string_view why;
};
constexpr KnownDifference kKnownDifferences[] = {
    // Three "pillows": two triangles sharing all three vertices (valence-2
    // interior vertices). The corner children of such a pair again share all
    // three vertices; OpenSubdiv keeps the two child edges that lie inside
    // the two parent faces as distinct edges between the same two vertices,
    // each with two faces, smooth, each with its own edge point (68 edges at
    // level 1). subdiv derives edges from vertex pairs, so it merges each
    // such pair into one edge with four faces, non-manifold hence sharp (59
    // edges). Level 1 agrees; from level 2 on the counts differ (vertices:
    // 102 vs 93 at level 2, 358 vs 295 at level 3) and so do positions near
    // the pillows (at level 2: 8 vertex points by up to 0.031 and 9 edge
    // points by up to 0.054, bounding-box diagonal 3.9).
    {"loop_val2_interior", 2,
     "OpenSubdiv keeps coincident child edges of a two-triangle pillow distinct; subdiv merges them "
     "into one non-manifold edge"},
};

const KnownDifference* known_difference(const std::string& shape) {
  for (const KnownDifference& k : kKnownDifferences)
    if (k.shape == shape) return &k;
  return nullptr;
}

fs::path shape_dir() { return test::opensubdiv_shape_dir(); }
using test::harness_boundary;
using test::rejection;
using test::unsupported_feature;

// The scheme a regression shape's file name prefix names.
struct SchemePair {
  const Scheme* ours = nullptr;
  Sdc::SchemeType theirs = Sdc::SCHEME_CATMARK;
};

SchemePair scheme_of(const std::string& shape) {
  if (shape.starts_with("catmark_")) return {find_scheme("catmull-clark"), Sdc::SCHEME_CATMARK};
  if (shape.starts_with("loop_")) return {find_scheme("loop"), Sdc::SCHEME_LOOP};
  if (shape.starts_with("bilinear_")) return {find_scheme("bilinear"), Sdc::SCHEME_BILINEAR};
  return {};
}

Sdc::Options::VtxBoundaryInterpolation their_boundary(const Tags& tags) {
  if (!tags.boundary_interpolation_set) return Sdc::Options::VTX_BOUNDARY_NONE;
  switch (tags.boundary_interpolation) {
    case BoundaryInterpolation::none: return Sdc::Options::VTX_BOUNDARY_NONE;
    case BoundaryInterpolation::edge_only: return Sdc::Options::VTX_BOUNDARY_EDGE_ONLY;
    case BoundaryInterpolation::edge_and_corner: return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
  }
  return Sdc::Options::VTX_BOUNDARY_NONE;
}

// OpenSubdiv stores sharpness as float; give both libraries the same values.
void round_sharpness_to_float(Tags& tags) {
  for (CreaseTag& c : tags.creases) c.sharpness = static_cast<double>(static_cast<float>(c.sharpness));
  for (CornerTag& c : tags.corners) c.sharpness = static_cast<double>(static_cast<float>(c.sharpness));
}

// PrimvarRefiner's vertex interface, in double precision.
struct OsdVertex {
  double x = 0.0, y = 0.0, z = 0.0;
  void Clear() { x = y = z = 0.0; }
  void AddWithWeight(const OsdVertex& src, double w) {
    x += w * src.x;
    y += w * src.y;
    z += w * src.z;
  }
};

std::unique_ptr<Far::TopologyRefiner> make_refiner(const PolygonMesh& mesh, Sdc::SchemeType scheme) {
  std::vector<int> verts_per_face(static_cast<std::size_t>(mesh.face_count()));
  for (Index f = 0; f < mesh.face_count(); ++f) verts_per_face[static_cast<std::size_t>(f)] = mesh.face_size(f);
  const std::vector<Far::Index> face_vertices(mesh.face_indices.begin(), mesh.face_indices.end());
  std::vector<Far::Index> crease_pairs;
  std::vector<float> crease_weights;
  for (const CreaseTag& c : mesh.tags.creases) {
    crease_pairs.push_back(c.v0);
    crease_pairs.push_back(c.v1);
    crease_weights.push_back(static_cast<float>(c.sharpness));
  }
  std::vector<Far::Index> corner_vertices;
  std::vector<float> corner_weights;
  for (const CornerTag& c : mesh.tags.corners) {
    corner_vertices.push_back(c.vertex);
    corner_weights.push_back(static_cast<float>(c.sharpness));
  }
  const std::vector<Far::Index> holes(mesh.tags.holes.begin(), mesh.tags.holes.end());

  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.vertex_count();
  desc.numFaces = mesh.face_count();
  desc.numVertsPerFace = verts_per_face.data();
  desc.vertIndicesPerFace = face_vertices.data();
  desc.numCreases = static_cast<int>(crease_weights.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = crease_weights.data();
  desc.numCorners = static_cast<int>(corner_weights.size());
  desc.cornerVertexIndices = corner_vertices.data();
  desc.cornerWeights = corner_weights.data();
  desc.numHoles = static_cast<int>(holes.size());
  desc.holeIndices = holes.data();

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(their_boundary(mesh.tags));
  options.SetCreasingMethod(mesh.tags.crease_method == CreaseMethod::chaikin ? Sdc::Options::CREASE_CHAIKIN
                                                                            : Sdc::Options::CREASE_UNIFORM);
  options.SetTriangleSubdivision(mesh.tags.triangle_subdivision == TriangleSubdivision::smooth
                                     ? Sdc::Options::TRI_SUB_SMOOTH
                                     : Sdc::Options::TRI_SUB_CATMARK);
  std::unique_ptr<Far::TopologyRefiner> refiner(Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
      desc, Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(scheme, options)));
  if (!refiner) return refiner;
  Far::TopologyRefiner::UniformOptions uniform(kLevels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  return refiner;
}

// Positions of every level, level by level through PrimvarRefiner.
std::vector<std::vector<OsdVertex>> their_positions(const Far::TopologyRefiner& refiner, const PolygonMesh& mesh) {
  std::vector<std::vector<OsdVertex>> levels(static_cast<std::size_t>(refiner.GetNumLevels()));
  for (std::size_t l = 0; l < levels.size(); ++l)
    levels[l].resize(static_cast<std::size_t>(refiner.GetLevel(static_cast<int>(l)).GetNumVertices()));
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    levels[0][v] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
  const Far::PrimvarRefinerReal<double> primvar(refiner);
  for (std::size_t l = 1; l < levels.size(); ++l) {
    const OsdVertex* src = levels[l - 1].data();
    OsdVertex* dst = levels[l].data();
    primvar.Interpolate(static_cast<int>(l), src, dst);
  }
  return levels;
}

double bbox_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0.0;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  return norm(hi - lo);
}

// Where a child vertex of ours comes from, for messages.
std::string describe_child(const SplitMap& map, Index i) {
  if (i < map.edge_points) return "face point of parent face " + std::to_string(i - map.face_points);
  if (i < map.vertex_points) return "edge point of parent edge " + std::to_string(i - map.edge_points);
  return "vertex point of parent vertex " + std::to_string(i - map.vertex_points);
}

bool same_cycle(std::span<const Index> a, Far::ConstIndexArray b) {
  const int n = static_cast<int>(a.size());
  if (b.size() != n) return false;
  for (int r = 0; r < n; ++r) {
    bool all = true;
    for (int k = 0; k < n && all; ++k) all = a[static_cast<std::size_t>(k)] == b[(k + r) % n];
    if (all) return true;
  }
  return false;
}

// OpenSubdiv's smooth triangle rule (TRI_SUB_SMOOTH) has no regression shape
// of its own: the shape with triangles next to quads, its tag switched to it.
constexpr const char* kSmoothTrianglesShape = "catmark_smoothtris0";
constexpr const char* kSmoothTrianglesVariant = "catmark_smoothtris0_tri_sub_smooth";

std::vector<std::string> shape_names() {
  std::vector<std::string> names;
  std::error_code ec;
  if (fs::is_directory(shape_dir(), ec))
    for (const auto& entry : fs::directory_iterator(shape_dir(), ec))
      if (entry.path().extension() == ".obj") names.push_back(entry.path().stem().string());
  if (std::find(names.begin(), names.end(), kSmoothTrianglesShape) != names.end())
    names.push_back(kSmoothTrianglesVariant);
  std::sort(names.begin(), names.end());
  if (names.empty()) names.push_back("collection_absent");  // the test skips, saying so
  return names;
}

class OpenSubdivAgreement : public ::testing::TestWithParam<std::string> {};

TEST_P(OpenSubdivAgreement, RefinesLikeOpenSubdiv) {
  const std::string shape = GetParam();
  const bool smooth_triangles = shape == kSmoothTrianglesVariant;
  const fs::path path = shape_dir() / ((smooth_triangles ? std::string(kSmoothTrianglesShape) : shape) + ".obj");
  if (!fs::exists(path))
    GTEST_SKIP() << "OpenSubdiv regression shapes not found at " << shape_dir()
                 << " (the shared collection sits beside the repository)";
  const SchemePair scheme = scheme_of(shape);
  ASSERT_NE(scheme.ours, nullptr) << "no scheme for " << shape << " (expected catmark_, loop_ or bilinear_)";

  PolygonMesh mesh = read_mesh(path).mesh;
  if (smooth_triangles) mesh.tags.triangle_subdivision = TriangleSubdivision::smooth;
  if (const std::string why = unsupported_feature(mesh); !why.empty())
    GTEST_SKIP() << shape << ": not supported by subdiv yet: " << why;
  round_sharpness_to_float(mesh.tags);

  RefineOptions options;
  options.levels = 1;
  options.boundary = harness_boundary(mesh.tags);
  options.allow_non_manifold = true;
  if (const std::string why = rejection(mesh, *scheme.ours, options); !why.empty())
    GTEST_SKIP() << shape << ": " << why;

  const auto refiner = make_refiner(mesh, scheme.theirs);
  ASSERT_TRUE(refiner) << "OpenSubdiv rejected " << shape;
  ASSERT_EQ(refiner->GetNumLevels(), kLevels + 1);

  // A vertex channel equal to the positions: it must follow the same masks.
  {
    VertexChannel channel{"P", 3, {}};
    for (const Vec3& p : mesh.positions) channel.values.insert(channel.values.end(), {p.x, p.y, p.z});
    mesh.vertex_channels.push_back(std::move(channel));
  }
  const auto theirs = their_positions(*refiner, mesh);
  const double tolerance = kRelativeTolerance * bbox_diagonal(mesh.positions);

  // ours -> theirs, vertices and faces of the current level.
  std::vector<Far::Index> vertex_map(static_cast<std::size_t>(mesh.vertex_count()));
  std::vector<Far::Index> face_map(static_cast<std::size_t>(mesh.face_count()));
  for (std::size_t i = 0; i < vertex_map.size(); ++i) vertex_map[i] = static_cast<Far::Index>(i);
  for (std::size_t i = 0; i < face_map.size(); ++i) face_map[i] = static_cast<Far::Index>(i);

  const KnownDifference* known = known_difference(shape);
  PolygonMesh parent = std::move(mesh);
  for (int level = 1; level <= kLevels; ++level) {
    SCOPED_TRACE(shape + ", level " + std::to_string(level));
    const Far::TopologyLevel& their_parent = refiner->GetLevel(level - 1);
    const Far::TopologyLevel& their_child = refiner->GetLevel(level);

    PolygonMesh child;
    ASSERT_NO_THROW(child = refine(parent, *scheme.ours, options));
    if (known && level >= known->level) {
      if (child.vertex_count() != their_child.GetNumVertices() || child.face_count() != their_child.GetNumFaces() ||
          MeshTopology(parent).edge_count() != their_parent.GetNumEdges()) {
        std::cout << "[   NOTE   ] " << shape << ": known difference from level " << known->level
                  << " (compared levels 1-" << level - 1 << "): " << known->why << "\n";
        return;
      }
      ADD_FAILURE() << "known difference no longer observed at level " << level
                    << ": remove it from kKnownDifferences (" << known->why << ")";
    }
    ASSERT_EQ(child.vertex_count(), their_child.GetNumVertices());
    ASSERT_EQ(child.face_count(), their_child.GetNumFaces());

    // Child vertex ranges of our split (split.h).
    const MeshTopology topology(parent);
    SplitMap map;
    map.rule = scheme.ours->split;
    map.face_points = 0;
    map.edge_points = map.rule == SplitRule::quad ? parent.face_count() : 0;
    map.vertex_points = map.edge_points + topology.edge_count();
    map.child_vertex_count = map.vertex_points + parent.vertex_count();
    ASSERT_EQ(map.child_vertex_count, child.vertex_count());
    ASSERT_EQ(topology.edge_count(), their_parent.GetNumEdges());

    std::vector<Far::Index> child_vertex_map(static_cast<std::size_t>(child.vertex_count()), -1);
    if (map.rule == SplitRule::quad)
      for (Index f = 0; f < parent.face_count(); ++f)
        child_vertex_map[static_cast<std::size_t>(map.face_point(f))] =
            their_parent.GetFaceChildVertex(face_map[static_cast<std::size_t>(f)]);
    for (Index e = 0; e < topology.edge_count(); ++e) {
      const auto [a, b] = topology.edge_vertices(e);
      const Far::Index te =
          their_parent.FindEdge(vertex_map[static_cast<std::size_t>(a)], vertex_map[static_cast<std::size_t>(b)]);
      ASSERT_NE(te, Far::INDEX_INVALID) << "OpenSubdiv has no edge for our edge " << e << " (" << a << ", " << b << ")";
      child_vertex_map[static_cast<std::size_t>(map.edge_point(e))] = their_parent.GetEdgeChildVertex(te);
    }
    for (Index v = 0; v < parent.vertex_count(); ++v)
      child_vertex_map[static_cast<std::size_t>(map.vertex_point(v))] =
          their_parent.GetVertexChildVertex(vertex_map[static_cast<std::size_t>(v)]);

    // The correspondence is one to one.
    {
      std::vector<char> hit(child_vertex_map.size(), 0);
      for (std::size_t i = 0; i < child_vertex_map.size(); ++i) {
        const Far::Index t = child_vertex_map[i];
        ASSERT_TRUE(t >= 0 && static_cast<std::size_t>(t) < hit.size() && !hit[static_cast<std::size_t>(t)])
            << "child vertex " << i << " (" << describe_child(map, static_cast<Index>(i))
            << ") maps to OpenSubdiv vertex " << t << ", out of range or already taken";
        hit[static_cast<std::size_t>(t)] = 1;
      }
    }

    // Child faces: the same vertices in the same cyclic order.
    std::vector<Far::Index> child_face_map(static_cast<std::size_t>(child.face_count()), -1);
    {
      std::vector<char> taken(child_face_map.size(), 0);
      std::vector<Index> mapped;
      for (Index f = 0; f < child.face_count(); ++f) {
        mapped.clear();
        for (const Index v : child.face(f)) mapped.push_back(child_vertex_map[static_cast<std::size_t>(v)]);
        Far::Index match = -1;
        for (const Far::Index tf : their_child.GetVertexFaces(mapped.front()))
          if (!taken[static_cast<std::size_t>(tf)] && same_cycle(mapped, their_child.GetFaceVertices(tf))) {
            match = tf;
            break;
          }
        ASSERT_NE(match, -1) << "our child face " << f << " has no OpenSubdiv counterpart";
        taken[static_cast<std::size_t>(match)] = 1;
        child_face_map[static_cast<std::size_t>(f)] = match;
      }
    }

    // Positions and the channel.
    const std::vector<OsdVertex>& expected = theirs[static_cast<std::size_t>(level)];
    ASSERT_EQ(child.vertex_channels.size(), 1u);
    const std::vector<double>& channel = child.vertex_channels[0].values;
    ASSERT_EQ(channel.size(), 3 * child.positions.size());
    double worst = 0.0, worst_channel = 0.0;
    Index worst_vertex = 0;
    std::size_t channel_mismatches = 0;
    for (Index i = 0; i < child.vertex_count(); ++i) {
      const auto ii = static_cast<std::size_t>(i);
      const OsdVertex& t = expected[static_cast<std::size_t>(child_vertex_map[ii])];
      const Vec3 want{t.x, t.y, t.z};
      const double d = norm(child.positions[ii] - want);
      if (!(d <= worst)) {  // also catches NaN
        worst = d;
        worst_vertex = i;
      }
      const Vec3 c{channel[3 * ii], channel[3 * ii + 1], channel[3 * ii + 2]};
      worst_channel = std::max(worst_channel, norm(c - want));
      if (!(c == child.positions[ii])) ++channel_mismatches;
    }
    EXPECT_LE(worst, tolerance) << "largest position difference at our vertex " << worst_vertex << " ("
                                << describe_child(map, worst_vertex) << "), OpenSubdiv vertex "
                                << child_vertex_map[static_cast<std::size_t>(worst_vertex)] << " (tolerance "
                                << tolerance << ")";
    EXPECT_LE(worst_channel, tolerance) << "vertex channel differs from OpenSubdiv";
    EXPECT_EQ(channel_mismatches, 0u) << "vertex channel not refined exactly as the positions";

    vertex_map = std::move(child_vertex_map);
    face_map = std::move(child_face_map);
    parent = std::move(child);
  }
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) { return test::shape_test_name(info.param); }

INSTANTIATE_TEST_SUITE_P(Shapes, OpenSubdivAgreement, ::testing::ValuesIn(shape_names()), param_name);

}  // namespace
}  // namespace subdiv
