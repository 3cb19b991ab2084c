// The limit evaluator against independent routes: at the dyadic parameters
// of a ptex face, which are vertices of the uniform refinement, it must equal
// those vertices' limit positions and normals from the closed-form limit
// masks (limit_positions); its derivatives must be the finite differences of
// its positions; shared edges must give equal points and normals from both
// sides; regular faces must be the uniform bicubic B-spline written out here.

#include "subdiv/eval/limit_evaluator.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "refine/grid_test_support.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/rules/limit_mask.h"
#include "support/refine_options.h"
#include "support/scheme_by_name.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

using grid_test::diagonal;

using test::scheme;

// A closed double pyramid over an n-gon: apexes of valence n, the equator's
// vertices of valence 4; jittered so that no symmetry hides an error.
PolygonMesh bipyramid(int n, unsigned seed) { return test::jittered(test::bipyramid(n), seed); }

// The bipyramid's triangles split into quads once (bilinear): apexes of
// valence n, the other vertices of valence 3, 4 and 6, all faces quads.
PolygonMesh quad_bipyramid(int n, unsigned seed) {
  return test::jittered(refine(bipyramid(n, seed), scheme("bilinear"), test::levels(1)), seed + 1);
}

// The ptex parameter of each vertex of a level of refinement, found by
// refining a face-varying channel that holds each ptex face's corner
// parameters (the splits make face-varying values linear within faces,
// which is how the ptex parameter runs), and the ptex face each face of
// the level lies in.
struct LevelParameters {
  PolygonMesh mesh;               // the level, with channel "ptex"
  std::vector<Index> face_ptex;   // per face of the level
};

LevelParameters ptex_parameters(const PolygonMesh& control, const Scheme& s, const LimitEvaluator& evaluator,
                                int levels) {
  const bool triangles = s.split == SplitRule::triangle;
  // Catmull-Clark's n-gons have their ptex faces one level down: start there.
  PolygonMesh start = control;
  std::vector<Index> face_ptex;
  FaceVaryingChannel ptex{"ptex", 2, {}, {}};
  const auto add_corner = [&](double u, double v) {
    ptex.values.push_back(u);
    ptex.values.push_back(v);
    ptex.indices.push_back(static_cast<Index>(ptex.indices.size()));
  };
  int levels_left = levels;
  if (!triangles) {
    start = refine(control, s, test::levels(1));
    const MeshTopology coarse(control);
    for (Index c = 0; c < coarse.corner_count(); ++c) {  // child face c sits at parent corner c
      const Index f = coarse.corner_face(c), k = c - coarse.face_first_corner(f);
      if (coarse.face_size(f) == 4) {
        const std::array<std::array<double, 2>, 4> p = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
        const auto& a = p[static_cast<std::size_t>(k)];
        const auto& next = p[static_cast<std::size_t>((k + 1) % 4)];
        const auto& prev = p[static_cast<std::size_t>((k + 3) % 4)];
        add_corner(a[0], a[1]);
        add_corner(0.5 * (a[0] + next[0]), 0.5 * (a[1] + next[1]));
        add_corner(0.5, 0.5);
        add_corner(0.5 * (a[0] + prev[0]), 0.5 * (a[1] + prev[1]));
        face_ptex.push_back(evaluator.ptex_face_of(f));
      } else {
        add_corner(0, 0);
        add_corner(1, 0);
        add_corner(1, 1);
        add_corner(0, 1);
        face_ptex.push_back(evaluator.ptex_face_of(f) + k);
      }
    }
    --levels_left;
  } else {
    for (Index f = 0; f < control.face_count(); ++f) {
      add_corner(0, 0);
      add_corner(1, 0);
      add_corner(0, 1);
      face_ptex.push_back(evaluator.ptex_face_of(f));
    }
  }
  start.face_varying_channels = {ptex};
  const Hierarchy h = refine_hierarchy(start, s, test::levels(levels_left));
  for (std::size_t l = 1; l < h.levels.size(); ++l) {
    const MeshTopology parent(h.levels[l - 1].mesh);
    std::vector<Index> child_ptex;
    const Index child_faces = h.levels[l].mesh.face_count();
    for (Index g = 0; g < child_faces; ++g) {
      const Index parent_face = triangles ? g / 4 : parent.corner_face(g);
      child_ptex.push_back(face_ptex[static_cast<std::size_t>(parent_face)]);
    }
    face_ptex = std::move(child_ptex);
  }
  return {h.finest().mesh, face_ptex};
}

