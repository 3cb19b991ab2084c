// Exact limit evaluation: construction walks each ptex face down the
// uniform refinement until every face below it is a regular patch or has
// one extraordinary corner whose face ring matches the model of its
// configuration (isolation), and records those patches with their frames;
// evaluation finds the patch holding (u, v) and applies its basis.

#include "subdiv/eval/limit_evaluator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "subdiv/core/error.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"
#include "../analysis/closed_form_limit.h"
#include "../analysis/extraordinary_patch.h"
#include "../analysis/patch_basis.h"
#include "../analysis/patch_points.h"
#include "patch_frame.h"
#include "refined_surface.h"

namespace subdiv {

namespace {

// Isolation needs two levels on a mesh without semi-sharp features (one
// makes every Catmull-Clark face a quad, the next separates extraordinary
// vertices), up to six near semi-sharp ones (kMaxSemiSharpness); more
// means a small mesh whose patches reach a vertex twice.
constexpr int kMaxIsolationLevels = 6;

// The largest finite sharpness isolated: a semi-sharp feature decays one
// level at a time, and its faces become patches a level after it has.
constexpr double kMaxSemiSharpness = 4.0;

// The largest coordinate taken: patches sum and difference control points
// with weights of a few units, phantom points reflect them (2 p - q), so
// coordinates near the double range would overflow.
constexpr double kMaxCoordinate = 1e300;

// How far outside a ptex face a parameter may lie and still be taken (as
// the nearest point of the face).
constexpr double kDomainSlack = 1e-12;

std::string face_name(Index face) { return "face " + std::to_string(face); }

}  // namespace

/// Walks the hierarchy and fills the evaluator's patches.
class LimitEvaluator::Builder {
 public:
  Builder(LimitEvaluator& out, const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options)
      : out_(out), scheme_(scheme), options_(options) {
    options_.levels = 0;
    options_.start_level = 0;
    hierarchy_ = refine_hierarchy(mesh, scheme, options_, KeepLevels::all);
  }
  // Approximate evaluation: every ptex face down to the last level of
  // `refined`, each face there an interpolant of its corners' limits.
  Builder(LimitEvaluator& out, detail::RefinedSurface&& refined, const Scheme& scheme, const RefineOptions& options)
      : out_(out), scheme_(scheme), options_(options), hierarchy_(std::move(refined.hierarchy)) {
    options_.levels = 0;
    options_.start_level = 0;
    linear_level_ = static_cast<int>(hierarchy_.levels.size()) - 1;
    last_normals_ = std::move(refined.normals);
  }

  void build() {
    const MeshTopology& coarse = topology(0);
    const Index regular_size = out_.triangles_ ? 3 : 4;
    out_.face_ptex_.assign(1, 0);
    out_.ptex_leaves_.assign(1, 0);
    for (Index f = 0; f < coarse.face_count(); ++f) {
      const Index n = coarse.face_size(f);
      if (n == regular_size) {
        add_ptex(0, f);
      } else {  // a Catmull-Clark n-gon: its sub-faces, child face = parent corner
        for (Index k = 0; k < n; ++k) add_ptex(1, coarse.face_first_corner(f) + k);
      }
      out_.face_ptex_.push_back(static_cast<Index>(out_.ptex_leaves_.size()) - 1);
    }
    // Control points were recorded per level: shift them into positions_.
    std::vector<std::size_t> offset(hierarchy_.levels.size());
    for (std::size_t l = 0; l < hierarchy_.levels.size(); ++l) {
      offset[l] = out_.positions_.size();
      const auto& p = hierarchy_.levels[l].mesh.positions;
      out_.positions_.insert(out_.positions_.end(), p.begin(), p.end());
    }
    // Phantom points (reflections across sharp edges) follow, recorded as
    // -1 - their number.
    const auto phantom_offset = static_cast<Index>(out_.positions_.size());
    out_.positions_.insert(out_.positions_.end(), phantoms_.begin(), phantoms_.end());
    if (linear_level_ >= 0) {  // the last level's limit normals, by position index
      out_.normals_.assign(out_.positions_.size(), Vec3{});
      std::copy(last_normals_.begin(), last_normals_.end(),
                out_.normals_.begin() + static_cast<std::ptrdiff_t>(offset[static_cast<std::size_t>(linear_level_)]));
    }
    for (std::size_t i = 0; i < out_.leaves_.size(); ++i) {
      const std::size_t end = i + 1 < out_.leaves_.size() ? out_.leaves_[i + 1].first_control : out_.control_.size();
      for (std::size_t c = out_.leaves_[i].first_control; c < end; ++c) {
        Index& index = out_.control_[c];
        index = index < 0 ? phantom_offset + (-1 - index)
                          : index + static_cast<Index>(offset[static_cast<std::size_t>(leaf_level_[i])]);
      }
    }
    out_.isolation_levels_ = static_cast<int>(hierarchy_.levels.size()) - 1;
  }

