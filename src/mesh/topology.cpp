#include "subdiv/mesh/topology.h"

#include <algorithm>
#include <atomic>
#include <numeric>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "subdiv/core/error.h"

#include "../core/large_buffers.h"
#include "../core/parallel_buckets.h"
#include "union_find.h"

namespace subdiv {

namespace {

// Turns per-bucket counts (size n + 1, counts in [1..n]) into CSR offsets.
void counts_to_offsets(std::vector<Index>& offsets) {
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
}

}  // namespace

MeshTopology::MeshTopology(const PolygonMesh& mesh) : MeshTopology(mesh, std::span<const Index>()) {}

MeshTopology::MeshTopology(const PolygonMesh& mesh, std::span<const Index> corner_edge_key)
    : face_offsets_(mesh.face_offsets), corner_vertex_(mesh.face_indices) {
  check_face_arrays(mesh);
  const Index nc = corner_count();
  if (!corner_edge_key.empty() && corner_edge_key.size() != static_cast<std::size_t>(nc))
    throw InvalidInputError("edge keys: " + std::to_string(corner_edge_key.size()) + " keys for " +
                            std::to_string(nc) + " face corners");
  const Index first_size = face_count() > 0 ? face_size(0) : 0;
  bool uniform = first_size == 3 || first_size == 4;
  for (Index f = 1; f < face_count() && uniform; ++f) uniform = face_size(f) == first_size;
  if (uniform) {
    uniform_face_size_ = first_size;
  } else {
    detail::assign_large(corner_face_, static_cast<std::size_t>(nc));
    for (Index f = 0; f < face_count(); ++f)
      std::fill(corner_face_.begin() + face_offsets_[f], corner_face_.begin() + face_offsets_[f + 1], f);
  }
  detail::assign_large(vertex_kind_, static_cast<std::size_t>(mesh.vertex_count()), VertexKind::isolated);

  build_edges(corner_edge_key);
  build_vertex_incidence();
  classify_and_order_vertices();
  build_boundary_loops();
}

// Half-edges are bucketed by their smaller vertex (a counting sort), then each
// small bucket is sorted by (larger vertex, corner). Edges come out numbered
// in (min, max) order, independent of face order within a bucket. The sides
// along one vertex pair (a run) are one edge, but for the exceptions
// has_coincident_edges() names (or, given keys, one edge per key); such a run
// is regrouped by edge, the edges in order of their first side, and each
// side that starts an edge after the run's first is marked by storing its
// other vertex complemented (~other < 0), for the numbering pass.
void MeshTopology::build_edges(std::span<const Index> key) {
  const Index nc = corner_count();
  const Index nv = vertex_count();
  detail::assign_large(corner_edge_, static_cast<std::size_t>(nc), kInvalidIndex);

  const detail::ParallelBuckets by_vertex(nv);
  auto smaller_end = [this](Index c, auto&& emit) {
    emit(std::min(corner_vertex_[c], corner_vertex_[corner_next(c)]));
  };
  std::vector<Index> bucket_offsets;
  by_vertex.count(nc, smaller_end, bucket_offsets);
  struct HalfEdge { Index other; Index corner; };
  std::vector<HalfEdge> buckets(static_cast<std::size_t>(bucket_offsets.back()));
  by_vertex.fill(nc, smaller_end, bucket_offsets, [&](Index slot, Index c) {
    buckets[static_cast<std::size_t>(slot)] = {std::max(corner_vertex_[c], corner_vertex_[corner_next(c)]), c};
  });
  auto key_of = [&](const HalfEdge& h) { return key[static_cast<std::size_t>(h.corner)]; };

  // Buckets are independent: sort them and count their edges in parallel,
  // number the edges by a prefix sum, then fill in parallel.
  std::vector<Index> first_edge(static_cast<std::size_t>(nv) + 1, 0);
  std::atomic<bool> coincident = false;
  tbb::parallel_for(tbb::blocked_range<Index>(0, nv, 4096), [&](const tbb::blocked_range<Index>& range) {
    std::vector<std::pair<Index, HalfEdge>> regrouped;  // (edge within the run, side)
    for (Index v = range.begin(); v != range.end(); ++v) {
      const auto first = buckets.begin() + bucket_offsets[v], last = buckets.begin() + bucket_offsets[v + 1];
      std::sort(first, last, [](const HalfEdge& l, const HalfEdge& r) {
        return l.other != r.other ? l.other < r.other : l.corner < r.corner;
      });
      Index edges = 0;
      for (auto run = first; run != last;) {
        auto run_end = run + 1;
        while (run_end != last && run_end->other == run->other) ++run_end;
        const auto n = static_cast<std::size_t>(run_end - run);
        // Each side's edge within the run, sides in corner (face) order:
        // from v to v an edge each; given keys, one per key; else the first
        // edge, unless its last side is in the same face (OpenSubdiv's rule).
        regrouped.clear();
        Index run_edges = 1;
        if (run->other == v) {
          for (std::size_t i = 0; i < n; ++i) regrouped.emplace_back(static_cast<Index>(i), run[static_cast<std::ptrdiff_t>(i)]);
          run_edges = static_cast<Index>(n);
        } else if (n > 1 && !key.empty()) {
          bool one_key = true;
          for (std::size_t i = 1; i < n && one_key; ++i) one_key = key_of(run[static_cast<std::ptrdiff_t>(i)]) == key_of(*run);
          for (std::size_t i = 0; i < n && !one_key; ++i) {
            const HalfEdge& side = run[static_cast<std::ptrdiff_t>(i)];
            std::size_t j = 0;
            while (j < i && key_of(regrouped[j].second) != key_of(side)) ++j;
            regrouped.emplace_back(j < i ? regrouped[j].first : i == 0 ? 0 : run_edges++, side);
          }
        } else if (n > 1) {
          // Counted first: the common run (one edge, one or two faces) needs no regrouping.
          auto own_edges = [&](auto&& each) {
            Index last_face_of_first = corner_face(run->corner);
            Index count = 1;
            for (std::size_t i = 0; i < n; ++i) {
              const Index f = corner_face(run[static_cast<std::ptrdiff_t>(i)].corner);
              const bool own = i > 0 && f == last_face_of_first;
              if (!own) last_face_of_first = f;
              each(i, own ? count++ : 0);
            }
            return count;
          };
          run_edges = own_edges([](std::size_t, Index) {});
          if (run_edges > 1)
            own_edges([&](std::size_t i, Index edge) { regrouped.emplace_back(edge, run[static_cast<std::ptrdiff_t>(i)]); });
        }
        if (run_edges > 1 || run->other == v) {
          coincident = true;
          std::stable_sort(regrouped.begin(), regrouped.end(),
                           [](const auto& l, const auto& r) { return l.first < r.first; });
          for (std::size_t i = 0; i < n; ++i) {
            HalfEdge side = regrouped[i].second;
            if (i > 0 && regrouped[i].first != regrouped[i - 1].first) side.other = ~side.other;
            run[static_cast<std::ptrdiff_t>(i)] = side;
          }
        }
        edges += run_edges;
        run = run_end;
      }
      first_edge[static_cast<std::size_t>(v) + 1] = edges;
    }
  });
  coincident_edges_ = coincident;
  edges_keyed_ = !key.empty();
  counts_to_offsets(first_edge);
  const Index ne = first_edge.back();
  detail::assign_large(edge_vertices_, static_cast<std::size_t>(ne));
  detail::assign_large(edge_corner_offsets_, static_cast<std::size_t>(ne) + 1);
  detail::assign_large(edge_corners_, buckets.size());
  tbb::parallel_for(tbb::blocked_range<Index>(0, nv, 4096), [&](const tbb::blocked_range<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      Index e = first_edge[static_cast<std::size_t>(v)] - 1;
      Index previous = kInvalidIndex;
      for (Index position = bucket_offsets[v]; position < bucket_offsets[v + 1]; ++position) {
        const HalfEdge& side = buckets[static_cast<std::size_t>(position)];
        const Index other = side.other < 0 ? ~side.other : side.other;
        if (side.other < 0 || other != previous) {
          ++e;
          edge_vertices_[static_cast<std::size_t>(e)] = {v, other};
          edge_corner_offsets_[static_cast<std::size_t>(e)] = position;
        }
        previous = other;
        corner_edge_[side.corner] = e;
        edge_corners_[static_cast<std::size_t>(position)] = side.corner;
      }
    }
  });
  edge_corner_offsets_[static_cast<std::size_t>(ne)] = static_cast<Index>(edge_corners_.size());
}