// At every vertex of `levels` refinements, the evaluator equals the
// vertex's closed-form limit position (to 1e-12 of the mesh's size) and
// normal (to 1e-9; not on interior creases, where each side has its own).
void expect_equals_limits_at_dyadic_points(const PolygonMesh& control, const char* name, int levels) {
  SCOPED_TRACE(std::string(name) + " at level " + std::to_string(levels));
  const Scheme& s = scheme(name);
  const LimitEvaluator evaluator(control, s);
  const LevelParameters level = ptex_parameters(control, s, evaluator, levels);
  const LimitResult limits = limit_positions(level.mesh, s);
  ASSERT_EQ(limits.approximated, 0);
  const double size = diagonal(control);
  const FaceVaryingChannel& ptex = level.mesh.face_varying_channels.at(0);
  const MeshTopology topology(level.mesh);
  const LevelCreasing creasing =
      compute_creasing(level.mesh, topology, boundary_of(level.mesh, {}), crease_method_of(level.mesh, {}));
  int checked = 0;
  for (Index f = 0; f < level.mesh.face_count(); ++f) {
    const auto corners = level.mesh.face(f);
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const std::size_t corner = static_cast<std::size_t>(level.mesh.face_offsets[static_cast<std::size_t>(f)]) + k;
      const Index value = ptex.indices[corner];
      const double u = ptex.values[2 * static_cast<std::size_t>(value)];
      const double v = ptex.values[2 * static_cast<std::size_t>(value) + 1];
      const LimitPoint p = evaluator.evaluate(level.face_ptex[static_cast<std::size_t>(f)], u, v);
      const auto w = static_cast<std::size_t>(corners[k]);
      ASSERT_LE(norm(p.position - limits.positions[w]), 1e-12 * size)
          << "ptex face " << level.face_ptex[static_cast<std::size_t>(f)] << " at (" << u << ", " << v << ")";
      const bool on_crease =
          topology.vertex_kind(corners[k]) == VertexKind::interior &&
          (creasing.vertex_rule[w] == VertexRule::crease || creasing.vertex_rule[w] == VertexRule::corner);
      if (!on_crease) {
        ASSERT_LE(norm(p.normal - limits.normals[w]), 1e-9)
            << "ptex face " << level.face_ptex[static_cast<std::size_t>(f)] << " at (" << u << ", " << v << ")";
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(LimitEvaluator, CatmullClarkEqualsTheLimitsAtDyadicPointsForValences3To12) {
  expect_equals_limits_at_dyadic_points(test::jittered(test::cube(), 3), "catmull-clark", 3);
  for (int n = 3; n <= 12; ++n) expect_equals_limits_at_dyadic_points(quad_bipyramid(n, 10u + n), "catmull-clark", 3);
}

// The cube without its top face: its rim's vertices lie on the boundary
// with two faces each, its bottom corners are extraordinary (valence 3).
PolygonMesh open_cube() {
  PolygonMesh mesh;
  const PolygonMesh c = test::cube();
  mesh.positions = c.positions;
  for (Index f = 0; f < c.face_count(); ++f)
    if (f != 1) mesh.add_face(c.face(f));  // face 1 is the top, z = 1
  return mesh;
}

// A fan of three quads around boundary vertex 0 (a boundary sector of
// three faces).
PolygonMesh fan_of_three() {
  PolygonMesh fan;
  fan.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {0, -1, 0}};
  fan.add_face({0, 1, 2, 3});
  fan.add_face({0, 3, 4, 5});
  fan.add_face({0, 5, 6, 7});
  return fan;
}

// The fan split once, so that it has interior faces too.
PolygonMesh boundary_fan() { return refine(fan_of_three(), scheme("bilinear"), test::levels(1)); }

TEST(LimitEvaluator, ExtraordinaryBoundaryVerticesAndCornersEqualTheLimitsAtDyadicPoints) {
  // Boundary vertices of three faces.
  expect_equals_limits_at_dyadic_points(test::jittered(boundary_fan(), 11), "catmull-clark", 4);
  // Boundary vertices of one face with the crease rule (edge_only).
  PolygonMesh grid = test::jittered(test::quad_grid(3, 3), 12);
  grid.tags.boundary_interpolation = BoundaryInterpolation::edge_only;
  grid.tags.boundary_interpolation_set = true;
  expect_equals_limits_at_dyadic_points(grid, "catmull-clark", 4);
  // A concave corner of three faces, tagged.
  expect_equals_limits_at_dyadic_points(read_mesh(test::bundled_path("l_shape.obj")).mesh, "catmull-clark", 4);
}

// The creased cube's split with other creases: the edges whose two ends
// pass `on`.
template <class On>
PolygonMesh split_cube_with_creases(On on) {
  PolygonMesh mesh = test::creased_cube();
  mesh.tags.creases.clear();
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto v = mesh.face(f);
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Index a = v[k], b = v[(k + 1) % v.size()];
      if (a < b && on(mesh.positions[static_cast<std::size_t>(a)], mesh.positions[static_cast<std::size_t>(b)]))
        mesh.tags.creases.push_back({a, b, kInfiniteSharpness});
    }
  }
  return mesh;
}