 private:
  void add_ptex(int level, Index face) {
    add_leaves(level, face, Frame{});
    out_.ptex_leaves_.push_back(static_cast<Index>(out_.leaves_.size()));
  }

  const MeshTopology& topology(int level) {
    while (static_cast<int>(hierarchy_.levels.size()) <= level) {
      if (static_cast<int>(hierarchy_.levels.size()) > kMaxIsolationLevels)
        throw InvalidInputError("limit evaluation: the mesh's extraordinary vertices are not isolated after " +
                                std::to_string(kMaxIsolationLevels) + " levels");
      refine_further(hierarchy_, scheme_, 1, options_, KeepLevels::all);
    }
    while (static_cast<int>(topologies_.size()) <= level)
      topologies_.push_back(std::make_unique<MeshTopology>(hierarchy_.levels[topologies_.size()].mesh));
    return *topologies_[static_cast<std::size_t>(level)];
  }

  // The level's creasing (boundaries and crease tags), computed once.
  const LevelCreasing& creasing(int level) {
    const MeshTopology& t = topology(level);
    while (static_cast<int>(creasings_.size()) <= level) creasings_.emplace_back();
    auto& slot = creasings_[static_cast<std::size_t>(level)];
    if (!slot) {
      const PolygonMesh& mesh = hierarchy_.levels[static_cast<std::size_t>(level)].mesh;
      slot = std::make_unique<LevelCreasing>(
          compute_creasing(mesh, t, boundary_of(mesh, options_), crease_method_of(mesh, options_)));
    }
    return *slot;
  }

  // The smooth rule and no sharp edge around v.
  bool is_smooth_vertex(int level, Index v) {
    const LevelCreasing& c = creasing(level);
    if (c.vertex_rule[static_cast<std::size_t>(v)] != VertexRule::smooth) return false;
    for (const Index e : topology(level).vertex_edges(v))
      if (edge_sharpness_of(c, e) > 0.0) return false;
    return true;
  }

  // An extraordinary corner's model.
  struct Model {
    Configuration configuration;
    int position = 0;
    bool dart = false;
  };

  // A model per configuration kind (darts apart), valence or face count,
  // and place of the face.
  const ExtraordinaryPatch& model(const Model& m) {
    auto& slot = out_.patches_[{m.dart ? -1 : static_cast<int>(m.configuration.kind), m.configuration.k, m.position}];
    if (!slot)
      slot = std::make_unique<ExtraordinaryPatch>(out_.triangles_ ? SplitRule::triangle : SplitRule::quad,
                                                  m.configuration, m.position, m.dart, &scheme_);
    return *slot;
  }

  // The model of the extraordinary corner `corner` (its vertex's and its
  // face's place): a smooth interior vertex; a dart (one infinitely sharp
  // edge), the face counted from it; or the sector between sharp edges
  // (boundaries, infinitely sharp creases) that holds the face, at a vertex
  // with the crease rule (a boundary sector's model) or the corner rule (a
  // corner sector's). None near semi-sharp features, which isolation
  // resolves first.
  std::optional<Model> model_at(int level, Index corner) {
    const MeshTopology& t = topology(level);
    const Index v = t.corner_vertex(corner);
    if (t.vertex_kind(v) == VertexKind::interior && is_smooth_vertex(level, v))
      return Model{Configuration{Configuration::Kind::interior, static_cast<int>(t.valence(v))}, 0, false};
    const LevelCreasing& c = creasing(level);
    const VertexRule rule = c.vertex_rule[static_cast<std::size_t>(v)];
    if (rule == VertexRule::smooth || rule != c.child_vertex_rule[static_cast<std::size_t>(v)]) return std::nullopt;
    for (const Index e : t.vertex_edges(v)) {
      const double sharpness = edge_sharpness_of(c, e);
      if (sharpness > 0.0 && sharpness < kInfiniteSharpness) return std::nullopt;
    }
    const auto sector = sector_corners(topology(level), creasing(level), corner);
    if (!sector) return std::nullopt;
    const auto position = static_cast<int>(std::find(sector->begin(), sector->end(), corner) - sector->begin());
    if (rule == VertexRule::dart) {
      if (t.vertex_kind(v) != VertexKind::interior) return std::nullopt;
      return Model{Configuration{Configuration::Kind::interior, static_cast<int>(t.valence(v))}, position, true};
    }
    return Model{Configuration{rule == VertexRule::crease ? Configuration::Kind::boundary : Configuration::Kind::corner,
                               static_cast<int>(sector->size())},
                 position, false};
  }

