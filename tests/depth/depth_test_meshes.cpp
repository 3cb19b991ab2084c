#include "depth/depth_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "subdiv/depth/depth.h"
#include "subdiv/depth/mesh_measures.h"
#include "subdiv/mesh/triangulate.h"

namespace subdiv {

namespace {

PolygonMesh torus_positions(int n, int m, double R, double r) {
  PolygonMesh mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2.0 * std::numbers::pi * i / n;
      const double v = 2.0 * std::numbers::pi * j / m;
      mesh.positions.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  return mesh;
}

}  // namespace

PolygonMesh quad_torus(int n, int m, double R, double r) {
  PolygonMesh mesh = torus_positions(n, m, R, r);
  const auto id = [&](int i, int j) { return static_cast<Index>((i % n) * m + j % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) mesh.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return mesh;
}

PolygonMesh triangle_torus(int n, int m, double R, double r) {
  PolygonMesh mesh = torus_positions(n, m, R, r);
  const auto id = [&](int i, int j) { return static_cast<Index>((i % n) * m + j % m); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      mesh.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

PolygonMesh spinning_top(int n, double radius, double top, double bottom) {
  PolygonMesh mesh;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    mesh.positions.push_back({radius * std::cos(a), radius * std::sin(a), 0.0});
  }
  mesh.positions.push_back({0.0, 0.0, top});
  mesh.positions.push_back({0.0, 0.0, -bottom});
  const auto apex_top = static_cast<Index>(n);
  const auto apex_bottom = static_cast<Index>(n + 1);
  for (int i = 0; i < n; ++i) {
    const auto a = static_cast<Index>(i);
    const auto b = static_cast<Index>((i + 1) % n);
    mesh.add_face({a, b, apex_top});
    mesh.add_face({b, a, apex_bottom});
  }
  return mesh;
}

PolygonMesh perturbed(PolygonMesh mesh, double amount, std::mt19937& random) {
  std::uniform_real_distribution<double> offset(-amount, amount);
  for (Vec3& p : mesh.positions) p += Vec3{offset(random), offset(random), offset(random)};
  return mesh;
}

double largest_extent(const PolygonMesh& mesh) {
  Vec3 lo = mesh.positions.front();
  Vec3 hi = lo;
  for (const Vec3& p : mesh.positions)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

PolygonMesh for_scheme(PolygonMesh mesh, const Scheme& scheme) {
  return scheme.traits.needs_triangles ? triangulate(mesh) : mesh;
}

namespace {

void check_bound_holds_or_throw(const PolygonMesh& mesh, const Scheme& scheme, const std::string& name,
                                std::int64_t max_faces) {
  const DepthBound bound = depth_bound(mesh, scheme);
  int target = bound.start;
  const std::vector<LevelCost> costs = level_costs(mesh, scheme, bound.start + 4);
  while (target + 1 < static_cast<int>(costs.size()) && costs[static_cast<std::size_t>(target + 1)].faces <= max_faces)
    ++target;
  const double eps = bound.at(target);
  const int depth = bound.depth_for(eps);
  ASSERT_LE(depth, target) << name;
  PolygonMesh level = mesh;
  for (int k = 0; k <= depth; ++k) {
    SCOPED_TRACE("level " + std::to_string(k));
    LimitOptions limit;
    limit.refine.start_level = k;
    if (k >= bound.start) {
      const LimitDistances measured = resolved_limit_distances(level, scheme, limit);
      EXPECT_EQ(measured.approximated, 0) << name << " " << scheme.name << " level " << k;
      // On a regular mesh the bound is attained (old vertices contract by
      // exactly the rate), so the two sides differ only by rounding.
      EXPECT_LE(measured.max, bound.at(k) * (1.0 + 1e-12)) << name << " " << scheme.name << " level " << k;
      if (k == depth) {
        EXPECT_LE(measured.max, eps * (1.0 + 1e-12)) << name << " " << scheme.name << " at depth " << depth;
      }
    }
    RefineOptions step = limit.refine;
    step.levels = 1;
    level = refine(level, scheme, step);
  }
}

}  // namespace

void check_bound_holds(const PolygonMesh& mesh, const Scheme& scheme, const std::string& name, std::int64_t max_faces) {
  SCOPED_TRACE(name + ", " + std::string(scheme.name));
  try {
    check_bound_holds_or_throw(mesh, scheme, name, max_faces);
  } catch (const std::exception& e) {
    ADD_FAILURE() << name << ", " << scheme.name << ": " << e.what();
  }
}

}  // namespace subdiv
