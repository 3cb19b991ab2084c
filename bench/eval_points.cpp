#include "eval_points.h"

#include <random>

#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"

namespace subdiv::bench {

PolygonMesh refined_cube(int levels) {
  PolygonMesh cube;
  cube.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& f : std::vector<std::array<Index, 4>>{
           {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}})
    cube.add_face({f[0], f[1], f[2], f[3]});
  RefineOptions options;
  options.levels = levels;
  PolygonMesh mesh = refine(cube, *find_scheme("bilinear"), options);
  std::mt19937 random(1);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  const double step = 1.0 / (1 << levels);
  for (Vec3& p : mesh.positions)
    for (int a = 0; a < 3; ++a) p[a] += step * jitter(random);
  return mesh;
}

std::vector<SurfaceLocation> points_in_faces(const std::vector<Index>& faces, int per_face) {
  std::mt19937 random(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<SurfaceLocation> at;
  at.reserve(faces.size() * static_cast<std::size_t>(per_face));
  for (const Index f : faces)
    for (int k = 0; k < per_face; ++k) at.push_back({f, unit(random), unit(random)});
  return at;
}

std::vector<SurfaceLocation> points_near_extraordinary_corners(const PolygonMesh& mesh, const std::vector<Index>& faces,
                                                               int per_face, double reach) {
  const MeshTopology t(mesh);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> near(0.0, reach);
  // Ptex (u, v) of a quad's corners 0..3.
  constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<SurfaceLocation> at;
  at.reserve(faces.size() * static_cast<std::size_t>(per_face));
  for (const Index f : faces) {
    const auto vertices = t.face_vertices(f);
    std::size_t corner = 0;
    while (corner + 1 < vertices.size() && t.valence(vertices[corner]) == 4) ++corner;
    if (t.valence(vertices[corner]) == 4) corner = 0;
    const auto& [cu, cv] = kCorner[corner];
    for (int k = 0; k < per_face; ++k) {
      const double a = near(random), b = near(random);
      at.push_back({f, cu == 0 ? a : 1.0 - a, cv == 0 ? b : 1.0 - b});
    }
  }
  return at;
}

std::vector<Index> faces_at_extraordinary_vertices(const PolygonMesh& mesh) {
  const MeshTopology t(mesh);
  std::vector<Index> faces;
  for (Index f = 0; f < t.face_count(); ++f) {
    bool extraordinary = false;
    for (const Index v : t.face_vertices(f)) extraordinary |= t.valence(v) != 4;
    if (extraordinary) faces.push_back(f);
  }
  return faces;
}

std::vector<Index> all_faces(const PolygonMesh& mesh) {
  std::vector<Index> faces(static_cast<std::size_t>(mesh.face_count()));
  for (Index f = 0; f < mesh.face_count(); ++f) faces[static_cast<std::size_t>(f)] = f;
  return faces;
}

}  // namespace subdiv::bench