  void add_leaf(int level, const Frame& frame, const ExtraordinaryPatch* patch, std::span<const Index> points,
                Vec3 corner_normal = {}) {
    out_.leaves_.push_back({frame, detail::inverse_of(frame), patch, out_.control_.size(), corner_normal});
    out_.control_.insert(out_.control_.end(), points.begin(), points.end());
    leaf_level_.push_back(level);
  }

  // The patches of `face` on `level`, whose corner 0 is at frame.origin;
  // approximate evaluation: the faces below it on the last level.
  void add_leaves(int level, Index face, const Frame& frame) {
    const MeshTopology& t = topology(level);
    if (linear_level_ >= 0) {
      if (level == linear_level_) return add_leaf(level, frame, nullptr, t.face_vertices(face));
    } else if (add_patch(level, face, frame)) {
      return;
    }
    const Index first = t.face_first_corner(face);
    if (out_.triangles_) {
      for (int k = 0; k < 4; ++k) add_leaves(level + 1, 4 * face + k, detail::triangle_child_frame(frame, k));
    } else {  // a quad here: only the coarse level has other faces, and those are ptex sub-faces
      for (int k = 0; k < 4; ++k) add_leaves(level + 1, first + k, detail::quad_child_frame(frame, k));
    }
  }

  // The patch of `face` on `level` where it is one: a regular patch or one
  // extraordinary corner whose model applies.
  bool add_patch(int level, Index face, const Frame& frame) {
    const MeshTopology& t = topology(level);
    const Index size = out_.triangles_ ? 3 : 4;
    if (t.face_size(face) == size) {
      const Index first = t.face_first_corner(face);
      if (out_.triangles_) {
        if (const auto stencils = box_spline_patch_stencils(t, creasing(level), first)) {
          add_leaf(level, frame, nullptr, control_points(level, std::span<const PatchStencil>(*stencils)));
          return true;
        }
      } else if (const auto stencils = bicubic_patch_stencils(t, creasing(level), first)) {
        add_leaf(level, frame, nullptr, control_points(level, std::span<const PatchStencil>(*stencils)));
        return true;
      }
      // One extraordinary corner, the others regular: its model's patch.
      int irregular = 0;
      Index corner = first;
      for (Index k = 0; k < size; ++k) {
        const bool regular = out_.triangles_ ? is_regular_box_spline_corner(t, creasing(level), first + k)
                                             : is_regular_patch_corner(t, creasing(level), first + k);
        if (!regular) {
          ++irregular;
          corner = first + k;
        }
      }
      const auto m = irregular == 1 ? model_at(level, corner) : std::nullopt;
      if (m) {
        const ExtraordinaryPatch& patch = model(*m);
        const auto ring = face_ring(t, corner, &creasing(level));
        if (ring && ring->signature == patch.signature()) {
          add_leaf(level, detail::frame_at_corner(frame, static_cast<int>(corner - first), out_.triangles_), &patch,
                   ring->vertices, corner_normal(level, corner));
          return true;
        }
      }
    }
    return false;
  }

  // The patch's control points: its vertices (level-local indices), and
  // each phantom point as a new point (-1 - its number, see build()).
  std::vector<Index> control_points(int level, std::span<const PatchStencil> stencils) {
    const std::vector<Vec3>& positions = hierarchy_.levels[static_cast<std::size_t>(level)].mesh.positions;
    std::vector<Index> points;
    points.reserve(stencils.size());
    for (const PatchStencil& p : stencils) {
      if (p.size == 1) {
        points.push_back(p.vertex[0]);
        continue;
      }
      Vec3 phantom{};
      for (int i = 0; i < p.size; ++i)
        phantom += p.weight[static_cast<std::size_t>(i)] * positions[static_cast<std::size_t>(p.vertex[static_cast<std::size_t>(i)])];
      points.push_back(-1 - static_cast<Index>(phantoms_.size()));
      phantoms_.push_back(phantom);
    }
    return points;
  }