// Creases inside the mesh that bend or meet: the bottom square's rim (bent
// at the cube's corners, vertices of three edges: sectors of one and two
// faces), and the equator with the upper half of a meridian ending on it
// (three sharp edges: corner sectors).
TEST(LimitEvaluator, CreaseSectorsEqualTheLimitsAtDyadicPoints) {
  const PolygonMesh rim = split_cube_with_creases([](Vec3 p, Vec3 q) {
    return p.z == 0 && q.z == 0 && ((p.x == q.x && (p.x == 0 || p.x == 1)) || (p.y == q.y && (p.y == 0 || p.y == 1)));
  });
  ASSERT_EQ(rim.tags.creases.size(), 8u);
  expect_equals_limits_at_dyadic_points(test::jittered(rim, 21), "catmull-clark", 4);
  const PolygonMesh tee = split_cube_with_creases([](Vec3 p, Vec3 q) {
    return (p.z == 0.5 && q.z == 0.5) || (p.x == 0.5 && q.x == 0.5 && p.z >= 0.5 && q.z >= 0.5);
  });
  expect_equals_limits_at_dyadic_points(test::jittered(tee, 22), "catmull-clark", 4);
}

// At every corner of every ptex face the normal is the limit of the
// normals inside the face: at an extraordinary vertex on a crease, its own
// side's (the sector's tangent masks), not the other side's, which differs
// by about a right angle here. Normals converge slowly at the rim's
// corners (a sector of one face under the crease rule: 0.0124 off at 1e-7
// from the corner, 0.0075 at 1e-12, measured), hence 2e-2 at 1e-12. (Not at
// the L-shape's concave corner: there the standard corner rule is not
// tangent plane continuous; du and dv grow without bound toward it.)
TEST(LimitEvaluator, NormalsAtCornersAreTheLimitsFromInsideTheFace) {
  const PolygonMesh rim = test::jittered(split_cube_with_creases([](Vec3 p, Vec3 q) {
    return p.z == 0 && q.z == 0 && ((p.x == q.x && (p.x == 0 || p.x == 1)) || (p.y == q.y && (p.y == 0 || p.y == 1)));
  }), 23);
  const std::vector<std::pair<std::string, PolygonMesh>> meshes = {{"rim", rim},
                                                                    {"fan", test::jittered(boundary_fan(), 24)}};
  for (const auto& [name, mesh] : meshes) {
    SCOPED_TRACE(name);
    const LimitEvaluator evaluator(mesh, scheme("catmull-clark"));
    for (Index f = 0; f < evaluator.ptex_face_count(); ++f) {
      for (const auto& [u, v, du, dv] : std::vector<std::array<double, 4>>{
               {0, 0, 1, 1}, {1, 0, -1, 1}, {1, 1, -1, -1}, {0, 1, 1, -1}}) {
        const Vec3 at_corner = evaluator.evaluate(f, u, v).normal;
        const Vec3 inside = evaluator.evaluate(f, u + 1e-12 * du, v + 1e-12 * dv).normal;
        EXPECT_LT(norm(at_corner - inside), 2e-2) << "ptex face " << f << " corner (" << u << ", " << v << ")";
      }
    }
  }
}

// Each quad split into two triangles along the diagonal from its first
// corner.
PolygonMesh triangulated(const PolygonMesh& quads) {
  PolygonMesh mesh;
  mesh.positions = quads.positions;
  mesh.tags = quads.tags;
  for (Index f = 0; f < quads.face_count(); ++f) {
    const auto v = quads.face(f);
    mesh.add_face({v[0], v[1], v[2]});
    mesh.add_face({v[0], v[2], v[3]});
  }
  return mesh;
}

// Loop at boundaries, creases and corners: regular boundary patches
// (parallelogram reflections) and sector models.
TEST(LimitEvaluator, LoopBoundariesCreasesAndCornersEqualTheLimitsAtDyadicPoints) {
  expect_equals_limits_at_dyadic_points(test::jittered(test::box_spline_grid(4, 3), 41), "loop", 4);
  expect_equals_limits_at_dyadic_points(test::jittered(test::triangle_grid(3, 3), 42), "loop", 4);
  expect_equals_limits_at_dyadic_points(test::jittered(triangulated(test::creased_cube()), 43), "loop", 4);
  // A crease around one face of the tetrahedron: sectors of one and two faces.
  PolygonMesh tetrahedron = test::tetrahedron();
  const auto f = tetrahedron.face(0);
  tetrahedron.tags.creases = {{f[0], f[1], kInfiniteSharpness}, {f[1], f[2], kInfiniteSharpness},
                              {f[2], f[0], kInfiniteSharpness}};
  expect_equals_limits_at_dyadic_points(tetrahedron, "loop", 4);
}

