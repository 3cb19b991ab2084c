#include "bench_meshes.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <numbers>

namespace subdiv::bench {

PolygonMesh torus(int n) {
  PolygonMesh mesh;
  const double two_pi = 2 * std::numbers::pi;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = two_pi * i / n, v = two_pi * j / n;
      const double r = 1.0 + 0.3 * std::cos(v) + 1e-3 * std::sin(7.0 * i + 3.0 * j);
      mesh.positions.push_back({r * std::cos(u), r * std::sin(u), 0.3 * std::sin(v)});
    }
  auto id = [n](int i, int j) { return static_cast<Index>(((j + n) % n) * n + (i + n) % n); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) mesh.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return mesh;
}

PolygonMesh triangulated_torus(int n) {
  const PolygonMesh quads = torus(n);
  PolygonMesh mesh;
  mesh.positions = quads.positions;
  for (Index f = 0; f < quads.face_count(); ++f) {
    const auto q = quads.face(f);
    mesh.add_face({q[0], q[1], q[2]});
    mesh.add_face({q[0], q[2], q[3]});
  }
  return mesh;
}

std::string shared_mesh(const std::string& relative) {
  const std::string path = std::string(SUBDIV_SHARED_MESH_DIR) + "/" + relative;
  return std::filesystem::exists(path) ? path : std::string();
}

}  // namespace subdiv::bench

namespace subdiv::bench {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace subdiv::bench