void MeshTopology::build_vertex_incidence() {
  const detail::ParallelBuckets by_vertex(vertex_count());
  auto corner_vertex = [this](Index c, auto&& emit) { emit(corner_vertex_[c]); };
  by_vertex.count(corner_count(), corner_vertex, vertex_corner_offsets_);
  detail::assign_large(vertex_corners_, corner_vertex_.size());
  by_vertex.fill(corner_count(), corner_vertex, vertex_corner_offsets_,
                 [this](Index slot, Index c) { vertex_corners_[static_cast<std::size_t>(slot)] = c; });

  auto edge_ends = [this](Index e, auto&& emit) {
    emit(edge_vertices_[e][0]);
    emit(edge_vertices_[e][1]);
  };
  by_vertex.count(edge_count(), edge_ends, vertex_edge_offsets_);
  detail::assign_large(vertex_edges_, 2 * edge_vertices_.size());
  by_vertex.fill(edge_count(), edge_ends, vertex_edge_offsets_,
                 [this](Index slot, Index e) { vertex_edges_[static_cast<std::size_t>(slot)] = e; });
}

// Faces at the same vertex are in one fan when they share an edge at that
// vertex (any shared edge, manifold or not: the usual definition of a
// non-manifold "bowtie" vertex) or are the same face (a face visiting the
// vertex twice). Counted per vertex with a small local union-find over its
// corners, so vertices are independent and processed in parallel.
Index MeshTopology::local_fan_count(Index v, std::vector<Index>& parent, std::vector<std::pair<Index, Index>>& seen) const {
  const auto corners = vertex_corners(v);
  const auto k = static_cast<Index>(corners.size());
  parent.resize(corners.size());
  for (Index i = 0; i < k; ++i) parent[static_cast<std::size_t>(i)] = i;
  auto find = [&](Index i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    return i;
  };
  auto unite = [&](Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  };
  seen.clear();
  for (Index i = 0; i < k; ++i) {
    const Index c = corners[static_cast<std::size_t>(i)];
    if (i > 0 && corner_face(c) == corner_face(corners[static_cast<std::size_t>(i - 1)])) unite(i, i - 1);
    for (const Index e : {corner_edge_[c], corner_edge_[corner_prev(c)]}) {
      if (e == kInvalidIndex) continue;
      auto it = std::find_if(seen.begin(), seen.end(), [e](const auto& p) { return p.first == e; });
      if (it == seen.end()) seen.emplace_back(e, i);
      else unite(i, it->second);
    }
  }
  Index fans = 0;
  for (Index i = 0; i < k; ++i) fans += find(i) == i;
  return fans;
}