// The split cube with a crease along part of its equator, ending at the
// left and right faces' centres (vertices of four edges): two darts.
PolygonMesh cube_with_darts() {
  return split_cube_with_creases([](Vec3 p, Vec3 q) { return p.z == 0.5 && q.z == 0.5 && p.y < 1 && q.y < 1; });
}

// A corner of a control face at a dart: the face, the ptex parameter of
// the corner, and the dart vertex.
struct DartCorner {
  Index face;
  std::array<double, 2> at;
  std::size_t vertex;
};

std::vector<DartCorner> dart_corners(const PolygonMesh& control) {
  const MeshTopology t(control);
  const LevelCreasing c = compute_creasing(control, t, boundary_of(control, {}), crease_method_of(control, {}));
  constexpr std::array<std::array<double, 2>, 4> kQuadCorner = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  constexpr std::array<std::array<double, 2>, 3> kTriangleCorner = {{{0, 0}, {1, 0}, {0, 1}}};
  std::vector<DartCorner> corners;
  for (Index f = 0; f < control.face_count(); ++f) {
    const auto face = control.face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      const auto w = static_cast<std::size_t>(face[k]);
      if (c.vertex_rule[w] == VertexRule::dart)
        corners.push_back({f, face.size() == 4 ? kQuadCorner[k] : kTriangleCorner[k], w});
    }
  }
  return corners;
}

// Darts: a crease along part of the equator, ending at the left and right
// faces' centres (vertices of four edges). The limit at a dart is its own
// matrix's (limit_positions takes its eigenvectors, the evaluator A^256 of
// the face ring's matrix): both equal there, normals included.
TEST(LimitEvaluator, DartsEqualTheLimitsAtDyadicPoints) {
  const PolygonMesh darts = cube_with_darts();
  ASSERT_EQ(darts.tags.creases.size(), 4u);
  for (const char* name : {"catmull-clark", "loop"}) {
    const bool loop = std::string(name) == "loop";
    expect_equals_limits_at_dyadic_points(test::jittered(loop ? triangulated(darts) : darts, 51), name, 4);
  }
}

// Close to a dart, inside each face around it, the evaluator's normal goes
// to the normal of the dart's tangent masks (its matrix's subdominant left
// eigenvectors), from every face: the dart is tangent plane continuous.
TEST(LimitEvaluator, NearDartsNormalsApproachTheDartMasks) {
  const PolygonMesh darts = test::jittered(cube_with_darts(), 57);
  for (const char* name : {"catmull-clark", "loop"}) {
    SCOPED_TRACE(name);
    const Scheme& s = scheme(name);
    const PolygonMesh control = std::string(name) == "loop" ? triangulated(darts) : darts;
    const LimitEvaluator evaluator(control, s);
    const LimitResult limits = limit_positions(control, s);
    int checked = 0;
    for (const DartCorner& corner : dart_corners(control)) {
      const auto [f, at, w] = corner;
      // Toward a point inside the face, 2^-level of the way from the dart.
      const bool quad = control.face(f).size() == 4;
      const double inside[2] = {quad ? 0.4 : 0.3, quad ? 0.3 : 0.2};
      for (const int level : {30, 100}) {
        const double h = std::ldexp(1.0, -level);
        const double u = at[0] + h * (inside[0] - at[0]), v = at[1] + h * (inside[1] - at[1]);
        const LimitPoint p = evaluator.evaluate(evaluator.ptex_face_of(f), u, v);
        if (level == 100) {
          EXPECT_LT(norm(p.position - limits.positions[w]), 1e-12 * diagonal(control));
        }
        EXPECT_LT(norm(p.normal - limits.normals[w]), level == 30 ? 1e-3 : 1e-9)
            << "face " << f << " at (" << at[0] << ", " << at[1] << "), 2^-" << level;
        ++checked;
      }
    }
    EXPECT_GT(checked, 8);
  }
}

