// The survey's comparison (section 4.3, Figs. 11 and 12), in numbers: on the
// cube and the tetrahedron (triangulated for the triangle schemes) Loop and
// Catmull-Clark shrink most, Doo-Sabin and the modified Butterfly stay
// closest to the control mesh. Measured after four steps as the largest
// distance from a refined vertex to the control mesh's surface (per unit
// edge length), with the enclosed volume beside it; the figures are in
// docs/schemes.md.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/refine.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

// The volume a closed, consistently oriented mesh encloses (divergence
// theorem over a fan of each face).
double volume(const PolygonMesh& mesh) {
  double v = 0.0;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto face = mesh.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      v += dot(mesh.positions[face[0]], cross(mesh.positions[face[i]], mesh.positions[face[i + 1]])) / 6.0;
  }
  return v;
}

// Distance from p to triangle abc (Ericson, Real-Time Collision Detection,
// 5.1.5: the closest point by Voronoi regions).
double point_triangle_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(ap);
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return norm(p - (a + (d1 / (d1 - d3)) * ab));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return norm(p - (a + (d2 / (d2 - d6)) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return norm(p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
  const double denom = 1.0 / (va + vb + vc);
  return norm(p - (a + (vb * denom) * ab + (vc * denom) * ac));
}

// The largest distance from a vertex of `mesh` to the control mesh's surface.
double max_distance_to(const PolygonMesh& mesh, const PolygonMesh& control) {
  const PolygonMesh triangles = triangulate(control);
  double worst = 0.0;
  for (const Vec3& p : mesh.positions) {
    double nearest = 1e300;
    for (Index f = 0; f < triangles.face_count(); ++f) {
      const auto t = triangles.face(f);
      nearest = std::min(nearest, point_triangle_distance(p, triangles.positions[t[0]], triangles.positions[t[1]],
                                                          triangles.positions[t[2]]));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

struct Measures {
  double volume_ratio = 0.0;   ///< refined volume / control volume
  double max_distance = 0.0;   ///< to the control surface, per unit edge length
};

std::map<std::string, Measures> measure(const PolygonMesh& control, double edge) {
  RefineOptions options;
  options.levels = 4;
  std::map<std::string, Measures> out;
  for (const char* name : {"catmull-clark", "doo-sabin", "midedge", "loop", "modified-butterfly", "butterfly"}) {
    const Scheme& scheme = *find_scheme(name);
    const PolygonMesh input = scheme.traits.needs_triangles ? triangulate(control) : control;
    const PolygonMesh refined = refine(input, scheme, options);
    out[name] = {volume(refined) / volume(control), max_distance_to(refined, control) / edge};
    std::printf("%-20s volume ratio %.4f   max distance to the control mesh %.4f\n", name, out[name].volume_ratio,
                out[name].max_distance);
  }
  return out;
}

TEST(SchemeComparison, DooSabinAndModifiedButterflyStayClosestToTheControlMesh) {
  for (const auto& [what, control] : {std::pair{"cube", test::cube()}, std::pair{"tetrahedron", test::tetrahedron()}}) {
    const auto e = control.face(0);
    const double edge = norm(control.positions[e[1]] - control.positions[e[0]]);
    std::printf("%s\n", what);
    const auto m = measure(control, edge);
    for (const char* closest : {"doo-sabin", "modified-butterfly"})
      for (const char* shrinking : {"loop", "catmull-clark"})
        EXPECT_LT(m.at(closest).max_distance, m.at(shrinking).max_distance) << what << ": " << closest << " vs " << shrinking;
    // Approximating schemes shrink a convex body.
    for (const char* approximating : {"loop", "catmull-clark", "doo-sabin", "midedge"})
      EXPECT_LT(m.at(approximating).volume_ratio, 1.0) << what << " " << approximating;
  }
}

}  // namespace
}  // namespace subdiv