  // The unit normal at an extraordinary corner, from the scheme's tangent
  // masks (a dart's are the smooth ones); in a sector, those of the sector
  // alone (each side of a crease has its own normal).
  Vec3 corner_normal(int level, Index corner) {
    const MeshTopology& t = topology(level);
    const PolygonMesh& mesh = hierarchy_.levels[static_cast<std::size_t>(level)].mesh;
    const Index vertex = t.corner_vertex(corner);
    const VertexRule rule = creasing(level).vertex_rule[static_cast<std::size_t>(vertex)];
    LimitMasks scratch;
    std::optional<detail::VertexLimit> limit;
    if (t.vertex_kind(vertex) == VertexKind::interior && (rule == VertexRule::smooth || rule == VertexRule::dart)) {
      // Read only: no vertex is semi-sharp where an extraordinary patch applies.
      if (semi_sharp_.size() < static_cast<std::size_t>(mesh.vertex_count()))
        semi_sharp_.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
      limit = detail::closed_form_limit(scheme_, detail::LimitLevel{t, creasing(level), mesh.positions, semi_sharp_},
                                        vertex, scratch);
    } else {
      limit = sector_limit(level, corner, scratch);
    }
    if (!limit) throw std::logic_error("limit evaluation: no tangent masks at an isolated extraordinary vertex");
    const Vec3 n = cross(limit->tangent1, limit->tangent2);
    const double length = norm(n);
    return length > 0.0 ? (1.0 / length) * n : Vec3{};
  }

  // The closed-form limit at `corner`'s vertex of its sector alone: the
  // sector's faces as a mesh of their own, the vertex on its boundary with
  // its rule (crease, or a corner tag).
  std::optional<detail::VertexLimit> sector_limit(int level, Index corner, LimitMasks& scratch) {
    const MeshTopology& t = topology(level);
    const PolygonMesh& mesh = hierarchy_.levels[static_cast<std::size_t>(level)].mesh;
    const Index vertex = t.corner_vertex(corner);
    PolygonMesh sector;
    std::vector<Index> local(static_cast<std::size_t>(mesh.vertex_count()), kInvalidIndex);
    const auto add = [&](Index v) {
      Index& slot = local[static_cast<std::size_t>(v)];
      if (slot == kInvalidIndex) {
        slot = static_cast<Index>(sector.positions.size());
        sector.positions.push_back(mesh.positions[static_cast<std::size_t>(v)]);
      }
      return slot;
    };
    const auto faces = sector_corners(topology(level), creasing(level), corner);
    if (!faces) throw std::logic_error("limit evaluation: an extraordinary corner's sector has no sharp edge");
    for (const Index c : *faces) {
      std::vector<Index> face;
      Index k = c;
      do {
        face.push_back(add(t.corner_vertex(k)));
        k = t.corner_next(k);
      } while (k != c);
      sector.add_face(face);
    }
    if (creasing(level).vertex_rule[static_cast<std::size_t>(vertex)] == VertexRule::corner)
      sector.tags.corners.push_back(
          {local[static_cast<std::size_t>(vertex)], kInfiniteSharpness, CornerType::unspecified, std::nullopt});
    const MeshTopology sector_topology(sector);
    const LevelCreasing sector_creasing =
        compute_creasing(sector, sector_topology, BoundaryInterpolation::edge_only, CreaseMethod::uniform);
    const std::vector<char> none(sector.positions.size(), 0);
    return detail::closed_form_limit(scheme_, detail::LimitLevel{sector_topology, sector_creasing, sector.positions, none},
                                     local[static_cast<std::size_t>(vertex)], scratch);
  }