// The smooth limit masks (OpenSubdiv's at darts) applied at a dart vertex
// of `mesh`: its limit had its sharp edge been smooth.
Vec3 smooth_masks_at(const PolygonMesh& mesh, const MeshTopology& t, const Scheme& s, Index v) {
  VertexNeighbourhood n;
  n.edges = static_cast<int>(t.vertex_edges(v).size());
  n.faces = static_cast<int>(t.vertex_corners(v).size());
  n.rule = VertexRule::smooth;
  LimitMasks masks;
  if (!s.limit_masks(n, masks)) throw std::runtime_error("no smooth masks");
  Vec3 sum = masks.position.vertex * mesh.positions[static_cast<std::size_t>(v)];
  for (std::size_t i = 0; i < masks.position.edges.size(); ++i)
    sum += masks.position.edges[i] * mesh.positions[static_cast<std::size_t>(t.other_vertex(t.vertex_edges(v)[i], v))];
  for (std::size_t j = 0; j < masks.position.faces.size(); ++j)
    sum +=
        masks.position.faces[j] *
        mesh.positions[static_cast<std::size_t>(t.corner_vertex(t.corner_next(t.corner_next(t.vertex_corners(v)[j]))))];
  return sum;
}

// An independent route to the limit at a dart: the smooth masks applied
// after L levels of refinement err less and less as L grows, and converge
// to the evaluator's value, which limit_positions() gives at every level.
TEST(LimitEvaluator, AtDartsDeeperRefinementConvergesToTheEvaluator) {
  const PolygonMesh darts = test::jittered(cube_with_darts(), 53);
  for (const char* name : {"catmull-clark", "loop"}) {
    SCOPED_TRACE(name);
    const Scheme& s = scheme(name);
    const PolygonMesh control = std::string(name) == "loop" ? triangulated(darts) : darts;
    const LimitEvaluator evaluator(control, s);
    // Every dart's limit, from the evaluator: the corners of the ptex faces
    // (the control faces) at dart vertices.
    std::vector<Vec3> exact;
    for (const DartCorner& corner : dart_corners(control))
      exact.push_back(evaluator.evaluate(evaluator.ptex_face_of(corner.face), corner.at[0], corner.at[1]).position);
    ASSERT_FALSE(exact.empty());
    const double size = diagonal(control);
    const auto nearest = [&](Vec3 p) {
      double d = std::numeric_limits<double>::infinity();
      for (const Vec3& e : exact) d = std::min(d, norm(p - e));
      return d;
    };
    std::vector<double> error;
    for (int levels = 0; levels <= 4; ++levels) {
      const PolygonMesh refined = refine(control, s, test::levels(levels));
      const MeshTopology rt(refined);
      const LevelCreasing rc = compute_creasing(refined, rt, boundary_of(refined, {}), crease_method_of(refined, {}));
      const LimitResult limits = limit_positions(refined, s);
      double worst = 0.0;
      int seen = 0;
      for (Index v = 0; v < rt.vertex_count(); ++v) {
        if (rc.vertex_rule[static_cast<std::size_t>(v)] != VertexRule::dart) continue;
        ++seen;
        EXPECT_EQ(limits.sources[static_cast<std::size_t>(v)], LimitSource::generic);
        EXPECT_LE(nearest(limits.positions[static_cast<std::size_t>(v)]), 1e-12 * size) << "level " << levels;
        worst = std::max(worst, nearest(smooth_masks_at(refined, rt, s, v)));
      }
      EXPECT_EQ(seen, 2);
      error.push_back(worst);
    }
    std::cout << "[ darts    ] " << name << ": smooth masks after 0..4 levels, distance from the dart limits:";
    for (const double e : error) std::cout << " " << e;
    std::cout << "\n";
    for (std::size_t l = 1; l < error.size(); ++l) EXPECT_LT(error[l], 0.7 * error[l - 1]) << "level " << l;
    EXPECT_GT(error.front(), 1e-4 * size);  // the smooth masks are not the dart's limit
    EXPECT_LT(error.back(), error.front() / 10);
  }
}

// Semi-sharp creases and corners: isolated until they have decayed.
TEST(LimitEvaluator, SemiSharpFeaturesEqualTheLimitsAtDyadicPoints) {
  for (const double sharpness : {0.5, 1.0, 2.5, 4.0}) {  // 4: the most isolated
    PolygonMesh mesh = test::jittered(test::creased_cube(), 31);
    for (CreaseTag& c : mesh.tags.creases) c.sharpness = sharpness;
    mesh.tags.corners = {CornerTag{0, sharpness, CornerType::unspecified, std::nullopt}};
    SCOPED_TRACE("sharpness " + std::to_string(sharpness));
    expect_equals_limits_at_dyadic_points(mesh, "catmull-clark", 5);
  }
  PolygonMesh chaikin = test::jittered(test::creased_cube(), 32);
  for (std::size_t i = 0; i < chaikin.tags.creases.size(); ++i) chaikin.tags.creases[i].sharpness = 0.5 + 0.25 * (i % 7);
  chaikin.tags.crease_method = CreaseMethod::chaikin;
  chaikin.tags.crease_method_set = true;
  expect_equals_limits_at_dyadic_points(chaikin, "catmull-clark", 5);
  PolygonMesh triangles = test::jittered(triangulated(test::creased_cube()), 33);
  for (CreaseTag& c : triangles.tags.creases) c.sharpness = 1.5;
  expect_equals_limits_at_dyadic_points(triangles, "loop", 4);
}