void MeshTopology::classify_and_order_vertices() {
  detail::assign_large(ring_ordered_, static_cast<std::size_t>(vertex_count()), 0);
  detail::assign_large(fan_count_, static_cast<std::size_t>(vertex_count()), 0);
  // Every vertex reads shared arrays and writes only its own entries and
  // incidence slices: a parallel loop gives the same result as a serial one.
  tbb::parallel_for(tbb::blocked_range<Index>(0, vertex_count(), 1024), [this](const tbb::blocked_range<Index>& range) {
    std::vector<Index> ring_corners, ring_edges, parent;  // scratch, reused within the range
    std::vector<std::pair<Index, Index>> seen;
    for (Index v = range.begin(); v != range.end(); ++v) {
      const auto corners = vertex_corners(v);
      if (corners.empty()) continue;
      bool non_manifold_edge = false, on_boundary = false, repeated_face = false;
      for (const Index e : vertex_edges(v)) {
        if (is_non_manifold_edge(e)) non_manifold_edge = true;
        if (is_boundary_edge(e)) on_boundary = true;
      }
      for (std::size_t i = 1; i < corners.size(); ++i)
        if (corner_face(corners[i]) == corner_face(corners[i - 1])) repeated_face = true;
      const VertexKind manifold_kind = on_boundary ? VertexKind::boundary : VertexKind::interior;
      // A complete ring walk proves a single fan; only when it fails are the
      // fans counted (the common, manifold case stays cheap).
      if (!non_manifold_edge && !repeated_face) {
        vertex_kind_[v] = manifold_kind;
        if (order_ring(v, ring_corners, ring_edges)) {
          fan_count_[v] = 1;
          ring_ordered_[v] = 1;
          continue;
        }
      }
      fan_count_[v] = local_fan_count(v, parent, seen);
      const bool manifold = fan_count_[v] == 1 && !non_manifold_edge && !repeated_face;
      vertex_kind_[v] = manifold ? manifold_kind : VertexKind::non_manifold;
    }
  });
}