  LimitEvaluator& out_;
  const Scheme& scheme_;
  RefineOptions options_;
  Hierarchy hierarchy_;
  std::vector<std::unique_ptr<MeshTopology>> topologies_;
  std::vector<int> leaf_level_;
  std::vector<std::unique_ptr<LevelCreasing>> creasings_;  // per level, when asked
  std::vector<Vec3> phantoms_;                              // phantom control points, in order
  std::vector<char> semi_sharp_;  // all zero
  int linear_level_ = -1;         // approximate evaluation: the level interpolated
  std::vector<Vec3> last_normals_;  // approximate evaluation: that level's limit normals
};

namespace {

// Sharp features: infinitely sharp edges (boundaries, creases) and corners
// split the faces around a vertex into sectors, each evaluated by its own
// patches; semi-sharp ones are isolated until they have decayed (up to
// kMaxSemiSharpness). The first feature outside that, as a reason.
std::optional<std::string> sharp_feature_refusal(const PolygonMesh& mesh, const MeshTopology& t,
                                                 const RefineOptions& options) {
  const LevelCreasing c = compute_creasing(mesh, t, boundary_of(mesh, options), crease_method_of(mesh, options));
  const auto semi_sharp_refusal = [](const std::string& what, double s) {
    return what + " has sharpness " + std::to_string(s) + "; exact evaluation isolates semi-sharp features up to " +
           "sharpness " + std::to_string(static_cast<int>(kMaxSemiSharpness));
  };
  for (Index e = 0; e < t.edge_count(); ++e) {
    const double s = edge_sharpness_of(c, e);
    if (s > kMaxSemiSharpness && s < kInfiniteSharpness) {
      const auto [a, b] = t.edge_vertices(e);
      return semi_sharp_refusal("edge " + std::to_string(a) + "-" + std::to_string(b), s);
    }
  }
  for (const CornerTag& corner : mesh.tags.corners)
    if (corner.sharpness > kMaxSemiSharpness && corner.sharpness < kInfiniteSharpness)
      return semi_sharp_refusal("the corner tag of vertex " + std::to_string(corner.vertex), corner.sharpness);
  // What stays once semi-sharp features have decayed: the infinitely sharp
  // edges and corner tags.
  std::vector<char> sharp_corner(static_cast<std::size_t>(t.vertex_count()), 0);
  for (const CornerTag& corner : mesh.tags.corners)
    if (corner.sharpness >= kInfiniteSharpness && corner.vertex >= 0 && corner.vertex < t.vertex_count())
      sharp_corner[static_cast<std::size_t>(corner.vertex)] = 1;
  for (Index v = 0; v < t.vertex_count(); ++v) {
    int sharp = 0;
    for (const Index e : t.vertex_edges(v)) sharp += edge_sharpness_of(c, e) >= kInfiniteSharpness ? 1 : 0;
    if (sharp < 2 && sharp_corner[static_cast<std::size_t>(v)])
      return "vertex " + std::to_string(v) + " is a corner where " + std::to_string(sharp) +
             " sharp edges meet; exact evaluation covers corners between two or more sharp edges";
  }
  return std::nullopt;
}

// What neither evaluation takes, as an error naming the element.
void check_common_scope(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options) {
  check_refinable(mesh, scheme, options);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3 p = mesh.positions[v];
    if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate)
      throw InvalidInputError("limit evaluation: vertex " + std::to_string(v) + " has a coordinate beyond 1e300, which "
                              "evaluation's sums and differences would overflow (scale the mesh down)");
  }
  if (!mesh.tags.holes.empty())
    throw InvalidInputError("limit evaluation: the mesh has hole tags, which evaluation does not cover yet");
  const MeshTopology t(mesh);
  for (Index v = 0; v < t.vertex_count(); ++v) {
    const VertexKind kind = t.vertex_kind(v);
    // (A vertex used by no face has no part in the surface.)
    if (kind != VertexKind::interior && kind != VertexKind::boundary && kind != VertexKind::isolated)
      throw InvalidInputError("limit evaluation: vertex " + std::to_string(v) + " is non-manifold");
  }
}

}  // namespace

std::optional<std::string> LimitEvaluator::exact_evaluation_unavailable(const PolygonMesh& mesh, const Scheme& scheme,
                                                                        const RefineOptions& options) {
  // The patches model these schemes' rules: regular patches of the bicubic
  // B-spline and of the box spline (Loop's and loop-warren's regular rules
  // are the same), models read off their own refinement.
  const std::string name(scheme.name), catmull_clark(catmull_clark_scheme().name), loop(loop_scheme().name),
      loop_warren(loop_warren_scheme().name);
  if (name != catmull_clark && name != loop && name != loop_warren)
    return name + " has no exact evaluator (" + catmull_clark + ", " + loop + " and " + loop_warren + " have)";
  const MeshTopology t(mesh);
  for (Index v = 0; v < t.vertex_count(); ++v)
    if (t.vertex_kind(v) == VertexKind::interior && t.valence(v) < 3)
      return "vertex " + std::to_string(v) + " has valence " + std::to_string(t.valence(v)) +
             "; exact evaluation covers interior vertices of valence 3 and more";
  return sharp_feature_refusal(mesh, t, options);
}

