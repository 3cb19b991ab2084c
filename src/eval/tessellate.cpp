// Uniform tessellation: each point of the result is numbered by what it lies
// on in the control mesh (a vertex, the inside of an edge, the inside of an
// n-gon's inner edge or its centre, the inside of a ptex face), so that
// neighbouring faces share it, and is evaluated once, from the first ptex
// face that reaches it.

#include "subdiv/eval/tessellate.h"
#include "tessellation_grid.h"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"

namespace subdiv {

namespace {

constexpr int kMaxRate = 4096;

// The numbering of the result's points, in blocks: control vertices, edge
// insides (rate - 1 per edge, from edge_vertices(e)[0]), n-gon centres,
// n-gon inner edges (half - 1 per corner, from the edge's midpoint to the
// centre), ptex face insides.
class PointNumbering {
 public:
  PointNumbering(const MeshTopology& t, int rate, bool triangles) : t_(t), rate_(rate), half_(rate / 2) {
    std::int64_t next = t.vertex_count();
    edges_ = next;
    next += std::int64_t{t.edge_count()} * (rate - 1);
    centres_ = next;
    ngon_.assign(static_cast<std::size_t>(t.face_count()), -1);
    const Index regular = triangles ? 3 : 4;
    Index ngons = 0;
    for (Index f = 0; f < t.face_count(); ++f)
      if (t.face_size(f) != regular) ngon_[static_cast<std::size_t>(f)] = ngons++;
    next += ngons;
    inner_ = next;
    // Inner edges of n-gon f: one per corner, numbered by the face's corners.
    for (Index f = 0; f < t.face_count(); ++f)
      if (t.face_size(f) != regular) inner_corners_ += t.face_size(f);
    next += inner_corners_ * (half_ - 1);
    insides_ = next;
    count_ = next;  // ptex insides are added by the caller
  }

  std::int64_t vertex(Index v) const { return v; }
  // Point i (0..rate) of the edge leaving corner c, counted from its vertex.
  std::int64_t along_corner_edge(Index c, int i) const {
    if (i == 0) return vertex(t_.corner_vertex(c));
    if (i == rate_) return vertex(t_.corner_vertex(t_.corner_next(c)));
    const Index e = t_.corner_edge(c);
    const bool forward = t_.edge_vertices(e)[0] == t_.corner_vertex(c);
    return edges_ + std::int64_t{e} * (rate_ - 1) + (forward ? i : rate_ - i) - 1;
  }
  std::int64_t centre(Index f) const { return centres_ + ngon_[static_cast<std::size_t>(f)]; }
  // Point j (0..half) of n-gon f's inner edge at corner c: from the midpoint
  // of the edge leaving c to the centre.
  std::int64_t inner(Index f, Index c, std::int64_t first_inner_corner, int j) const {
    if (j == 0) return along_corner_edge(c, half_);
    if (j == half_) return centre(f);
    return inner_ + (first_inner_corner + (c - t_.face_first_corner(f))) * (half_ - 1) + j - 1;
  }
  std::int64_t insides() const { return insides_; }
  bool is_ngon(Index f) const { return ngon_[static_cast<std::size_t>(f)] >= 0; }

