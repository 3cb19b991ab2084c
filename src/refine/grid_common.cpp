// What the grid path's quad and triangle splits share (grid_common.h).

#include "grid_common.h"

#include <algorithm>
#include <array>
#include <span>

#include "../core/large_buffers.h"

namespace subdiv::detail {

PointValues::PointValues(const PolygonMesh& m) : mesh(m) {
  for (const VertexChannel& c : mesh.vertex_channels) width += c.components;
}

void PointValues::gather_channels(Index v, double* out) const {
  for (const VertexChannel& c : mesh.vertex_channels) {
    const auto k = static_cast<std::size_t>(c.components);
    std::copy_n(c.values.data() + static_cast<std::size_t>(v) * k, k, out);
    out += k;
  }
}

void scatter_channels(const double* values, Index v, PolygonMesh& out) {
  for (VertexChannel& c : out.vertex_channels) {
    const auto k = static_cast<std::size_t>(c.components);
    std::copy_n(values, k, c.values.data() + static_cast<std::size_t>(v) * k);
    values += k;
  }
}

void copy_point(const PolygonMesh& in, Index from, Index to, PolygonMesh& out) {
  out.positions[static_cast<std::size_t>(to)] = in.positions[static_cast<std::size_t>(from)];
  for (std::size_t ch = 0; ch < out.vertex_channels.size(); ++ch) {
    const auto k = static_cast<std::size_t>(out.vertex_channels[ch].components);
    std::copy_n(in.vertex_channels[ch].values.data() + static_cast<std::size_t>(from) * k, k,
                out.vertex_channels[ch].values.data() + static_cast<std::size_t>(to) * k);
  }
}

Tags tag_options(const Tags& parent) {
  Tags tags = parent;
  tags.creases.clear();
  tags.corners.clear();
  tags.holes.clear();
  tags.other.clear();
  return tags;
}

std::vector<char> sharp_vertices(const PolygonMesh& level, const MeshTopology& t) {
  std::vector<char> sharp(static_cast<std::size_t>(t.vertex_count()));
  auto valid = [&](Index v) { return v >= 0 && v < t.vertex_count(); };
  for (const CreaseTag& c : level.tags.creases)
    if (c.sharpness > 0.0 && valid(c.v0) && valid(c.v1) && t.find_edge(c.v0, c.v1) != kInvalidIndex)
      sharp[static_cast<std::size_t>(c.v0)] = sharp[static_cast<std::size_t>(c.v1)] = 1;
  for (const CornerTag& c : level.tags.corners)
    if (c.sharpness > 0.0 && valid(c.vertex)) sharp[static_cast<std::size_t>(c.vertex)] = 1;
  return sharp;
}

bool covers_level(const PolygonMesh& level, const MeshTopology& t, const RefineOptions& options, int levels,
                  Index face_size) {
  if (levels < 1 || levels > kMaxGridLevels) return false;
  if (options.boundary_rules != BoundaryRules::standard || options.allow_non_manifold) return false;
  for (const FaceVaryingChannel& c : level.face_varying_channels) {
    if (c.components <= 0 || c.values.size() % static_cast<std::size_t>(c.components) != 0 ||
        c.indices.size() != static_cast<std::size_t>(t.corner_count()))
      return false;
    for (const Index i : c.indices)
      if (i < 0 || i >= c.value_count()) return false;
  }
  for (const VertexChannel& c : level.vertex_channels)
    if (c.components <= 0 || c.values.size() != level.positions.size() * static_cast<std::size_t>(c.components))
      return false;
  // Chaikin's creasing reads a semi-sharp edge's neighbours: the masks.
  if (crease_method_of(level, options) == CreaseMethod::chaikin)
    for (const CreaseTag& c : level.tags.creases)
      if (c.sharpness > 0.0 && c.sharpness < kInfiniteSharpness) return false;
  for (Index f = 0; f < t.face_count(); ++f)
    if (t.face_size(f) != face_size) return false;
  for (Index v = 0; v < t.vertex_count(); ++v)
    if (t.vertex_kind(v) == VertexKind::isolated) return false;
  return true;
}

std::optional<MasksMesh> masks_mesh(const PolygonMesh& level, const MeshTopology& t, const std::vector<char>& regular,
                                    int rings, bool close_pinches) {
  const Index nf = t.face_count();
  std::vector<char> near(static_cast<std::size_t>(t.vertex_count()));
  for (Index f = 0; f < nf; ++f)
    if (!regular[static_cast<std::size_t>(f)])
      for (const Index v : t.face_vertices(f)) near[static_cast<std::size_t>(v)] = 1;
  auto touches = [&](Index f) {
    const auto vertices = t.face_vertices(f);
    return std::any_of(vertices.begin(), vertices.end(), [&](Index v) { return near[static_cast<std::size_t>(v)] != 0; });
  };
  const Tags& tags = level.tags;
  const bool tagged = !tags.creases.empty() || !tags.corners.empty() || !tags.holes.empty();
  std::vector<char> ring(static_cast<std::size_t>(nf));
  for (int r = 1; r < rings + (tagged ? 1 : 0); ++r) {
    for (Index f = 0; f < nf; ++f) ring[static_cast<std::size_t>(f)] = touches(f);
    for (Index f = 0; f < nf; ++f)
      if (ring[static_cast<std::size_t>(f)])
        for (const Index v : t.face_vertices(f)) near[static_cast<std::size_t>(v)] = 1;
  }
  // Where asked, every vertex whose taken faces form several fans takes all
  // of its faces, until none does: the mesh then does not pinch.
  for (bool grew = close_pinches; grew;) {
    grew = false;
    for (Index f = 0; f < nf; ++f) ring[static_cast<std::size_t>(f)] = touches(f);
    for (Index v = 0; v < t.vertex_count(); ++v) {
      if (near[static_cast<std::size_t>(v)]) continue;  // all of its faces are taken
      const auto corners = t.vertex_corners(v);
      const auto n = corners.size();
      auto taken = [&](std::size_t i) { return ring[static_cast<std::size_t>(t.corner_face(corners[i % n]))] != 0; };
      std::size_t fans = 0;
      for (std::size_t i = 0; i < n; ++i)
        fans += taken(i) && (i == 0 ? t.vertex_kind(v) != VertexKind::interior || !taken(n - 1) : !taken(i - 1));
      if (fans > 1 || (fans > 0 && !t.ring_ordered(v))) near[static_cast<std::size_t>(v)] = 1, grew = true;
    }
  }
  MasksMesh local;
  local.face_in_mesh.assign(static_cast<std::size_t>(nf), kInvalidIndex);
  std::vector<Index> vertex_in_mesh(static_cast<std::size_t>(t.vertex_count()), kInvalidIndex);
  PolygonMesh& mesh = local.mesh;
  mesh.tags = tag_options(tags);
  for (const VertexChannel& c : level.vertex_channels) mesh.vertex_channels.push_back({c.name, c.components, {}});
  for (Index f = 0; f < nf; ++f) {
    const auto vertices = t.face_vertices(f);
    if (!touches(f)) continue;
    if (2 * (mesh.face_count() + 1) > nf) return std::nullopt;
    std::array<Index, 4> face;
    for (std::size_t c = 0; c < vertices.size(); ++c) {
      const auto v = static_cast<std::size_t>(vertices[c]);
      if (vertex_in_mesh[v] == kInvalidIndex) {
        vertex_in_mesh[v] = mesh.vertex_count();
        local.level_vertex.push_back(vertices[c]);
        mesh.positions.push_back(level.positions[v]);
        for (std::size_t ch = 0; ch < level.vertex_channels.size(); ++ch) {
          const VertexChannel& in = level.vertex_channels[ch];
          const auto k = static_cast<std::size_t>(in.components);
          mesh.vertex_channels[ch].values.insert(mesh.vertex_channels[ch].values.end(), in.values.begin() + v * k,
                                                 in.values.begin() + (v + 1) * k);
        }
      }
      face[c] = vertex_in_mesh[v];
    }
    local.face_in_mesh[static_cast<std::size_t>(f)] = mesh.add_face(std::span<const Index>(face.data(), vertices.size()));
  }
  // The tags on its elements.
  auto in_mesh = [&](Index v) {
    return v >= 0 && v < t.vertex_count() ? vertex_in_mesh[static_cast<std::size_t>(v)] : kInvalidIndex;
  };
  for (const CreaseTag& c : tags.creases)
    if (in_mesh(c.v0) != kInvalidIndex && in_mesh(c.v1) != kInvalidIndex)
      mesh.tags.creases.push_back({in_mesh(c.v0), in_mesh(c.v1), c.sharpness});
  for (const CornerTag& c : tags.corners)
    if (in_mesh(c.vertex) != kInvalidIndex) {
      mesh.tags.corners.push_back(c);
      mesh.tags.corners.back().vertex = in_mesh(c.vertex);
    }
  for (const Index f : tags.holes)
    if (f >= 0 && f < nf && local.face_in_mesh[static_cast<std::size_t>(f)] != kInvalidIndex)
      mesh.tags.holes.push_back(local.face_in_mesh[static_cast<std::size_t>(f)]);
  return local;
}

RefineOptions masks_options(const RefineOptions& options, int levels) {
  RefineOptions by_masks = options;
  by_masks.levels = levels;
  by_masks.regular_grids = false;
  by_masks.on_level = nullptr;
  by_masks.allow_non_manifold = true;  // its rim may pinch; the points taken lie inside
  return by_masks;
}

PolygonMesh sized_result(const PolygonMesh& level, const RefineOptions& options, Tags tags, std::int64_t vertices,
                         std::int64_t faces, Index face_size) {
  PolygonMesh out;
  out.tags = std::move(tags);
  const CreaseMethod method = crease_method_of(level, options);
  if (out.tags.crease_method != method) {
    out.tags.crease_method = method;
    out.tags.crease_method_set = true;
  }
  assign_large(out.positions, static_cast<std::size_t>(vertices));
  assign_large(out.face_offsets, static_cast<std::size_t>(faces) + 1);
  assign_large(out.face_indices, static_cast<std::size_t>(face_size) * static_cast<std::size_t>(faces));
  for (const VertexChannel& c : level.vertex_channels) {
    out.vertex_channels.push_back({c.name, c.components, {}});
    assign_large(out.vertex_channels.back().values,
                 static_cast<std::size_t>(vertices) * static_cast<std::size_t>(c.components));
  }
  return out;
}

}  // namespace subdiv::detail