LimitEvaluator::LimitEvaluator(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options) {
  check_common_scope(mesh, scheme, options);
  if (const auto reason = exact_evaluation_unavailable(mesh, scheme, options))
    throw InvalidInputError("limit evaluation: " + *reason);
  triangles_ = scheme.split == SplitRule::triangle;
  Builder(*this, mesh, scheme, options).build();
}

LimitEvaluator LimitEvaluator::by_refinement(const PolygonMesh& mesh, const Scheme& scheme, double accuracy,
                                             const RefineOptions& options, int max_levels) {
  if (const auto reason = detail::refined_evaluation_unavailable(scheme))
    throw InvalidInputError("approximate evaluation: " + std::string(scheme.name) + ": " + *reason);
  check_common_scope(mesh, scheme, options);
  detail::RefinedSurface refined = detail::refine_to_accuracy(mesh, scheme, options, accuracy, max_levels);
  LimitEvaluator out;
  out.triangles_ = scheme.split == SplitRule::triangle;
  out.exact_ = false;
  out.measured_change_ = refined.measured_change;
  out.unresolved_vertices_ = refined.unresolved;
  Builder(out, std::move(refined), scheme, options).build();
  return out;
}

LimitEvaluator::~LimitEvaluator() noexcept = default;
LimitEvaluator::LimitEvaluator(LimitEvaluator&&) noexcept = default;
LimitEvaluator& LimitEvaluator::operator=(LimitEvaluator&&) noexcept = default;

Index LimitEvaluator::ptex_face_of(Index face) const {
  if (face < 0 || face >= static_cast<Index>(face_ptex_.size()) - 1)
    throw InvalidInputError("limit evaluation: " + face_name(face) + " is not a face of the mesh");
  return face_ptex_[static_cast<std::size_t>(face)];
}

void LimitEvaluator::check_location(Index face, double u, double v) const {
  if (face < 0 || face >= ptex_face_count())
    throw InvalidInputError("limit evaluation: ptex face " + std::to_string(face) + " is outside [0, " +
                            std::to_string(ptex_face_count()) + ")");
  // Written so that NaN fails too. Rounding slack: a parameter computed as
  // i / n + j / n can land an ulp outside; it is clamped onto the face.
  if (!(u >= -kDomainSlack && v >= -kDomainSlack && (triangles_ ? u + v : std::max(u, v)) <= 1.0 + kDomainSlack))
    throw InvalidInputError("limit evaluation: (" + std::to_string(u) + ", " + std::to_string(v) +
                            ") is outside ptex face " + std::to_string(face));
}

LimitPoint LimitEvaluator::evaluate(Index face, double u, double v) const {
  check_location(face, u, v);
  const auto first = static_cast<std::size_t>(ptex_leaves_[static_cast<std::size_t>(face)]);
  const auto last = static_cast<std::size_t>(ptex_leaves_[static_cast<std::size_t>(face) + 1]);
  if (!exact_) {
    const std::size_t leaf = leaf_by_descent(first, last - first, u, v);
    const detail::PatchParameter at =
        detail::clamp_into(detail::to_patch(leaves_[leaf].frame, leaves_[leaf].inverse, u, v), triangles_);
    LimitPoint point = evaluate_interpolant(leaves_[leaf], at.s, at.t);
    detail::to_ptex(leaves_[leaf].inverse, point);
    return point;
  }
  // The patch holding (u, v): the first one it lies in, else (rounding on
  // a shared edge) the nearest, with (s, t) clamped into it.
  std::size_t best = first;
  detail::PatchParameter best_at{};
  double best_outside = std::numeric_limits<double>::infinity();
  for (std::size_t i = first; i < last; ++i) {
    const detail::PatchParameter at = detail::to_patch(leaves_[i].frame, leaves_[i].inverse, u, v);
    const double outside = detail::distance_outside(at, triangles_);
    if (outside < best_outside) {
      best = i;
      best_at = at;
      best_outside = outside;
      if (outside == 0.0) break;
    }
  }
  const detail::PatchParameter at = detail::clamp_into(best_at, triangles_);
  LimitPoint point = evaluate_leaf(leaves_[best], at.s, at.t);
  detail::to_ptex(leaves_[best].inverse, point);
  return point;
}

