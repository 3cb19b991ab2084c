#include "render_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"

namespace subdiv::render {

namespace {

std::uint64_t edge_key(Index a, Index b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{hi} << 32) | lo;
}

// Sharpness of each tagged edge, by its vertex pair.
std::unordered_map<std::uint64_t, double> crease_sharpness(const PolygonMesh& mesh) {
  std::unordered_map<std::uint64_t, double> sharpness;
  for (const CreaseTag& c : mesh.tags.creases)
    if (c.v0 >= 0 && c.v1 >= 0 && c.v0 < mesh.vertex_count() && c.v1 < mesh.vertex_count() && c.sharpness > 0.0)
      sharpness[edge_key(c.v0, c.v1)] = c.sharpness;
  return sharpness;
}

void add_segment(LineSet& set, const Vec3& a, const Vec3& b) {
  set.ends.insert(set.ends.end(), {static_cast<float>(a.x), static_cast<float>(a.y), static_cast<float>(a.z),
                                   static_cast<float>(b.x), static_cast<float>(b.y), static_cast<float>(b.z)});
}


// The faces' edges in colour: every edge (wireframe), boundaries, creases.
void add_edges(Scene& scene, const PolygonMesh& mesh, const std::vector<char>& drawn, const EdgeStyle& style,
               const Rgb& plain, float plain_width) {
  const MeshTopology topology(mesh);
  const auto sharpness = crease_sharpness(mesh);
  LineSet wire{{}, plain, plain_width}, boundary{{}, kBoundaryColour, 2.0F}, sharp{{}, kSharpColour, 2.0F},
      semi{{}, kSemiSharpColour, 2.0F};
  for (Index e = 0; e < topology.edge_count(); ++e) {
    Index faces_drawn = 0;
    for (const Index c : topology.edge_corners(e)) faces_drawn += drawn[static_cast<std::size_t>(topology.corner_face(c))];
    if (faces_drawn == 0) continue;
    const auto [a, b] = topology.edge_vertices(e);
    const Vec3& pa = mesh.positions[static_cast<std::size_t>(a)];
    const Vec3& pb = mesh.positions[static_cast<std::size_t>(b)];
    LineSet* set = style.wireframe ? &wire : nullptr;
    if (style.features) {
      const auto tagged = sharpness.find(edge_key(a, b));
      if (tagged != sharpness.end())
        set = tagged->second >= kInfiniteSharpness ? &sharp : &semi;
      else if (faces_drawn == 1)
        set = &boundary;
    }
    if (set) add_segment(*set, pa, pb);
  }
  for (LineSet* set : {&wire, &semi, &sharp, &boundary})
    if (!set->ends.empty()) scene.lines.push_back(std::move(*set));
}

}  // namespace