TEST(LimitEvaluator, BoundariesCreasesAndCornersEqualTheLimitsAtDyadicPoints) {
  // Boundary vertices of two faces, corners of one (the corner rule).
  expect_equals_limits_at_dyadic_points(test::jittered(test::quad_grid(4, 3), 5), "catmull-clark", 3);
  // Creases through vertices of four edges, and corners where they cross.
  expect_equals_limits_at_dyadic_points(test::jittered(test::creased_cube(), 7), "catmull-clark", 3);
  // A boundary next to extraordinary vertices.
  expect_equals_limits_at_dyadic_points(test::jittered(open_cube(), 9), "catmull-clark", 4);
}

// Down to 2^-6 of the cube's corners (valence 3): the powers of the
// subdivision matrix through its eigenbasis at n = 5.
TEST(LimitEvaluator, CloseToExtraordinaryVerticesTheLimitsStillAgree) {
  expect_equals_limits_at_dyadic_points(test::jittered(test::cube(), 3), "catmull-clark", 6);
  expect_equals_limits_at_dyadic_points(bipyramid(5, 6), "loop", 5);
}

TEST(LimitEvaluator, CatmullClarkNGonsAreAddressedByTheirSubFaces) {
  // Triangles and pentagons: each corner a ptex face of the first level.
  for (int n : {3, 5, 7}) expect_equals_limits_at_dyadic_points(bipyramid(n, 40u + n), "catmull-clark", 3);
}

TEST(LimitEvaluator, LoopEqualsTheLimitsAtDyadicPointsForValences3To12) {
  for (int n = 3; n <= 12; ++n) expect_equals_limits_at_dyadic_points(bipyramid(n, 70u + n), "loop", 3);
  // Every vertex of valence 3, each face touching three: isolation, and the
  // valence-3 patch's middle child one level further down.
  expect_equals_limits_at_dyadic_points(test::tetrahedron(), "loop", 4);
}

// loop-warren: Loop's rules but Warren's weight at extraordinary vertices
// (3 / (8 k), 3/16 at valence 3): its own models, its own closed forms, and
// a surface that differs from Loop's near extraordinary vertices.
TEST(LimitEvaluator, LoopWarrenEqualsItsLimitsAtDyadicPoints) {
  for (const int n : {3, 5, 8}) expect_equals_limits_at_dyadic_points(bipyramid(n, 90u + n), "loop-warren", 3);
  expect_equals_limits_at_dyadic_points(test::tetrahedron(), "loop-warren", 4);
  expect_equals_limits_at_dyadic_points(test::jittered(triangulated(test::creased_cube()), 91), "loop-warren", 3);
  const PolygonMesh mesh = bipyramid(5, 95);
  const LimitEvaluator warren(mesh, scheme("loop-warren")), loop(mesh, scheme("loop"));
  EXPECT_GT(norm(warren.evaluate(0, 0.1, 0.1).position - loop.evaluate(0, 0.1, 0.1).position), 1e-6);
}

TEST(LimitEvaluator, RegularTorusesNeedNoIsolation) {
  const LimitEvaluator quads(grid_test::torus(8), scheme("catmull-clark"));
  EXPECT_EQ(quads.isolation_levels(), 0);
  EXPECT_EQ(quads.patch_count(), 64u);
  const LimitEvaluator triangles(grid_test::triangulated_torus(8), scheme("loop"));
  EXPECT_EQ(triangles.isolation_levels(), 0);
  EXPECT_EQ(triangles.patch_count(), 128u);
  expect_equals_limits_at_dyadic_points(grid_test::torus(8), "catmull-clark", 3);
  expect_equals_limits_at_dyadic_points(grid_test::triangulated_torus(8), "loop", 3);
}

// The uniform cubic B-spline basis written out (not the library's table).
std::array<double, 4> cubic_bspline(double t) {
  const double s = 1.0 - t;
  return {s * s * s / 6.0, (3 * t * t * t - 6 * t * t + 4) / 6.0, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0,
          t * t * t / 6.0};
}