 private:
  const MeshTopology& t_;
  int rate_, half_;
  std::int64_t edges_ = 0, centres_ = 0, inner_ = 0, insides_ = 0, count_ = 0, inner_corners_ = 0;
  std::vector<Index> ngon_;
};

}  // namespace

namespace detail {

TessellationGrid tessellation_grid(const PolygonMesh& mesh, const LimitEvaluator& evaluator, int rate) {
  if (rate < 1 || rate > kMaxRate)
    throw InvalidInputError("tessellate: rate " + std::to_string(rate) + " is outside [1, " +
                            std::to_string(kMaxRate) + "]");
  const MeshTopology t(mesh);
  const bool triangles = evaluator.triangles();
  const Index regular = triangles ? 3 : 4;
  Index ptex_faces = 0;
  bool ngons = false;
  for (Index f = 0; f < t.face_count(); ++f) {
    ngons |= t.face_size(f) != regular;
    ptex_faces += t.face_size(f) == regular ? 1 : t.face_size(f);
  }
  if (ptex_faces != evaluator.ptex_face_count() || t.face_count() == 0)
    throw InvalidInputError("tessellate: the mesh's ptex faces are not the evaluator's (" + std::to_string(ptex_faces) +
                            " against " + std::to_string(evaluator.ptex_face_count()) + ")");
  if (ngons && rate % 2 != 0)
    throw InvalidInputError("tessellate: rate " + std::to_string(rate) +
                            " is odd, and the mesh has faces that are not quads, whose sub-faces take half the rate "
                            "each; give an even rate");
  const PointNumbering numbering(t, rate, triangles);
  const int half = rate / 2;
  // Points inside each ptex face, and the result's size.
  const std::int64_t inside_quad = std::int64_t{rate - 1} * (rate - 1);
  const std::int64_t inside_triangle = std::int64_t{rate - 1} * (rate - 2) / 2;
  const std::int64_t inside_sub_face = std::int64_t{half - 1} * (half - 1);
  std::int64_t points = numbering.insides(), faces = 0;
  for (Index f = 0; f < t.face_count(); ++f) {
    if (numbering.is_ngon(f)) {
      points += t.face_size(f) * inside_sub_face;
      faces += std::int64_t{t.face_size(f)} * half * half;
    } else {
      points += triangles ? inside_triangle : inside_quad;
      faces += std::int64_t{rate} * rate;
    }
  }
  if (points > kMaxElements || faces * regular > kMaxElements)
    throw InvalidInputError("tessellate: rate " + std::to_string(rate) + " makes " + std::to_string(faces) +
                            " faces, beyond the index range");

  std::vector<SurfaceLocation> where(static_cast<std::size_t>(points));
  std::vector<char> placed(static_cast<std::size_t>(points), 0);
  PolygonMesh out;
  out.face_offsets.reserve(static_cast<std::size_t>(faces) + 1);
  out.face_indices.reserve(static_cast<std::size_t>(faces * regular));
  const auto place = [&](std::int64_t point, Index ptex, double u, double v) {
    if (!placed[static_cast<std::size_t>(point)]) {
      placed[static_cast<std::size_t>(point)] = 1;
      where[static_cast<std::size_t>(point)] = {ptex, u, v};
    }
    return static_cast<Index>(point);
  };
  std::int64_t next_inside = numbering.insides();
  // One grid per ptex face: `grid(i, j)` numbers point (i, j) of an n x n
  // grid (triangles: i + j <= n), placing it at (i / n, j / n).
  std::vector<Index> ids;
  const auto add_grid = [&](Index ptex, int n, bool triangle, const auto& boundary_point) {
    const auto stride = static_cast<std::size_t>(n + 1);
    ids.assign(stride * stride, -1);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= (triangle ? n - j : n); ++i) {
        const bool on_boundary = i == 0 || j == 0 || (triangle ? i + j == n : i == n || j == n);
        const std::int64_t point = on_boundary ? boundary_point(i, j) : next_inside++;
        ids[static_cast<std::size_t>(j) * stride + static_cast<std::size_t>(i)] =
            place(point, ptex, static_cast<double>(i) / n, static_cast<double>(j) / n);
      }
    const auto id = [&](int i, int j) { return ids[static_cast<std::size_t>(j) * stride + static_cast<std::size_t>(i)]; };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < (triangle ? n - j : n); ++i) {
        if (triangle) {
          out.add_face({id(i, j), id(i + 1, j), id(i, j + 1)});
          if (i + j + 1 < n) out.add_face({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        } else {
          out.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
      }
  };

  std::int64_t first_inner_corner = 0;
  for (Index f = 0; f < t.face_count(); ++f) {
    const Index first = t.face_first_corner(f), size = t.face_size(f);
    const Index ptex = evaluator.ptex_face_of(f);
    if (!numbering.is_ngon(f)) {
      const Index c0 = first, c1 = first + 1, c2 = first + 2;
      if (triangles) {
        add_grid(ptex, rate, true, [&](int i, int j) {
          if (j == 0) return numbering.along_corner_edge(c0, i);
          if (i == 0) return numbering.along_corner_edge(c2, rate - j);
          return numbering.along_corner_edge(c1, j);  // i + j == rate
        });
      } else {
        const Index c3 = first + 3;
        add_grid(ptex, rate, false, [&](int i, int j) {
          if (j == 0) return numbering.along_corner_edge(c0, i);
          if (i == rate) return numbering.along_corner_edge(c1, j);
          if (j == rate) return numbering.along_corner_edge(c2, rate - i);
          return numbering.along_corner_edge(c3, rate - j);  // i == 0
        });
      }
      continue;
    }
    for (Index k = 0; k < size; ++k) {
      const Index c = first + k, previous = first + (k + size - 1) % size;
      add_grid(ptex + k, half, false, [&](int i, int j) {
        if (j == 0) return numbering.along_corner_edge(c, i);                       // first half of c's edge
        if (i == 0) return numbering.along_corner_edge(previous, rate - j);          // second half of the previous edge
        if (i == half) return numbering.inner(f, c, first_inner_corner, j);          // to the centre from c's midpoint
        return numbering.inner(f, previous, first_inner_corner, i);                  // j == half
      });
    }
    first_inner_corner += size;
  }

  return {std::move(out), std::move(where)};
}

}  // namespace detail

PolygonMesh tessellate(const PolygonMesh& mesh, const LimitEvaluator& evaluator, int rate) {
  detail::TessellationGrid grid = detail::tessellation_grid(mesh, evaluator, rate);
  PolygonMesh& out = grid.faces;
  const std::vector<LimitPoint> limit = evaluator.evaluate(grid.locations);
  out.positions.resize(limit.size());
  FaceVaryingChannel normals{"normal", 3, {}, out.face_indices};
  normals.values.reserve(3 * limit.size());
  for (std::size_t i = 0; i < limit.size(); ++i) {
    out.positions[i] = limit[i].position;
    normals.values.insert(normals.values.end(), {limit[i].normal.x, limit[i].normal.y, limit[i].normal.z});
  }
  out.face_varying_channels.push_back(std::move(normals));
  return out;
}

}  // namespace subdiv