// Walks counter-clockwise around v: from a face, cross the edge that enters v
// (prev -> v) into the face that leaves v along it. Fails, leaving the
// incidence lists in index order, when a face on the way is flipped.
bool MeshTopology::order_ring(Index v, std::vector<Index>& ring_corners, std::vector<Index>& ring_edges) {
  const auto corners = vertex_corners(v);
  const std::size_t k = corners.size();
  const bool boundary = vertex_kind_[v] == VertexKind::boundary;
  Index start = corners[0];
  if (boundary) {
    Index found = 0;
    for (const Index c : corners)
      if (corner_edge_[c] != kInvalidIndex && is_boundary_edge(corner_edge_[c])) { start = c; ++found; }
    if (found != 1) return false;
  }
  ring_corners.clear();
  ring_edges.clear();
  Index c = start;
  while (true) {
    if (ring_corners.size() == k || corner_edge_[c] == kInvalidIndex) return false;
    ring_corners.push_back(c);
    ring_edges.push_back(corner_edge_[c]);
    const Index entering = corner_edge_[corner_prev(c)];
    if (entering == kInvalidIndex) return false;
    const auto sides = edge_corners(entering);
    if (sides.size() == 1) {  // reached the other boundary edge
      if (!boundary) return false;
      ring_edges.push_back(entering);
      break;
    }
    const Index across = sides[0] == corner_prev(c) ? sides[1] : sides[0];
    if (corner_vertex_[across] != v) return false;  // neighbour traverses the edge the same way
    if (across == start) break;
    c = across;
  }
  if (ring_corners.size() != k || ring_edges.size() != static_cast<std::size_t>(valence(v))) return false;
  std::copy(ring_corners.begin(), ring_corners.end(), vertex_corners_.begin() + vertex_corner_offsets_[v]);
  std::copy(ring_edges.begin(), ring_edges.end(), vertex_edges_.begin() + vertex_edge_offsets_[v]);
  return true;
}

bool MeshTopology::is_flipped_edge(Index e) const noexcept {
  const auto sides = edge_corners(e);
  if (sides.size() != 2) return false;
  return corner_vertex_[sides[0]] == corner_vertex_[sides[1]];
}

namespace {

// Whether edge e joins a vertex to itself or the same two vertices as
// another edge: coincident edges are numbered next to each other.
bool is_coincident(const MeshTopology& t, Index e) {
  const auto ends = t.edge_vertices(e);
  return ends[0] == ends[1] || (e > 0 && t.edge_vertices(e - 1) == ends) ||
         (e + 1 < t.edge_count() && t.edge_vertices(e + 1) == ends);
}

}  // namespace

bool MeshTopology::on_coincident_edge(Index v) const noexcept {
  if (!coincident_edges_) return false;
  for (const Index e : vertex_edges(v))
    if (is_coincident(*this, e)) return true;
  return false;
}

bool MeshTopology::is_non_manifold_corner(Index v) const noexcept {
  const bool input_defect = !edges_keyed_ && on_coincident_edge(v);
  if (vertex_kind_[v] == VertexKind::isolated || (ring_ordered_[v] != 0 && !input_defect)) return false;
  int non_manifold = 0, boundary = 0;
  for (const Index e : vertex_edges(v)) {
    non_manifold += edge_face_count(e) > 2 || is_flipped_edge(e) || (coincident_edges_ && is_coincident(*this, e));
    boundary += edge_face_count(e) < 2;
  }
  return !(non_manifold == 2 && boundary == 0 && vertex_face_count(v) > valence(v));
}