TEST(LimitEvaluator, RegularQuadsAreTheBicubicBSplineOfTheirControlPoints) {
  const int n = 8;
  const PolygonMesh torus = grid_test::torus(n);
  const LimitEvaluator evaluator(torus, scheme("catmull-clark"));
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto id = [](int i, int j) { return static_cast<std::size_t>(((j + n) % n) * n + (i + n) % n); };
  for (int trial = 0; trial < 200; ++trial) {
    const int i = trial % n, j = (trial / n) % n;
    const double u = unit(random), v = unit(random);
    const auto bu = cubic_bspline(u), bv = cubic_bspline(v);
    Vec3 expected;
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) expected += (bu[static_cast<std::size_t>(a)] * bv[static_cast<std::size_t>(b)]) *
                                              torus.positions[id(i + a - 1, j + b - 1)];
    const LimitPoint p = evaluator.evaluate(static_cast<Index>(j * n + i), u, v);
    ASSERT_LE(norm(p.position - expected), 1e-13 * norm(expected)) << "face " << j * n + i;
  }
}

// Central differences of the positions (step h: error h^2 times the third
// derivatives) and of the first derivatives.
void expect_derivatives_are_differences(const PolygonMesh& control, const char* name, unsigned seed) {
  SCOPED_TRACE(name);
  const LimitEvaluator evaluator(control, scheme(name));
  const bool triangles = std::string(name) == "loop";
  const double h = 1e-5, size = diagonal(control);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.05, 0.9);
  for (Index face = 0; face < evaluator.ptex_face_count(); ++face) {
    double u = unit(random), v = unit(random);
    if (triangles && u + v > 0.9) {
      u *= 0.45;
      v *= 0.45;
    }
    const LimitPoint p = evaluator.evaluate(face, u, v);
    const LimitPoint pu = evaluator.evaluate(face, u + h, v), mu = evaluator.evaluate(face, u - h, v);
    const LimitPoint pv = evaluator.evaluate(face, u, v + h), mv = evaluator.evaluate(face, u, v - h);
    const double scale = size * 1e-6 + norm(p.du) + norm(p.dv);
    ASSERT_LE(norm((1 / (2 * h)) * (pu.position - mu.position) - p.du), 1e-6 * scale) << "face " << face;
    ASSERT_LE(norm((1 / (2 * h)) * (pv.position - mv.position) - p.dv), 1e-6 * scale) << "face " << face;
    const double second = size * 1e-6 + norm(p.duu) + norm(p.duv) + norm(p.dvv);
    ASSERT_LE(norm((1 / (2 * h)) * (pu.du - mu.du) - p.duu), 1e-5 * second) << "face " << face;
    ASSERT_LE(norm((1 / (2 * h)) * (pv.du - mv.du) - p.duv), 1e-5 * second) << "face " << face;
    ASSERT_LE(norm((1 / (2 * h)) * (pv.dv - mv.dv) - p.dvv), 1e-5 * second) << "face " << face;
    ASSERT_NEAR(norm(p.normal), 1.0, 1e-12);
  }
}

TEST(LimitEvaluator, DerivativesAreTheDifferencesOfPositions) {
  expect_derivatives_are_differences(quad_bipyramid(5, 1), "catmull-clark", 1);
  expect_derivatives_are_differences(bipyramid(5, 2), "catmull-clark", 2);  // n-gons' sub-faces
  expect_derivatives_are_differences(bipyramid(7, 3), "loop", 3);
}

