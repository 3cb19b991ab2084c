#include "face_varying.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <unordered_map>

namespace subdiv::detail {

namespace {

using ValueTag = FaceVaryingRefiner::ValueTag;

constexpr std::uint8_t kEdgeMismatch = 1;  // the edge's faces disagree at one of its ends
constexpr std::uint8_t kEdgeLinear = 2;    // its edge point is a corner value (linear boundaries)

bool is_infinite(double s) { return s >= kInfiniteSharpness; }
bool is_semi_sharp(double s) { return s > 0.0 && s < kInfiniteSharpness; }

std::size_t at(Index i) { return static_cast<std::size_t>(i); }

// What the option sharpens (Vtr::FVarLevel::completeTopologyFromFaceValues).
struct Options {
  bool linear_boundaries = false;   // every seam and boundary value a corner
  bool dependent = false;           // corners_plus1/plus2: two-valued vertices sharpen together
  bool corners_sharp = false;       // single-face regions are corners
  bool sharpen_one_face_boundary = false;  // a one-face boundary vertex is mismatched
  bool both_if_one_corner = false;  // corners_plus2
  bool sharpen_darts = false;       // an interior vertex with one value and a seam
};

Options options_for(FaceVaryingInterpolation mode, BoundaryInterpolation boundary) {
  Options o;
  o.linear_boundaries = mode == FaceVaryingInterpolation::boundaries || mode == FaceVaryingInterpolation::all;
  o.dependent = mode == FaceVaryingInterpolation::corners_plus1 || mode == FaceVaryingInterpolation::corners_plus2;
  o.corners_sharp = mode != FaceVaryingInterpolation::none;
  o.sharpen_one_face_boundary = boundary != BoundaryInterpolation::edge_and_corner && o.corners_sharp;
  o.both_if_one_corner = mode == FaceVaryingInterpolation::corners_plus2;
  o.sharpen_darts = o.both_if_one_corner || o.linear_boundaries;
  return o;
}

const double* value_of(const FaceVaryingChannel& ch, Index value) {
  return ch.values.data() + at(value) * static_cast<std::size_t>(ch.components);
}

// The value at the other end of edge e from corner c's vertex, in c's face.
Index across(const MeshTopology& t, const FaceVaryingChannel& ch, Index c, Index e) {
  return ch.indices[at(t.corner_edge(c) == e ? t.corner_next(c) : t.corner_prev(c))];
}

// A run of consecutive faces around a vertex holding one value (a "span"):
// its size, what its interior edges are, and its two bounding edges' far
// values (Vtr::FVarLevel::gatherValueSpans and the crease ends).
struct Span {
  int size = 0;
  int disjoint = 0;  // seams inside it, or further runs of the same value
  int infinite = 0;  // infinitely sharp interior edges
  int semi = 0;      // semi-sharp interior edges
  std::vector<Index> interior;  // the interior edges
  Index end_values[2] = {kInvalidIndex, kInvalidIndex};
};

// The spans of each of vertex v's values (`values`, its siblings), for a
// vertex whose ring is ordered.
std::vector<Span> spans_at(const MeshTopology& t, const FaceVaryingChannel& ch, const LevelCreasing& creasing,
                           std::span<const std::uint8_t> edge_tags, Index v, std::span<const Index> values) {
  const auto corners = t.vertex_corners(v);
  const auto edges = t.vertex_edges(v);
  const auto k = static_cast<int>(corners.size());
  const auto m = static_cast<int>(edges.size());
  const bool interior = m == k;
  std::vector<Span> spans(values.size());
  auto sibling = [&](int j) {
    const Index value = ch.indices[at(corners[static_cast<std::size_t>(j)])];
    return static_cast<std::size_t>(std::find(values.begin(), values.end(), value) - values.begin());
  };
  auto count_interior = [&](Span& s, Index e) {
    s.interior.push_back(e);
    const double sharpness = edge_sharpness_of(creasing, e);
    if (edge_tags[at(e)] & kEdgeMismatch) ++s.disjoint;
    else if (is_infinite(sharpness)) ++s.infinite;
    else if (is_semi_sharp(sharpness)) ++s.semi;
  };
  // Corner j lies between edges j and j + 1 (topology.h).
  auto edge = [&](int j) { return edges[static_cast<std::size_t>(((j % m) + m) % m)]; };
  auto corner = [&](int j) { return corners[static_cast<std::size_t>(((j % k) + k) % k)]; };
  if (interior && values.size() == 1) {
    // One value all round: the span starts after the first seam; a second
    // seam makes it disjoint.
    Span& s = spans[0];
    s.size = k;
    int start = -1;
    for (int j = 0; j < m; ++j) {
      if (edge_tags[at(edge(j))] & kEdgeMismatch) {
        if (start >= 0) {
          s.disjoint = 1;
          break;
        }
        start = j;
      }
    }
    if (start < 0) start = 0;
    for (int j = start + 1; j < start + m; ++j) count_interior(s, edge(j));
    s.end_values[0] = across(t, ch, corner(start), edge(start));
    s.end_values[1] = across(t, ch, corner(start - 1), edge(start));
    return spans;
  }
  // Walk the runs: from a change of value on an interior ring, from the
  // first corner on a boundary ring.
  int first = 0;
  if (interior) {
    while (first < k && sibling(first) == sibling(first - 1 + (first == 0 ? k : 0))) ++first;
    if (first == k) first = 0;
  }
  std::vector<char> seen(values.size(), 0);
  for (int j = first; j < first + k;) {
    const std::size_t s_index = sibling(j % k);
    Span& s = spans[s_index];
    if (seen[s_index]) ++s.disjoint;
    seen[s_index] = 1;
    const int run_start = j;
    s.interior.clear();
    while (j + 1 < first + k && sibling((j + 1) % k) == s_index) {
      count_interior(s, edge(j + 1));
      ++j;
    }
    ++j;
    s.size += j - run_start;
    s.end_values[0] = across(t, ch, corner(run_start), edge(run_start));
    s.end_values[1] = across(t, ch, corner(j - 1), edge(j));
  }
  return spans;
}

// The spans of a vertex whose ring is not ordered (a non-manifold vertex,
// or the edge point of a non-manifold seam): only the far values of each
// value's two bounding edges, those of its faces' edges at v that no other
// of its faces shares; a value with more or fewer is left without them.
std::vector<Span> unordered_spans(const MeshTopology& t, const FaceVaryingChannel& ch, Index v,
                                  std::span<const Index> values) {
  std::vector<Span> spans(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::vector<std::pair<Index, Index>> sides;  // (edge at v, its far value in that face)
    for (const Index c : t.vertex_corners(v)) {
      if (ch.indices[at(c)] != values[i]) continue;
      ++spans[i].size;
      const Index out_edge = t.corner_edge(c), in_edge = t.corner_edge(t.corner_prev(c));
      sides.emplace_back(out_edge, ch.indices[at(t.corner_next(c))]);
      sides.emplace_back(in_edge, ch.indices[at(t.corner_prev(c))]);
    }
    std::vector<Index> ends;
    for (const auto& [e, value] : sides) {
      const auto n = std::count_if(sides.begin(), sides.end(), [e = e](const auto& s) { return s.first == e; });
      if (n == 1) ends.push_back(value);
    }
    if (ends.size() == 2) std::copy(ends.begin(), ends.end(), spans[i].end_values);
  }
  return spans;
}

// Reclassifies the child tags of vertex v's values whose semi-sharp
// features decay (Vtr::FVarRefinement::reclassifySemisharpValues):
// `child_tag(i)` is the tag of the child of v's value i, spans[i] its span.
template <typename ChildTag>
void reclassify_semi_sharp(const MeshTopology& t, const LevelCreasing& creasing, Index v, double vertex_sharpness,
                           const std::vector<Span>& spans, bool dependent, ChildTag&& child_tag) {
  auto child_sharpness = [&](Index e) { return child_sharpness_of(creasing, e, t.edge_vertices(e)[0] == v ? 0 : 1); };
  bool parent_semi = is_semi_sharp(vertex_sharpness), child_semi_edges = false;
  for (const Index e : t.vertex_edges(v)) {
    parent_semi |= is_semi_sharp(edge_sharpness_of(creasing, e));
    child_semi_edges |= is_semi_sharp(child_sharpness(e));
  }
  if (!parent_semi || subdivide_sharpness(vertex_sharpness) > 0.0) return;  // nothing decays yet
  const ValueTag crease{.mismatch = true, .crease = true};
  for (std::size_t i = 0; i < spans.size(); ++i) {
    ValueTag& tag = child_tag(i);
    if (!tag.semi_sharp) continue;
    if (!child_semi_edges) {
      tag = crease;
      continue;
    }
    if (tag.dep_sharp) continue;
    bool still = false;
    for (const Index e : spans[i].interior) still |= is_semi_sharp(child_sharpness(e));
    if (!still) tag = crease;
  }
  if (child_semi_edges && dependent && spans.size() == 2) {
    ValueTag& a = child_tag(0);
    ValueTag& b = child_tag(1);
    if (a.dep_sharp && !b.semi_sharp) a.dep_sharp = false;
    else if (b.dep_sharp && !a.semi_sharp) b.dep_sharp = false;
  }
}

// Each vertex's distinct values, in ring order of first appearance.
struct VertexValues {
  std::vector<Index> offsets;  // per vertex, into `values`
  std::vector<Index> values;
  std::span<const Index> of(Index v) const {
    return {values.data() + offsets[at(v)], static_cast<std::size_t>(offsets[at(v) + 1] - offsets[at(v)])};
  }
};

VertexValues vertex_values(const MeshTopology& t, const FaceVaryingChannel& ch) {
  VertexValues out;
  out.offsets.assign(at(t.vertex_count()) + 1, 0);
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const std::size_t begin = out.values.size();
    for (const Index c : t.vertex_corners(v)) {
      const Index value = ch.indices[at(c)];
      if (std::find(out.values.begin() + static_cast<std::ptrdiff_t>(begin), out.values.end(), value) ==
          out.values.end())
        out.values.push_back(value);
    }
    out.offsets[at(v) + 1] = static_cast<Index>(out.values.size());
  }
  return out;
}

// The channel with a value of its own per region ("sibling") of each vertex:
// the same numbers, so that each value belongs to one vertex. Regions are
// OpenSubdiv's (Vtr::FVarLevel::completeTopologyFromFaceValues): walking
// the faces around the vertex, a face continues its predecessor's region
// when it has the same value; otherwise it joins the region of an earlier
// face with its value, except that while two regions exist a value other
// than the first region's always opens a third. So values A, B, A, B around
// a vertex make regions A, B, A, B': the two runs of B are separate regions
// and the two runs of A one region, disjoint (a corner).
FaceVaryingChannel unique_per_vertex(const MeshTopology& t, const FaceVaryingChannel& in) {
  FaceVaryingChannel out{in.name, in.components, {}, std::vector<Index>(in.indices.size())};
  const auto k = static_cast<std::size_t>(in.components);
  std::vector<Index> region_values, region_made;  // per region of the current vertex
  for (Index v = 0; v < t.vertex_count(); ++v) {
    region_values.clear();
    region_made.clear();
    Index previous_value = kInvalidIndex, previous_region = kInvalidIndex;
    for (const Index c : t.vertex_corners(v)) {
      const Index value = in.indices[at(c)];
      Index region = previous_region;
      if (value != previous_value) {
        const bool opens = region_values.size() == 1 || (region_values.size() == 2 && region_values[0] != value);
        const auto found = std::find(region_values.begin(), region_values.end(), value);
        if (opens || found == region_values.end()) {
          region = static_cast<Index>(region_values.size());
          region_values.push_back(value);
          region_made.push_back(static_cast<Index>(out.values.size() / k));
          out.values.insert(out.values.end(), value_of(in, value), value_of(in, value) + k);
        } else {
          region = static_cast<Index>(found - region_values.begin());
        }
      }
      out.indices[at(c)] = region_made[at(region)];
      previous_value = value;
      previous_region = region;
    }
  }
  return out;
}

// The control mesh's edge tags and value tags
// (Vtr::FVarLevel::completeTopologyFromFaceValues).
void analyse(const MeshTopology& t, const FaceVaryingChannel& ch, const LevelCreasing& creasing,
             std::span<const double> vertex_sharpness, const Options& o, std::vector<std::uint8_t>& edge_tags,
             std::vector<ValueTag>& tags) {
  const Index nv = t.vertex_count();
  edge_tags.assign(at(t.edge_count()), 0);
  tags.assign(at(ch.value_count()), ValueTag{});
  const VertexValues vv = vertex_values(t, ch);
  std::vector<char> mismatch(at(nv), 0);
  auto mark_seam = [&](Index e) {
    const auto [a, b] = t.edge_vertices(e);
    mismatch[at(a)] = mismatch[at(b)] = 1;
    edge_tags[at(e)] = kEdgeMismatch | (o.linear_boundaries ? kEdgeLinear : 0);
  };
  // In vertex order, as OpenSubdiv: a boundary vertex's own test below sees
  // only the seams found so far.
  for (Index v = 0; v < nv; ++v) {
    const auto corners = t.vertex_corners(v);
    if (corners.empty()) continue;
    const auto edges = t.vertex_edges(v);
    const bool ordered = t.ring_ordered(v);
    bool boundary = false;
    for (const Index e : edges) boundary |= t.is_boundary_edge(e);
    if (ordered) {
      const auto k = static_cast<int>(corners.size());
      for (int j = boundary ? 1 : 0; j < k; ++j) {
        const Index prev = corners[static_cast<std::size_t>(j == 0 ? k - 1 : j - 1)];
        if (ch.indices[at(corners[static_cast<std::size_t>(j)])] != ch.indices[at(prev)])
          mark_seam(edges[static_cast<std::size_t>(j)]);
      }
    } else {
      for (const Index e : edges) {
        const auto sides = t.edge_corners(e);
        if (sides.size() < 2) continue;
        Index first = kInvalidIndex;
        bool seam = false;
        for (const Index c : sides) {
          const Index at_v = t.corner_vertex(c) == v ? c : t.corner_next(c);
          const Index value = ch.indices[at(at_v)];
          if (first == kInvalidIndex) first = value;
          else seam |= value != first;
        }
        if (seam) mark_seam(e);
      }
    }
    if (boundary && !mismatch[at(v)]) {
      if (o.linear_boundaries) {
        mismatch[at(v)] = 1;
        for (const Index e : edges)
          if (t.is_boundary_edge(e)) edge_tags[at(e)] |= kEdgeLinear;
      } else if (corners.size() == 1 && o.sharpen_one_face_boundary) {
        mismatch[at(v)] = 1;
      }
    }
    if (!ordered && vv.of(v).size() > 1) mismatch[at(v)] = 1;
  }

  for (Index v = 0; v < nv; ++v) {
    if (!mismatch[at(v)]) continue;
    const auto values = vv.of(v);
    const double vs = vertex_sharpness[at(v)];
    const bool ordered = t.ring_ordered(v);
    bool boundary = false;
    for (const Index e : t.vertex_edges(v)) boundary |= t.is_boundary_edge(e);
    bool all_corners = o.linear_boundaries || is_infinite(vs) || !ordered || (o.dependent && values.size() > 2) ||
                       (o.sharpen_darts && values.size() == 1 && !boundary);
    if (!ordered) {
      for (const Index value : values) tags[at(value)] = {.mismatch = true};
      continue;
    }
    const std::vector<Span> spans = spans_at(t, ch, creasing, edge_tags, v, values);
    bool sharpen_dependents = false;
    if (!all_corners && o.dependent && values.size() == 2) {
      all_corners = spans[0].infinite || spans[1].infinite || spans[0].disjoint || spans[1].disjoint;
      if (o.both_if_one_corner) all_corners |= spans[0].size == 1 || spans[1].size == 1;
      sharpen_dependents = (spans[0].semi > 0) != (spans[1].semi > 0);
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
      ValueTag& tag = tags[at(values[i])];
      tag = {.mismatch = true};
      const Span& s = spans[i];
      if (s.disjoint) continue;  // a corner
      const bool infinitely_sharp = all_corners || s.infinite || (s.size == 1 && o.corners_sharp);
      if (infinitely_sharp) continue;
      if (s.semi || is_semi_sharp(vs)) tag.semi_sharp = true;
      else if (sharpen_dependents) tag.semi_sharp = tag.dep_sharp = true;
      else tag.crease = true;
    }
  }
}

// The value of vertex w around an anchor: in the first of `corners`' faces
// that holds w, at the corner next to the anchor's where the face holds w
// twice (a face repeating a vertex); else, for a mask reaching further, w's
// first value.
Index value_near(const MeshTopology& t, const FaceVaryingChannel& ch, std::span<const Index> corners, Index w) {
  for (const Index c : corners) {
    if (t.corner_vertex(t.corner_next(c)) == w) return ch.indices[at(t.corner_next(c))];
    if (t.corner_vertex(t.corner_prev(c)) == w) return ch.indices[at(t.corner_prev(c))];
    const Index f = t.corner_face(c);
    const Index first = t.face_first_corner(f), n = t.face_size(f);
    for (Index d = first; d < first + n; ++d)
      if (t.corner_vertex(d) == w) return ch.indices[at(d)];
  }
  return ch.indices[at(t.vertex_corners(w).front())];
}

void add_weighted(const FaceVaryingChannel& ch, Index value, double w, double* out) {
  const double* src = value_of(ch, value);
  for (int j = 0; j < ch.components; ++j) out[j] += w * src[j];
}

}  // namespace