Index MeshTopology::find_edge(Index a, Index b) const noexcept {
  if (a < 0 || b < 0 || a >= vertex_count() || b >= vertex_count() || a == b) return kInvalidIndex;
  const std::array<Index, 2> key{std::min(a, b), std::max(a, b)};
  // Edges are numbered in (min, max) order, so a binary search finds them.
  auto it = std::lower_bound(edge_vertices_.begin(), edge_vertices_.end(), key);
  return it != edge_vertices_.end() && *it == key ? static_cast<Index>(it - edge_vertices_.begin())
                                                  : kInvalidIndex;
}

void MeshTopology::lay_out_vertex_incidence() {
  const std::size_t n = vertex_corner_offsets_.size() - 1;
  std::partial_sum(vertex_corner_offsets_.begin(), vertex_corner_offsets_.end(), vertex_corner_offsets_.begin());
  std::partial_sum(vertex_edge_offsets_.begin(), vertex_edge_offsets_.end(), vertex_edge_offsets_.begin());
  detail::assign_large(vertex_corners_, static_cast<std::size_t>(vertex_corner_offsets_.back()));
  detail::assign_large(vertex_edges_, static_cast<std::size_t>(vertex_edge_offsets_.back()));
  detail::assign_large(vertex_kind_, n, VertexKind::interior);
  detail::assign_large(ring_ordered_, n, 1);
  detail::assign_large(fan_count_, n, 1);
}

void MeshTopology::lay_out_point_split_incidence(const MeshTopology& p, Index face_point_ring) {
  const Index nf = p.face_count(), nv = p.vertex_count();
  detail::assign_large(vertex_corner_offsets_, static_cast<std::size_t>(nf + nv) + 1, 0);
  detail::assign_large(vertex_edge_offsets_, static_cast<std::size_t>(nf + nv) + 1, 0);
  tbb::parallel_for(tbb::blocked_range<Index>(0, nf, 16384), [&](const tbb::blocked_range<Index>& range) {
    for (Index f = range.begin(); f != range.end(); ++f)
      vertex_corner_offsets_[f + 1] = vertex_edge_offsets_[f + 1] = face_point_ring > 0 ? face_point_ring : p.face_size(f);
  });
  for (Index v = 0; v < nv; ++v) {
    vertex_corner_offsets_[nf + v + 1] = p.vertex_face_count(v);
    vertex_edge_offsets_[nf + v + 1] = p.valence(v);
  }
  lay_out_vertex_incidence();
}

// Face j of a ring leaves its vertex along edge j and enters along j + 1.
void MeshTopology::write_ring_from_smallest_corner(Index cv, const Index* ring_corners, const Index* ring_edges, Index n) {
  const auto start = static_cast<Index>(std::min_element(ring_corners, ring_corners + n) - ring_corners);
  Index* out_c = vertex_corners_.data() + vertex_corner_offsets_[cv];
  Index* out_e = vertex_edges_.data() + vertex_edge_offsets_[cv];
  for (Index k = 0; k < n; ++k) {
    const Index at = start + k < n ? start + k : start + k - n;
    out_c[k] = ring_corners[at];
    out_e[k] = ring_edges[at];
  }
}