Scene surface_scene(const PolygonMesh& mesh, const std::vector<Vec3>& vertex_normals, const EdgeStyle& edges) {
  if (mesh.vertex_count() >= std::numeric_limits<std::int32_t>::max())
    throw InvalidInputError("too many vertices to render: " + std::to_string(mesh.vertex_count()));
  std::vector<char> drawn(static_cast<std::size_t>(mesh.face_count()), 1);
  for (const Index f : mesh.tags.holes)
    if (f >= 0 && f < mesh.face_count()) drawn[static_cast<std::size_t>(f)] = 0;

  Scene scene;
  const auto n = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<Vec3> area_normals(n, Vec3{});
  std::vector<char> used(n, 0);
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (!drawn[static_cast<std::size_t>(f)]) continue;
    const auto face = mesh.face(f);
    if (face.size() < 3) continue;
    // Newell's normal: the polygon's area vector, also for non-planar faces.
    Vec3 area{};
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Vec3& p = mesh.positions[static_cast<std::size_t>(face[i])];
      const Vec3& q = mesh.positions[static_cast<std::size_t>(face[(i + 1) % face.size()])];
      area = area + cross(p, q);
    }
    for (std::size_t i = 0; i < face.size(); ++i) {
      area_normals[static_cast<std::size_t>(face[i])] = area_normals[static_cast<std::size_t>(face[i])] + area;
      used[static_cast<std::size_t>(face[i])] = 1;
    }
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      scene.triangles.insert(scene.triangles.end(), {static_cast<std::uint32_t>(face[0]),
                                                     static_cast<std::uint32_t>(face[i]),
                                                     static_cast<std::uint32_t>(face[i + 1])});
  }
  if (scene.triangles.empty()) throw InvalidInputError("nothing to render: the mesh has no face with three corners");
  if (edges.flat) {
    // A vertex per triangle corner, with the triangle's normal.
    std::vector<std::uint32_t> corners;
    corners.swap(scene.triangles);
    for (std::size_t t = 0; t < corners.size(); t += 3) {
      const Vec3& a = mesh.positions[corners[t]];
      const Vec3 facet = cross(mesh.positions[corners[t + 1]] - a, mesh.positions[corners[t + 2]] - a);
      const double length = norm(facet);
      const Vec3 unit = length > 0.0 ? (1.0 / length) * facet : Vec3{};
      for (std::size_t k = 0; k < 3; ++k) {
        const Vec3& p = mesh.positions[corners[t + k]];
        scene.positions.insert(scene.positions.end(),
                               {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
        scene.normals.insert(scene.normals.end(),
                             {static_cast<float>(unit.x), static_cast<float>(unit.y), static_cast<float>(unit.z)});
        scene.triangles.push_back(static_cast<std::uint32_t>(t + k));
      }
    }
  }

  if (!edges.flat) {
    scene.positions.resize(3 * n);
    scene.normals.resize(3 * n);
  }
  const bool given = vertex_normals.size() == n;
  Vec3 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
           std::numeric_limits<double>::max()};
  Vec3 high = -1.0 * low;
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3& p = mesh.positions[v];
    Vec3 normal = area_normals[v];
    if (given && dot(vertex_normals[v], vertex_normals[v]) > 0.0)
      normal = dot(vertex_normals[v], normal) < 0.0 ? -1.0 * vertex_normals[v] : vertex_normals[v];
    const double length = std::sqrt(dot(normal, normal));
    if (length > 0.0) normal = (1.0 / length) * normal;
    if (!edges.flat)
      for (int k = 0; k < 3; ++k) {
        scene.positions[3 * v + static_cast<std::size_t>(k)] = static_cast<float>(p[k]);
        scene.normals[3 * v + static_cast<std::size_t>(k)] = static_cast<float>(normal[k]);
      }
    if (!used[v]) continue;
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  scene.centre = 0.5 * (low + high);
  for (std::size_t v = 0; v < n; ++v)
    if (used[v]) {
      const Vec3 d = mesh.positions[v] - scene.centre;
      scene.radius = std::max(scene.radius, std::sqrt(dot(d, d)));
    }
  if (edges.wireframe || edges.features) add_edges(scene, mesh, drawn, edges, kWireColour, 1.0F);
  return scene;
}

void add_cage(Scene& scene, const PolygonMesh& cage) {
  const std::vector<char> drawn(static_cast<std::size_t>(cage.face_count()), 1);
  add_edges(scene, cage, drawn, EdgeStyle{.wireframe = true, .features = true}, kCageColour, 1.5F);
  for (const Vec3& p : cage.positions) {
    const Vec3 d = p - scene.centre;
    scene.radius = std::max(scene.radius, std::sqrt(dot(d, d)));
  }
}

void frame_together(std::vector<Scene*> scenes) {
  if (scenes.empty()) return;
  const Vec3 centre = scenes.front()->centre;
  double radius = 0.0;
  for (const Scene* s : scenes) radius = std::max(radius, norm(s->centre - centre) + s->radius);
  for (Scene* s : scenes) {
    s->centre = centre;
    s->radius = radius;
  }
}

}  // namespace subdiv::render
