#include "depth/depth_test_meshes.h"

#include <cmath>
#include <numbers>

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

}  // namespace subdiv