LimitPoint LimitEvaluator::evaluate_leaf(const Leaf& leaf, double s, double t) const {
  const Index* control = control_.data() + leaf.first_control;
  const auto gather = [&](auto& points) {
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = positions_[static_cast<std::size_t>(control[i])];
  };
  PatchPoint q;
  if (leaf.extraordinary) {
    // One buffer per thread: no allocation per evaluation.
    thread_local std::vector<Vec3> ring;
    ring.resize(static_cast<std::size_t>(leaf.extraordinary->size()));
    gather(ring);
    q = leaf.extraordinary->evaluate(ring, s, t);
  } else if (triangles_) {
    std::array<Vec3, 12> points;
    gather(points);
    q = box_spline_point(points, s, t);
  } else {
    q = bicubic_bspline_point([&](std::size_t i) { return positions_[static_cast<std::size_t>(control[i])]; }, s, t);
  }
  LimitPoint p{q.position, q.du, q.dv, q.duu, q.duv, q.dvv, {}};
  if (leaf.extraordinary && s == 0.0 && t == 0.0) p.normal = leaf.corner_normal;
  return p;
}

std::size_t LimitEvaluator::leaf_by_descent(std::size_t first, std::size_t count, double u, double v) const {
  // The leaves of a ptex face are its 4^m faces m levels down, in the
  // builder's depth-first order of children: walk down, taking at each
  // level the child the point lies in (or is nearest, on a shared edge).
  Frame frame;
  std::size_t index = first;
  for (std::size_t below = count / 4; below >= 1; below /= 4) {
    int best = 0;
    Frame best_frame;
    double best_outside = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
      const Frame child = triangles_ ? detail::triangle_child_frame(frame, k) : detail::quad_child_frame(frame, k);
      const double outside =
          detail::distance_outside(detail::to_patch(child, detail::inverse_of(child), u, v), triangles_);
      if (outside < best_outside) {
        best = k;
        best_frame = child;
        best_outside = outside;
      }
    }
    index += static_cast<std::size_t>(best) * below;
    frame = best_frame;
  }
  return index;
}

LimitPoint LimitEvaluator::evaluate_interpolant(const Leaf& leaf, double s, double t) const {
  const Index* corner = control_.data() + leaf.first_control;
  const auto p = [&](int k) { return positions_[static_cast<std::size_t>(corner[k])]; };
  const auto n = [&](int k) { return normals_[static_cast<std::size_t>(corner[k])]; };
  LimitPoint out;
  Vec3 normal;
  if (triangles_) {  // linear: corners at (0, 0), (1, 0), (0, 1)
    const double w[3] = {1.0 - s - t, s, t};
    for (int k = 0; k < 3; ++k) {
      out.position += w[k] * p(k);
      normal += w[k] * n(k);
    }
    out.du = p(1) - p(0);
    out.dv = p(2) - p(0);
  } else {  // bilinear: corners at (0, 0), (1, 0), (1, 1), (0, 1)
    const double w[4] = {(1.0 - s) * (1.0 - t), s * (1.0 - t), s * t, (1.0 - s) * t};
    for (int k = 0; k < 4; ++k) {
      out.position += w[k] * p(k);
      normal += w[k] * n(k);
    }
    out.du = (1.0 - t) * (p(1) - p(0)) + t * (p(2) - p(3));
    out.dv = (1.0 - s) * (p(3) - p(0)) + s * (p(2) - p(1));
    out.duv = p(0) - p(1) + p(2) - p(3);
  }
  // The corners' limit normals interpolated; where one is missing (a
  // crease between sides) or they cancel, to_ptex() takes du x dv.
  bool all = true;
  for (int k = 0; k < (triangles_ ? 3 : 4); ++k) all = all && !(n(k) == Vec3{});
  const double length = norm(normal);
  if (all && length > 1e-3) out.normal = (1.0 / length) * normal;
  return out;
}

std::vector<LimitPoint> LimitEvaluator::evaluate(std::span<const SurfaceLocation> at) const {
  for (const SurfaceLocation& l : at) check_location(l.face, l.u, l.v);
  std::vector<LimitPoint> out(at.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, at.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) out[i] = evaluate(at[i].face, at[i].u, at[i].v);
  });
  return out;
}

}  // namespace subdiv
