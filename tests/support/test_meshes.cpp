#include "support/test_meshes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace subdiv::test {

PolygonMesh cube() {
  return make_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                   {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
}

PolygonMesh creased_cube() {
  const PolygonMesh c = cube();
  PolygonMesh mesh;
  // The split by hand (no refinement in the test support): corners, then a
  // point per edge and per face, found by their coordinates.
  const auto point = [&](Vec3 p) {
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      if (mesh.positions[i] == p) return static_cast<Index>(i);
    mesh.positions.push_back(p);
    return static_cast<Index>(mesh.positions.size() - 1);
  };
  for (Index f = 0; f < c.face_count(); ++f) {
    const auto v = c.face(f);
    Vec3 centre{};
    for (const Index i : v) centre += 0.25 * c.positions[static_cast<std::size_t>(i)];
    for (std::size_t k = 0; k < 4; ++k) {
      const Vec3 a = c.positions[static_cast<std::size_t>(v[k])];
      const Vec3 next = c.positions[static_cast<std::size_t>(v[(k + 1) % 4])];
      const Vec3 prev = c.positions[static_cast<std::size_t>(v[(k + 3) % 4])];
      mesh.add_face({point(a), point(0.5 * (a + next)), point(centre), point(0.5 * (a + prev))});
    }
  }
  // Creases: the edges whose two ends lie on z = 1/2, or on x = 1/2.
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto v = mesh.face(f);
    for (std::size_t k = 0; k < 4; ++k) {
      const Index a = v[k], b = v[(k + 1) % 4];
      if (a > b) continue;  // each interior edge once (its other face has it b-a)
      const Vec3 p = mesh.positions[static_cast<std::size_t>(a)], q = mesh.positions[static_cast<std::size_t>(b)];
      if ((p.z == 0.5 && q.z == 0.5) || (p.x == 0.5 && q.x == 0.5)) mesh.tags.creases.push_back({a, b, kInfiniteSharpness});
    }
  }
  return mesh;
}

PolygonMesh quad_grid(int n, int m) {
  PolygonMesh mesh;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) mesh.positions.push_back({double(i), double(j), 0.0});
  auto id = [n](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) mesh.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return mesh;
}

namespace {

// The grid's quads each split into two triangles: along (i, j)-(i+1, j+1),
// or, `other_diagonal`, along (i+1, j)-(i, j+1).
PolygonMesh split_grid(int n, int m, bool other_diagonal) {
  PolygonMesh quads = quad_grid(n, m);
  PolygonMesh mesh;
  mesh.positions = quads.positions;
  for (Index f = 0; f < quads.face_count(); ++f) {
    const auto q = quads.face(f);
    if (other_diagonal) {
      mesh.add_face({q[0], q[1], q[3]});
      mesh.add_face({q[1], q[2], q[3]});
    } else {
      mesh.add_face({q[0], q[1], q[2]});
      mesh.add_face({q[0], q[2], q[3]});
    }
  }
  return mesh;
}

}  // namespace

PolygonMesh triangle_grid(int n, int m) { return split_grid(n, m, false); }

PolygonMesh box_spline_grid(int n, int m) { return split_grid(n, m, true); }

double radius(const PolygonMesh& mesh) {
  double r = 0.0;
  for (const Vec3& p : mesh.positions) r = std::max(r, norm(p));
  return r;
}

PolygonMesh jittered(PolygonMesh mesh, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (Vec3& p : mesh.positions) p += Vec3{jitter(random), jitter(random), jitter(random)};
  return mesh;
}

PolygonMesh with_random_heights(PolygonMesh mesh, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> height(-1.0, 1.0);
  for (Vec3& p : mesh.positions) p.z = height(random);
  return mesh;
}

PolygonMesh bipyramid(int n) {
  PolygonMesh mesh;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    mesh.positions.push_back({std::cos(a), std::sin(a), 0.0});
  }
  mesh.positions.push_back({0, 0, 1.2});
  mesh.positions.push_back({0, 0, -0.9});
  const auto top = static_cast<Index>(n), bottom = static_cast<Index>(n + 1);
  for (int i = 0; i < n; ++i) {
    const auto a = static_cast<Index>(i), b = static_cast<Index>((i + 1) % n);
    mesh.add_face({a, b, top});
    mesh.add_face({b, a, bottom});
  }
  return mesh;
}

PolygonMesh tetrahedron() {
  return make_mesh({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}});
}

PolygonMesh hard_numbers_mesh() {
  return make_mesh({{0.1, 1.0 / 3.0, -2.5e-300},
                    {1e300, -0.7, 2.0 / 7.0},
                    {3.141592653589793, 2.718281828459045, -1.4142135623730951},
                    {123456789.123456789, -0.0, 5e-324},
                    {0.30000000000000004, 7, -8},
                    {1.7976931348623157e308, 9.5, 10.25}},
                   {{0, 1, 2}, {0, 2, 3, 4}, {1, 5, 4, 3, 2}});
}

std::string data_path(const std::string& name) { return std::string(SUBDIV_TEST_DATA_DIR) + "/" + name; }
std::string bundled_path(const std::string& name) { return std::string(SUBDIV_BUNDLED_MESH_DIR) + "/" + name; }
std::string shared_mesh_dir() { return SUBDIV_SHARED_MESH_DIR; }

}  // namespace subdiv::test