// Every interior edge sampled from both of its faces: equal points and
// normals (meshes whose faces are their ptex faces).
void expect_continuous_across_edges(const PolygonMesh& control, const char* name) {
  SCOPED_TRACE(name);
  const LimitEvaluator evaluator(control, scheme(name));
  const MeshTopology t(control);
  const bool triangles = std::string(name) == "loop";
  const std::vector<std::array<double, 2>> quad = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::array<double, 2>> triangle = {{0, 0}, {1, 0}, {0, 1}};
  const auto& corners = triangles ? triangle : quad;
  const double size = diagonal(control);
  // The point a of the way along corner c's edge (from its vertex to the next).
  const auto along = [&](Index c, double a) {
    const Index f = t.corner_face(c);
    const auto k = static_cast<std::size_t>(c - t.face_first_corner(f));
    const auto& p = corners[k];
    const auto& q = corners[(k + 1) % corners.size()];
    return evaluator.evaluate(f, p[0] + a * (q[0] - p[0]), p[1] + a * (q[1] - p[1]));
  };
  int checked = 0;
  for (Index e = 0; e < t.edge_count(); ++e) {
    const auto sides = t.edge_corners(e);
    ASSERT_EQ(sides.size(), 2u);
    for (const double a : {0.0, 0.125, 0.3, 0.5, 0.77, 1.0}) {
      const LimitPoint one = along(sides[0], a), other = along(sides[1], 1.0 - a);
      ASSERT_LE(norm(one.position - other.position), 1e-12 * size) << "edge " << e << " at " << a;
      ASSERT_LE(norm(one.normal - other.normal), 1e-10) << "edge " << e << " at " << a;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(LimitEvaluator, PointsAndNormalsAreContinuousAcrossEdges) {
  for (int n : {3, 5, 8, 12}) expect_continuous_across_edges(quad_bipyramid(n, 20u + n), "catmull-clark");
  expect_continuous_across_edges(test::jittered(test::cube(), 9), "catmull-clark");
  for (int n : {3, 4, 5, 8, 12}) expect_continuous_across_edges(bipyramid(n, 30u + n), "loop");
}

TEST(LimitEvaluator, BatchesEqualSingleCalls) {
  const LimitEvaluator evaluator(quad_bipyramid(6, 4), scheme("catmull-clark"));
  std::vector<SurfaceLocation> at;
  std::mt19937 random(8);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 2000; ++i)
    at.push_back({static_cast<Index>(i % evaluator.ptex_face_count()), unit(random), unit(random)});
  const std::vector<LimitPoint> batch = evaluator.evaluate(at);
  ASSERT_EQ(batch.size(), at.size());
  for (std::size_t i = 0; i < at.size(); ++i) {
    const LimitPoint one = evaluator.evaluate(at[i].face, at[i].u, at[i].v);
    ASSERT_EQ(batch[i].position, one.position);
    ASSERT_EQ(batch[i].du, one.du);
    ASSERT_EQ(batch[i].normal, one.normal);
  }
}

TEST(LimitEvaluator, RefusesWhatItDoesNotCover) {
  const auto message = [](auto&& make) {
    try {
      make();
    } catch (const InvalidInputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto refused = [&](const PolygonMesh& mesh, const char* name, const std::string& why) {
    const std::string m = message([&] { LimitEvaluator(mesh, scheme(name)); });
    EXPECT_NE(m.find(why), std::string::npos) << m << " (expected: " << why << ")";
  };
  refused(test::cube(), "doo-sabin", "has no exact evaluator");
  PolygonMesh tagged = test::creased_cube();
  tagged.tags.creases.back().sharpness = 4.5;
  refused(tagged, "catmull-clark", "has sharpness 4.5");
  tagged.tags.creases.clear();
  tagged.tags.corners = {CornerTag{0, kInfiniteSharpness, CornerType::unspecified, std::nullopt}};
  refused(tagged, "catmull-clark", "vertex 0 is a corner where 0 sharp edges meet");
  tagged.tags.corners.clear();
  tagged.tags.holes = {0};
  refused(tagged, "catmull-clark", "hole tags");
  // Coordinates near the double range: the patches' sums would overflow.
  PolygonMesh huge = test::cube();
  huge.positions[3].y = 1e305;
  refused(huge, "catmull-clark", "vertex 3 has a coordinate beyond 1e300");
  // A vertex used by no face has no part in the surface: accepted.
  PolygonMesh stray = test::cube();
  stray.positions.push_back({5, 5, 5});
  EXPECT_NO_THROW(LimitEvaluator(stray, scheme("catmull-clark")));
  // Two quads glued along their four edges: vertices of valence 2.
  PolygonMesh pillow = test::quad_grid(1, 1);
  pillow.add_face({0, 2, 3, 1});
  refused(pillow, "catmull-clark", "vertex 0 has valence 2");

  const LimitEvaluator evaluator(test::cube(), scheme("catmull-clark"));
  EXPECT_EQ(evaluator.ptex_face_count(), 6);
  EXPECT_THROW(evaluator.evaluate(6, 0.5, 0.5), InvalidInputError);
  EXPECT_THROW(evaluator.evaluate(-1, 0.5, 0.5), InvalidInputError);
  EXPECT_THROW(evaluator.evaluate(0, 1.5, 0.5), InvalidInputError);
  EXPECT_THROW(evaluator.evaluate(0, std::nan(""), 0.5), InvalidInputError);
  EXPECT_THROW(evaluator.ptex_face_of(6), InvalidInputError);
  const std::vector<SurfaceLocation> bad = {{0, 0.5, 0.5}, {2, -0.1, 0.0}};
  EXPECT_THROW(evaluator.evaluate(bad), InvalidInputError);
  const LimitEvaluator loop(bipyramid(5, 1), scheme("loop"));
  EXPECT_THROW(loop.evaluate(0, 0.6, 0.6), InvalidInputError);  // outside the triangle
  EXPECT_NO_THROW(loop.evaluate(0, 0.5, 0.5));
}

}  // namespace
}  // namespace subdiv