bool FaceVaryingRefiner::applies(const Scheme& scheme, FaceVaryingInterpolation mode) noexcept {
  return mode != FaceVaryingInterpolation::all && scheme.traits.smooth_face_varying &&
         (scheme.split == SplitRule::quad || scheme.split == SplitRule::triangle) && !scheme.steps;
}

FaceVaryingRefiner::FaceVaryingRefiner(FaceVaryingInterpolation mode, BoundaryInterpolation boundary)
    : mode_(mode), boundary_(boundary) {}

void FaceVaryingRefiner::refine(const PolygonMesh& parent, const MeshTopology& t, const LevelCreasing& creasing,
                                const SplitMap& map, const ChildMask& mask_of, PolygonMesh& child) {
  const Options o = options_for(mode_, boundary_);
  const std::vector<double> sharpness = vertex_sharpness(parent, t, boundary_, creasing);
  const bool first_level = !started_;
  if (first_level) channels_.assign(parent.face_varying_channels.size(), ChannelState{});
  const bool quads = map.rule == SplitRule::quad;
  MaskBuilder mask;

  for (std::size_t ci = 0; ci < parent.face_varying_channels.size(); ++ci) {
    ChannelState& state = channels_[ci];
    FaceVaryingChannel unique;
    std::vector<std::uint8_t> edge_tags;
    if (first_level) {
      unique = unique_per_vertex(t, parent.face_varying_channels[ci]);
      analyse(t, unique, creasing, sharpness, o, edge_tags, state.tags);
    } else {
      // Edge tags: a child edge inside a parent face matches; a half of a
      // parent edge inherits its tag (Vtr::FVarRefinement::propagateEdgeTags).
      edge_tags.assign(at(t.edge_count()), 0);
      for (Index e = 0; e < t.edge_count(); ++e) {
        auto [a, b] = t.edge_vertices(e);
        if (a > b) std::swap(a, b);
        if (a >= previous_map_.edge_points && a < previous_map_.vertex_points && b >= previous_map_.vertex_points)
          edge_tags[at(e)] = state.previous_edges[at(a - previous_map_.edge_points)];
      }
    }
    const FaceVaryingChannel& in = first_level ? unique : parent.face_varying_channels[ci];
    const auto k = static_cast<std::size_t>(in.components);
    const VertexValues vv = vertex_values(t, in);

    // Child values: one per parent face (quads), one per edge or one per
    // edge side where the edge is a seam, one per parent value.
    const Index face_values = quads ? t.face_count() : 0;
    std::vector<Index> edge_first(at(t.edge_count()) + 1, 0);
    for (Index e = 0; e < t.edge_count(); ++e)
      edge_first[at(e) + 1] =
          edge_first[at(e)] + ((edge_tags[at(e)] & kEdgeMismatch) ? t.edge_face_count(e) : 1);
    const Index vertex_first = face_values + edge_first.back();
    const Index child_count = vertex_first + in.value_count();
    FaceVaryingChannel out{in.name, in.components, std::vector<double>(at(child_count) * k, 0.0), {}};
    std::vector<ValueTag> child_tags(at(child_count));
    auto edge_value = [&](Index c) {  // corner c's edge point, on c's side
      const Index e = t.corner_edge(c);
      if (!(edge_tags[at(e)] & kEdgeMismatch)) return face_values + edge_first[at(e)];
      const auto sides = t.edge_corners(e);
      const auto j = std::find(sides.begin(), sides.end(), c) - sides.begin();
      return face_values + edge_first[at(e)] + static_cast<Index>(j);
    };
    auto child_value = [&](Index parent_value) { return vertex_first + parent_value; };
    double* dst = out.values.data();

    // Face points: the face's average.
    for (Index f = 0; f < face_values; ++f) {
      const Index first = t.face_first_corner(f), n = t.face_size(f);
      for (Index c = first; c < first + n; ++c) add_weighted(in, in.indices[at(c)], 1.0 / n, dst + at(f) * k);
    }
    // A mask read on one side of the channel: parent vertices through
    // `near` (their value around the anchor), new points through the child.
    auto apply = [&](Index target, std::span<const Index> near, Index anchor_vertex, Index anchor_value) {
      double* p = dst + at(target) * k;
      const auto vs = mask.vertices();
      const auto ws = mask.weights();
      for (std::size_t j = 0; j < vs.size(); ++j)
        add_weighted(in, vs[j] == anchor_vertex ? anchor_value : value_near(t, in, near, vs[j]), ws[j], p);
      const auto fs = mask.face_points();
      const auto fws = mask.face_point_weights();
      for (std::size_t j = 0; j < fs.size(); ++j) add_weighted(out, fs[j], fws[j], p);
      const auto es = mask.edge_points();
      const auto ews = mask.edge_point_weights();
      for (std::size_t j = 0; j < es.size(); ++j)
        add_weighted(out, face_values + edge_first[at(es[j])], ews[j], p);
    };
    // Edge points: the scheme's mask where the edge is no seam, else the
    // midpoint on each side.
    const ValueTag split_tag{.mismatch = true, .crease = !o.linear_boundaries};
    for (Index e = 0; e < t.edge_count(); ++e) {
      const auto sides = t.edge_corners(e);
      const Index first = face_values + edge_first[at(e)];
      const Index count = edge_first[at(e) + 1] - edge_first[at(e)];
      const bool split = edge_tags[at(e)] & (kEdgeMismatch | kEdgeLinear);
      for (Index j = 0; j < count; ++j) child_tags[at(first + j)] = split ? split_tag : ValueTag{};
      if (!split) {
        mask_of(map.edge_point(e), mask);
        apply(first, sides, kInvalidIndex, kInvalidIndex);
        continue;
      }
      for (Index j = 0; j < count; ++j) {
        const Index c = sides[at(j)];
        double* p = dst + at(first + j) * k;
        add_weighted(in, in.indices[at(c)], 0.5, p);
        add_weighted(in, in.indices[at(t.corner_next(c))], 0.5, p);
      }
    }
    // Vertex points.
    for (Index v = 0; v < t.vertex_count(); ++v) {
      const auto values = vv.of(v);
      if (values.empty()) continue;
      for (const Index value : values) child_tags[at(child_value(value))] = state.tags[at(value)];
      if (!state.tags[at(values[0])].mismatch) {
        mask_of(map.vertex_point(v), mask);
        apply(child_value(values[0]), t.vertex_corners(v), v, values[0]);
        continue;
      }
      const std::vector<Span> spans = t.ring_ordered(v) ? spans_at(t, in, creasing, edge_tags, v, values)
                                                        : unordered_spans(t, in, v, values);
      // Semi-sharp values become creases once their features decay
      // (Vtr::FVarRefinement::reclassifySemisharpValues).
      if (!o.linear_boundaries) reclassify_semi_sharp(t, creasing, v, sharpness[at(v)], spans, o.dependent,
                                                      [&](std::size_t i) -> ValueTag& {
                                                        return child_tags[at(child_value(values[i]))];
                                                      });
      for (std::size_t i = 0; i < values.size(); ++i) {
        const Index value = values[i];
        double* p = dst + at(child_value(value)) * k;
        if (!child_tags[at(child_value(value))].crease || spans[i].end_values[0] == kInvalidIndex) {
          // a corner, or semi-sharp still
          add_weighted(in, value, 1.0, p);
          continue;
        }
        double vertex_weight = 0.75, end_weight = 0.125;
        const ValueTag& parent_tag = state.tags[at(value)];
        if (parent_tag.semi_sharp) {
          const Span& s = parent_tag.dep_sharp && values.size() == 2 ? spans[1 - i] : spans[i];
          const double w = decay_weight(t, creasing, v, sharpness[at(v)], s.interior);
          vertex_weight = (1.0 - w) * 0.75 + w;
          end_weight = (1.0 - w) * 0.125;
        }
        add_weighted(in, spans[i].end_values[0], end_weight, p);
        add_weighted(in, spans[i].end_values[1], end_weight, p);
        add_weighted(in, value, vertex_weight, p);
      }
    }

    // Child corners, in the split's face layout (quad_split.cpp,
    // triangle_split.cpp).
    out.indices.resize(child.face_indices.size());
    if (quads) {
      for (Index c = 0; c < t.corner_count(); ++c) {
        Index* q = out.indices.data() + 4 * at(c);
        q[0] = child_value(in.indices[at(c)]);
        q[1] = edge_value(c);
        q[2] = t.corner_face(c);
        q[3] = edge_value(t.corner_prev(c));
      }
    } else {
      for (Index f = 0; f < t.face_count(); ++f) {
        const Index c0 = 3 * f, c1 = c0 + 1, c2 = c0 + 2;
        const Index m0 = edge_value(c0), m1 = edge_value(c1), m2 = edge_value(c2);
        const Index tri[12] = {child_value(in.indices[at(c0)]), m0, m2, child_value(in.indices[at(c1)]), m1, m0,
                               child_value(in.indices[at(c2)]), m2, m1, m0, m1, m2};
        std::copy(tri, tri + 12, out.indices.begin() + 12 * static_cast<std::ptrdiff_t>(f));
      }
    }
    child.face_varying_channels[ci] = std::move(out);
    state.tags = std::move(child_tags);
    state.previous_edges = std::move(edge_tags);
  }
  started_ = true;
  previous_map_ = map;
}

}  // namespace subdiv::detail