// The child faces of parent edge e hold corners corners_per_edge * e ..,
// the first half on e's first side, the second on the other; a vertex
// point's ring has a child face per parent edge, between the spokes to the
// faces on either side. spoke_of[c]: the child edge from the face point of
// parent corner c's face to c's vertex point.
void MeshTopology::derive_vertex_point_rings(const MeshTopology& p, Index vertex_point, Index corners_per_edge,
                                             std::span<const Index> spoke_of) {
  tbb::parallel_for(tbb::blocked_range<Index>(0, p.vertex_count(), 4096), [&](const tbb::blocked_range<Index>& range) {
    std::vector<Index> ring_corners, ring_edges;
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Index cv = vertex_point + v;
      if (p.vertex_kind_[v] == VertexKind::isolated) {
        vertex_kind_[cv] = VertexKind::isolated;
        ring_ordered_[cv] = 0;
        fan_count_[cv] = 0;
        continue;
      }
      // The child face of ring edge e_j lies between the spokes to faces
      // j - 1 (leaving) and j (entering).
      const auto faces = p.vertex_corners(v);
      const auto edges = p.vertex_edges(v);
      const auto k = static_cast<Index>(edges.size());
      ring_corners.resize(static_cast<std::size_t>(k));
      ring_edges.resize(static_cast<std::size_t>(k));
      for (Index j = 0; j < k; ++j) {
        // Corner j leaves v along e_j: the first child face's V corner if it
        // is e_j's first side (running from a), else the second's.
        const Index e = edges[static_cast<std::size_t>(j)];
        const bool first_side = p.edge_corners(e)[0] == faces[static_cast<std::size_t>(j)];
        ring_corners[static_cast<std::size_t>(j)] = corners_per_edge * e + (first_side ? 0 : corners_per_edge / 2);
        ring_edges[static_cast<std::size_t>(j)] = spoke_of[static_cast<std::size_t>(faces[static_cast<std::size_t>(j == 0 ? k - 1 : j - 1)])];
      }
      write_ring_from_smallest_corner(cv, ring_corners.data(), ring_edges.data(), k);
    }
  });
}

void MeshTopology::build_boundary_loops() {
  std::vector<Index> boundary_edges;
  for (Index e = 0; e < edge_count(); ++e)
    if (is_boundary_edge(e)) boundary_edges.push_back(e);
  if (boundary_edges.empty()) return;  // closed: no per-vertex sets to build
  detail::UnionFind sets(vertex_count());
  for (const Index e : boundary_edges) sets.unite(edge_vertices_[e][0], edge_vertices_[e][1]);

  // Group boundary edges by component root; components are numbered by their
  // smallest vertex, so the loop order is deterministic.
  std::vector<Index> loop_of_root(static_cast<std::size_t>(vertex_count()), kInvalidIndex);
  std::vector<std::vector<Index>> loop_edges;
  for (const Index e : boundary_edges) {
    const Index root = sets.find(edge_vertices_[e][0]);
    if (loop_of_root[root] == kInvalidIndex) {
      loop_of_root[root] = static_cast<Index>(loop_edges.size());
      loop_edges.emplace_back();
    }
    loop_edges[loop_of_root[root]].push_back(e);
  }

  for (const auto& edges : loop_edges) {
    BoundaryLoop loop;
    // Try to follow the directed boundary half-edges (face direction) round a
    // simple cycle: each vertex must start exactly one boundary half-edge.
    std::vector<std::pair<Index, Index>> directed;  // (from, to)
    for (const Index e : edges) {
      const Index c = edge_corners(e)[0];
      directed.emplace_back(corner_vertex_[c], corner_vertex_[corner_next(c)]);
    }
    std::sort(directed.begin(), directed.end());
    bool simple = true;
    for (std::size_t i = 1; i < directed.size(); ++i)
      if (directed[i].first == directed[i - 1].first) simple = false;
    if (simple) {
      auto next_of = [&](Index from) -> Index {
        auto it = std::lower_bound(directed.begin(), directed.end(), std::make_pair(from, Index{-1}));
        return it != directed.end() && it->first == from ? it->second : kInvalidIndex;
      };
      const Index start = directed.front().first;
      Index v = start;
      do {
        loop.vertices.push_back(v);
        v = next_of(v);
      } while (v != kInvalidIndex && v != start && loop.vertices.size() <= directed.size());
      simple = v == start && loop.vertices.size() == directed.size();
    }
    loop.ordered = simple;
    if (!simple) {
      loop.vertices.clear();
      for (const Index e : edges) {
        loop.vertices.push_back(edge_vertices_[e][0]);
        loop.vertices.push_back(edge_vertices_[e][1]);
      }
      std::sort(loop.vertices.begin(), loop.vertices.end());
      loop.vertices.erase(std::unique(loop.vertices.begin(), loop.vertices.end()), loop.vertices.end());
    }
    boundary_loops_.push_back(std::move(loop));
  }
}

}  // namespace subdiv
