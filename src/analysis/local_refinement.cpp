#include "analysis/local_refinement.h"

#include <algorithm>
#include <span>

namespace subdiv::detail {

namespace {

bool semi_sharp(double s) { return s > 0.0 && s < kInfiniteSharpness; }

// The faces at each vertex, in face order: all the ring search and the
// tags read. (A MeshTopology of each whole child level, edges and ring
// orders included, would cost more than refining the cut level.)
struct VertexFaces {
  std::vector<Index> offsets, faces;

  explicit VertexFaces(const PolygonMesh& mesh) : offsets(static_cast<std::size_t>(mesh.vertex_count()) + 1, 0) {
    for (const Index v : mesh.face_indices) ++offsets[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 1; v < offsets.size(); ++v) offsets[v] += offsets[v - 1];
    faces.resize(mesh.face_indices.size());
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (Index f = 0; f < mesh.face_count(); ++f)
      for (const Index v : mesh.face(f)) faces[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = f;
  }
  std::span<const Index> at(Index v) const {
    const auto first = static_cast<std::size_t>(offsets[static_cast<std::size_t>(v)]);
    return {faces.data() + first, static_cast<std::size_t>(offsets[static_cast<std::size_t>(v) + 1]) - first};
  }
};

// Each vertex's distance in face rings from the nearest seed, counted from
// its `start` (a seed kept to fewer rings starts further out); only
// distances up to `last` are settled, the rest stay at `last + 1`.
std::vector<int> ring_distances(const PolygonMesh& mesh, const VertexFaces& around,
                                const std::vector<std::pair<Index, int>>& seeds, int last) {
  std::vector<int> ring(static_cast<std::size_t>(mesh.vertex_count()), last + 1);
  std::vector<std::vector<Index>> frontier(static_cast<std::size_t>(last) + 1);
  for (const auto& [v, start] : seeds)
    if (start < ring[static_cast<std::size_t>(v)]) {
      ring[static_cast<std::size_t>(v)] = start;
      frontier[static_cast<std::size_t>(start)].push_back(v);
    }
  for (int r = 0; r < last; ++r)
    for (const Index v : frontier[static_cast<std::size_t>(r)]) {
      if (ring[static_cast<std::size_t>(v)] != r) continue;  // reached sooner from another seed
      for (const Index f : around.at(v))
        for (const Index w : mesh.face(f))
          if (ring[static_cast<std::size_t>(w)] > r + 1) {
            ring[static_cast<std::size_t>(w)] = r + 1;
            frontier[static_cast<std::size_t>(r) + 1].push_back(w);
          }
    }
  return ring;
}

// Whether a kept face has the edge (a, b): refinement reads the tags of
// those edges only.
bool kept_edge(const PolygonMesh& mesh, const VertexFaces& around, const std::vector<Index>& face, Index a, Index b) {
  for (const Index f : around.at(a)) {
    if (face[static_cast<std::size_t>(f)] < 0) continue;
    const auto corners = mesh.face(f);
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Index next = corners[(i + 1) % corners.size()];
      if ((corners[i] == a && next == b) || (corners[i] == b && next == a)) return true;
    }
  }
  return false;
}

// The tags of the kept faces and vertices, renumbered (`vertex` maps old to
// new, -1 where dropped; `face` likewise).
Tags crop_tags(const PolygonMesh& mesh, const VertexFaces& around, const std::vector<Index>& vertex,
               const std::vector<Index>& face) {
  const Tags& in = mesh.tags;
  Tags out = in;
  out.creases.clear();
  out.corners.clear();
  out.holes.clear();
  out.other.clear();  // uninterpreted; the split drops them anyway
  for (const CreaseTag& c : in.creases)
    if (kept_edge(mesh, around, face, c.v0, c.v1))
      out.creases.push_back({vertex[static_cast<std::size_t>(c.v0)], vertex[static_cast<std::size_t>(c.v1)], c.sharpness});
  for (CornerTag c : in.corners) {
    if (vertex[static_cast<std::size_t>(c.vertex)] < 0) continue;
    c.vertex = vertex[static_cast<std::size_t>(c.vertex)];
    out.corners.push_back(c);
  }
  for (const Index f : in.holes)
    if (face[static_cast<std::size_t>(f)] >= 0) out.holes.push_back(face[static_cast<std::size_t>(f)]);
  return out;
}

}  // namespace

PolygonMesh crop_around(const PolygonMesh& mesh, std::vector<Index>& followed, int rings) {
  // Followed vertices start at ring 0, the tags' ends one ring short of the
  // last kept ring.
  std::vector<std::pair<Index, int>> seeds;
  for (const Index v : followed) seeds.emplace_back(v, 0);
  for (const CreaseTag& c : mesh.tags.creases)
    if (semi_sharp(c.sharpness)) {
      seeds.emplace_back(c.v0, rings - 1);
      seeds.emplace_back(c.v1, rings - 1);
    }
  for (const CornerTag& c : mesh.tags.corners)
    if (semi_sharp(c.sharpness)) seeds.emplace_back(c.vertex, rings - 1);
  const VertexFaces around(mesh);
  const std::vector<int> ring = ring_distances(mesh, around, seeds, rings - 1);

  // Kept: the faces at a vertex of ring < rings, and their vertices.
  std::vector<Index> face(static_cast<std::size_t>(mesh.face_count()), -1);
  std::vector<Index> vertex(static_cast<std::size_t>(mesh.vertex_count()), -1);
  for (const Index v : followed) vertex[static_cast<std::size_t>(v)] = 0;  // kept with or without faces
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const auto corners = mesh.face(f);
    if (std::none_of(corners.begin(), corners.end(), [&](Index v) { return ring[static_cast<std::size_t>(v)] < rings; }))
      continue;
    face[static_cast<std::size_t>(f)] = 0;
    for (const Index v : corners) vertex[static_cast<std::size_t>(v)] = 0;
  }
  PolygonMesh out;
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (vertex[static_cast<std::size_t>(v)] >= 0) {
      vertex[static_cast<std::size_t>(v)] = out.vertex_count();
      out.positions.push_back(mesh.positions[static_cast<std::size_t>(v)]);
    }
  std::vector<Index> corners;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (face[static_cast<std::size_t>(f)] < 0) continue;
    face[static_cast<std::size_t>(f)] = out.face_count();
    corners.clear();
    for (const Index v : mesh.face(f)) corners.push_back(vertex[static_cast<std::size_t>(v)]);
    out.add_face(corners);
  }
  out.tags = crop_tags(mesh, around, vertex, face);
  for (Index& v : followed) v = vertex[static_cast<std::size_t>(v)];
  return out;
}

}  // namespace subdiv::detail
