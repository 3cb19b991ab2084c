#pragma once
/// \file
/// A subdivision scheme as a runtime value: its refinement rule and its masks.
/// A mask is a function from a local neighbourhood of the parent level to
/// weights over parent vertices (and, in quad splits, the level's new face
/// points: see MaskBuilder); masks never read or write positions. The same
/// masks feed the fast path (positions written directly) and recorded stencil
/// tables, so refinement and analysis share one code path.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/rules/limit_mask.h"
#include "subdiv/topology/split.h"

namespace subdiv {

struct CurveScheme;

/// Which rule makes a vertex point, from the sharp edges around the vertex
/// and its own sharpness: the survey's smooth, dart, crease and corner
/// vertices (section 3.2), decided as OpenSubdiv's Sdc::Crease does.
enum class VertexRule : std::uint8_t {
  smooth,  ///< no sharp edge
  dart,    ///< one sharp edge: the smooth rule
  crease,  ///< two sharp edges: the curve rule along them
  corner,  ///< three or more sharp edges, or a sharp vertex: kept in place
};

/// Which rule makes an edge point.
enum class EdgeRule : std::uint8_t {
  smooth,  ///< the scheme's smooth rule
  crease,  ///< the curve rule along a sharp edge
};

/// The rule's name.
/// \param rule the rule.
/// \return "smooth", "dart", "crease" or "corner", a static string.
const char* to_string(VertexRule rule) noexcept;

/// The weights of one smoothing operator B_{alpha,beta} of Chen and
/// Prautzsch's generalized Catmull-Clark schemes (2012, Figure 1.3): an
/// interior vertex v of valence m of a quad mesh becomes
///   alpha(m) v + beta(m)/m sum e_i + gamma(m)/m sum d_i,  gamma = 1 - alpha - beta,
/// e_i its edge neighbours, d_i the vertices opposite it in its quads.
struct SmoothingWeights {
  /// The weights at valences not listed in `valences`.
  enum class Rule {
    constant,       ///< alpha, beta below
    catmull_clark,  ///< Catmull-Clark's: alpha(m) = 1 - 3/m, beta(m) = 2/m
  };
  /// The weights at one valence, overriding the rule there.
  struct AtValence {
    int valence = 4;     ///< the interior valence m, >= 3
    double alpha = 0.25;  ///< alpha(m)
    double beta = 0.5;    ///< beta(m)
  };
  Rule rule = Rule::constant;  ///< the weights at valences not listed
  double alpha = 0.25;         ///< Rule::constant: alpha at every valence not listed
  double beta = 0.5;           ///< Rule::constant: beta at every valence not listed
  std::vector<AtValence> valences = {};  ///< per-valence overrides (the first entry for a valence applies)

  /// alpha(m) and beta(m): the entry of `valences` for m, else the rule's.
  /// \param m the interior valence.
  /// \return the pair (alpha(m), beta(m)).
  std::pair<double, double> at(int m) const noexcept;
};

/// The tension families (Butterfly, Kobbelt): the tension w. Butterfly's
/// 1/16 (Dyn, Levin and Gregory 1990) reproduces cubic polynomials on
/// regular meshes.
struct TensionParameters {
  double tension = 1.0 / 16.0;  ///< the tension w; must be finite (check_parameters())
};

/// Generalized Catmull-Clark schemes (rules/generalized_catmull_clark.h):
/// the degree n >= 2 and the smoothing operators B_1 .. B_r, r = (n - 1) / 2
/// rounded down: one entry for all of them, or r entries (none for n = 2).
/// Change the degree with set_degree(), which also sets the split.
struct DegreeParameters {
  int degree = 3;  ///< the degree n, >= 2
  /// The weights of B_1 .. B_r: one entry for all of them, or r entries.
  std::vector<SmoothingWeights> smoothing = {};
};

/// Quasi 4-8's boundary treatment (Velho, sections 4.1 and 4.3).
enum class Quasi48Boundary {
  /// Boundary vertices do not move: old ones keep their position, split
  /// points of boundary edges stay at the midpoint (the paper's planar
  /// examples, and Figure 11(b), all boundary edges and vertices tagged).
  fixed,
  /// The boundary polygon is smoothed by the same two passes restricted to
  /// it: a split point is the average of its two boundary neighbours (the
  /// midpoint), an old boundary vertex 1/2 p + 1/(2k) sum of its k new
  /// boundary neighbours (kept where k = 0). Where both boundary edges of a
  /// vertex split, this is the cubic B-spline rule (3/4 p + 1/8 (a + b)).
  smoothed,
};

/// Quasi 4-8 (rules/quasi_4_8.h): its boundary treatment.
struct Quasi48Parameters {
  Quasi48Boundary boundary = Quasi48Boundary::fixed;  ///< the boundary treatment
};

struct CompositeProgram;

/// A composite scheme written as a sequence of averaging operators
/// (rules/composite.h): its parsed program, shared by its steps.
struct CompositeParameters {
  std::shared_ptr<const CompositeProgram> program;  ///< the upsampling and the averages
};

/// A family's parameters: none, a tension, a degree with its smoothing
/// operators, quasi 4-8's boundary treatment, or a composite scheme's
/// averaging operators. A registered scheme carries its defaults; set them
/// on a copy (Scheme is a plain value) to refine or analyse another member;
/// the rule file's check (Scheme::parameter_check) validates them. Masks
/// read them from the LevelView.
using SchemeParameters =
    std::variant<std::monostate, TensionParameters, DegreeParameters, Quasi48Parameters, CompositeParameters>;

/// The tension of a tension family.
/// \param p a scheme's parameters.
/// \return the TensionParameters \p p holds, or nullptr.
inline const TensionParameters* tension_parameters(const SchemeParameters& p) noexcept {
  return std::get_if<TensionParameters>(&p);
}
/// The tension of a tension family, to modify.
/// \param p a scheme's parameters.
/// \return the TensionParameters \p p holds, or nullptr.
inline TensionParameters* tension_parameters(SchemeParameters& p) noexcept {
  return std::get_if<TensionParameters>(&p);
}
/// The degree and smoothing of a generalized Catmull-Clark scheme.
/// \param p a scheme's parameters.
/// \return the DegreeParameters \p p holds, or nullptr.
inline const DegreeParameters* degree_parameters(const SchemeParameters& p) noexcept {
  return std::get_if<DegreeParameters>(&p);
}
/// The degree and smoothing of a generalized Catmull-Clark scheme, to modify.
/// \param p a scheme's parameters.
/// \return the DegreeParameters \p p holds, or nullptr.
inline DegreeParameters* degree_parameters(SchemeParameters& p) noexcept { return std::get_if<DegreeParameters>(&p); }

/// What a mask may look at: the parent level's topology (not its positions)
/// and the sharpness of its edges.
/// An edge is sharp for the rule being evaluated when its sharpness exceeds
/// `sharp_above`: 0 for this level's rule, 1 for the rule one level down
/// (a sharpness s becomes s - 1 there). Boundary and non-manifold edges are
/// infinitely sharp. An empty sharpness array means no edge is sharp.
///
/// With Chaikin creasing an edge's two children can differ one level down
/// (creasing.h), so "is e sharp one level down" depends on the end: the view
/// for the rule one level down then also carries `child_end_sharpness`, the
/// children's sharpness per edge end (2e + i for the child at
/// topology.edge_vertices(e)[i]), and is_sharp_at(e, v) asks whether the
/// child at v's end is sharp. Masks ask is_sharp_at where they know the vertex.
struct LevelView {
  const MeshTopology& topology;  ///< the parent level's topology
  /// Per edge, its sharpness on this level (subdiv::LevelCreasing); empty:
  /// no edge is sharp.
  std::span<const double> edge_sharpness;
  /// Sharpness an edge must exceed to be sharp for the rule evaluated: 0
  /// for this level's rule, 1 for the rule one level down.
  double sharp_above = 0.0;
  /// Piecewise-smooth rules only (empty otherwise): per vertex, the angle
  /// alpha each of its sectors spans (pi at crease and boundary vertices, the
  /// corner's angle at corners), 0 where the vertex is smooth. Edge masks
  /// next to such a vertex use theta_k = alpha / k, k the faces of the
  /// sector (rules/rule_helpers.h: sector_theta).
  std::span<const double> sector_angle = {};
  std::span<const double> child_end_sharpness = {};  ///< empty: is_sharp_at == is_sharp
  SchemeParameters parameters = {};  ///< the refined scheme's
  /// The tension of a tension family's masks.
  /// \return the tension w of `parameters`.
  /// \throws std::bad_variant_access if `parameters` hold no TensionParameters.
  double tension() const { return std::get<TensionParameters>(parameters).tension; }
  /// The parent's level, 0 for the control mesh: rules that alternate
  /// between steps (sqrt3's boundary) read its parity.
  int level = 0;
  /// Per vertex, the rule of its vertex point (this level's): masks of new
  /// points next to a vertex that depend on its rule (sqrt3's boundary
  /// points next to a corner) read it. Empty in views made outside the engine.
  std::span<const VertexRule> vertex_rule = {};
  /// A composite scheme's later steps: the split its first step made of the
  /// level's parent (which child vertices are new, and from what); nullptr
  /// otherwise.
  const SplitMap* level_split = nullptr;
  /// Per vertex, whether the scheme keeps it in place
  /// (SchemeMasks::held_vertices); empty where the masks declare none.
  std::span<const char> held = {};
  /// Catmull-Clark's edge rule where a triangle meets the edge: the level's
  /// `smoothtriangles` tag (OpenSubdiv's Sdc::Options::TriangleSubdivision).
  TriangleSubdivision triangle_subdivision = TriangleSubdivision::catmark;
  /// A number the engine gives each level it refines, unique within the
  /// process, so that masks may keep work shared between a level's points
  /// (a composite scheme's intermediate averages) without mistaking one
  /// level for another; 0 in views made outside the engine: nothing kept.
  std::uint64_t level_id = 0;

  /// Whether edge \p e is sharp for the rule being evaluated.
  /// \param e an edge of `topology`.
  /// \return true where its sharpness exceeds `sharp_above`.
  /// \pre \p e is in [0, edge count) (unchecked).
  bool is_sharp(Index e) const noexcept {
    return !edge_sharpness.empty() && edge_sharpness[static_cast<std::size_t>(e)] > sharp_above;
  }
  /// Whether edge e is sharp for the rule at its end vertex v: with
  /// `child_end_sharpness`, whether e's child at v is sharp one level down;
  /// without, is_sharp(e).
  /// \param e an edge of `topology`.
  /// \param v one of the ends of \p e.
  /// \return true where the edge is sharp at that end.
  /// \pre \p e is in [0, edge count) and \p v is one of its ends (unchecked; any
  ///   other vertex reads the second end).
  bool is_sharp_at(Index e, Index v) const noexcept {
    if (child_end_sharpness.empty()) return is_sharp(e);
    const std::size_t end = topology.edge_vertices(e)[0] == v ? 0 : 1;
    return child_end_sharpness[2 * static_cast<std::size_t>(e) + end] > 0.0;
  }
};

/// Collects (parent vertex, weight) pairs for one child vertex. Weights added
/// are multiplied by the current scale, so that the engine can blend the
/// masks of two rules (semi-sharp creases).
///
/// Quad-split schemes may also weight the level's new face points (the child
/// vertex of a parent face, made by the scheme's face mask), as OpenSubdiv's
/// Sdc masks weight face centres: a Catmull-Clark vertex mask then has 9
/// entries instead of 21. The fast path reads those face points from the
/// child level it has just computed; the stencil recorder substitutes their
/// face masks, so recorded tables are over parent vertices only. A scheme
/// whose face points are made from new edge points (Kobbelt's) weights those
/// instead, the other way round (SchemeMasks::face_points_read_edge_points).
class MaskBuilder {
 public:
  /// Removes every entry and resets the scale to 1; keeps the capacity.
  void clear() noexcept {
    vertices_.clear();
    weights_.clear();
    face_points_.clear();
    face_point_weights_.clear();
    edge_points_.clear();
    edge_point_weights_.clear();
    scale_ = 1.0;
  }
  /// Adds a weight on a parent vertex (entries for the same vertex add up
  /// when applied).
  /// \param vertex a parent vertex.
  /// \param weight the weight, multiplied by the current scale.
  /// \throws std::bad_alloc if memory runs out.
  void add(Index vertex, double weight) {
    vertices_.push_back(vertex);
    weights_.push_back(scale_ * weight);
  }
  /// Weight on the new face point of parent face `face` (quad split only).
  /// \param face a parent face.
  /// \param weight the weight, multiplied by the current scale.
  /// \throws std::bad_alloc if memory runs out.
  void add_face_point(Index face, double weight) {
    face_points_.push_back(face);
    face_point_weights_.push_back(scale_ * weight);
  }
  /// Weight on the new edge point of parent edge `edge` (quad split, face
  /// masks of schemes with SchemeMasks::face_points_read_edge_points only).
  /// \param edge a parent edge.
  /// \param weight the weight, multiplied by the current scale.
  /// \throws std::bad_alloc if memory runs out.
  void add_edge_point(Index edge, double weight) {
    edge_points_.push_back(edge);
    edge_point_weights_.push_back(scale_ * weight);
  }
  /// Sets the factor applied to the weights added from now on.
  /// \param scale the factor (1 after construction and clear()).
  void set_scale(double scale) noexcept { scale_ = scale; }
  /// Reserves room for this many entries of each kind.
  /// \param entries the entries per kind.
  /// \throws std::length_error if \p entries exceeds the vectors' max_size().
  /// \throws std::bad_alloc if memory runs out.
  void reserve(std::size_t entries) {
    vertices_.reserve(entries);
    weights_.reserve(entries);
    face_points_.reserve(entries);
    face_point_weights_.reserve(entries);
    edge_points_.reserve(entries);
    edge_point_weights_.reserve(entries);
  }
  /// The parent vertices added, in order.
  /// \return a view valid until the builder is next modified.
  std::span<const Index> vertices() const noexcept { return vertices_; }
  /// The scaled weights of vertices(), entry for entry.
  /// \return a view valid until the builder is next modified.
  std::span<const double> weights() const noexcept { return weights_; }
  /// The parent faces whose new face points were added, in order.
  /// \return a view valid until the builder is next modified.
  std::span<const Index> face_points() const noexcept { return face_points_; }
  /// The scaled weights of face_points(), entry for entry.
  /// \return a view valid until the builder is next modified.
  std::span<const double> face_point_weights() const noexcept { return face_point_weights_; }
  /// The parent edges whose new edge points were added, in order.
  /// \return a view valid until the builder is next modified.
  std::span<const Index> edge_points() const noexcept { return edge_points_; }
  /// The scaled weights of edge_points(), entry for entry.
  /// \return a view valid until the builder is next modified.
  std::span<const double> edge_point_weights() const noexcept { return edge_point_weights_; }
  /// The entries of all three kinds.
  /// \return vertices().size() + face_points().size() + edge_points().size().
  std::size_t size() const noexcept { return vertices_.size() + face_points_.size() + edge_points_.size(); }

 private:
  std::vector<Index> vertices_;
  std::vector<double> weights_;
  std::vector<Index> face_points_;
  std::vector<double> face_point_weights_;
  std::vector<Index> edge_points_;
  std::vector<double> edge_point_weights_;
  double scale_ = 1.0;
};

/// Quad, sqrt3 and sqrt2 splits: adds to `mask` the weights of the face
/// point of parent face `face`.
using FaceMask = void (*)(const LevelView& level, Index face, MaskBuilder& mask);
/// Primal splits: adds to `mask` the weights of the edge point of parent
/// edge `edge` under `rule` (the engine blends the two rules of a
/// semi-sharp edge).
using EdgeMask = void (*)(const LevelView& level, Index edge, EdgeRule rule, MaskBuilder& mask);
/// Splits with vertex points (primal, identity, sqrt3, sqrt2): adds to
/// `mask` the weights of the vertex point of parent vertex `vertex` under
/// `rule`.
using VertexMask = void (*)(const LevelView& level, Index vertex, VertexRule rule, MaskBuilder& mask);
/// Dual split: the child vertex of face corner `corner`.
using CornerMask = void (*)(const LevelView& level, Index corner, MaskBuilder& mask);
/// Dual split, and the sqrt3 split's trisecting steps: the child vertex near
/// end `vertex` of boundary edge `edge`.
using BoundaryPointMask = void (*)(const LevelView& level, Index edge, Index vertex, MaskBuilder& mask);

/// A level's child positions computed straight from the parent's, for the
/// fast path (refine()): the same values as the scheme's masks (tested
/// against the stencils), cheaper where the masks are wide. `map` is the
/// level's split of `parent`.
using PositionEvaluator = void (*)(const MeshTopology& parent, const SplitMap& map, std::span<const Vec3> parent_positions,
                                   std::span<Vec3> child_positions);

/// The fast path's position of child vertex `child` of the level (`map`)
/// straight from positions, where the scheme knows a cheaper route than its
/// mask (its regular cases); false where it does not, and the engine
/// applies the mask. `child_positions` holds the points made before this
/// one (face points, or edge points where face masks read them). Must give
/// the mask's value up to rounding (tested against the stencils).
using PointEvaluator = bool (*)(const LevelView& level, const SplitMap& map, Index child,
                                std::span<const Vec3> parent_positions, std::span<const Vec3> child_positions,
                                Vec3& out);

/// The vertices of a level that a scheme's masks keep in place (quasi 4-8's
/// tagged vertices), from the level's mesh (its tags) and topology: one
/// entry per vertex, nonzero where held (LevelView::held).
using HeldVertices = std::vector<char> (*)(const PolygonMesh& level, const MeshTopology& topology,
                                          const SchemeParameters& parameters);

/// Throws ParameterError when `parameters` lie outside the family's valid
/// range (the scheme's rule file states it). `name` is the scheme's.
using ParameterCheck = void (*)(std::string_view name, const SchemeParameters& parameters);

struct Scheme;
/// Composite schemes: the operators one level applies in turn, each an
/// ordinary one-split scheme with its own parameters (refine.cpp): a first
/// step that splits the level's parent, then identity steps that smooth its
/// child, and at most one dual split of the parent that reads them.
using StepList = std::vector<Scheme> (*)(const SchemeParameters& parameters);

/// Which published a-priori depth bound covers a scheme's regular part
/// (depth/depth_bound.h); every other scheme's bound comes from the analysis.
enum class PaperDepthBound : std::uint8_t {
  none,                 ///< no published bound: the analysis gives it
  loop_theorem_3,       ///< Loop's rules with Loop's beta
  cheng_catmull_clark,  ///< Catmull-Clark
  doo_sabin_theorem_5,  ///< Doo-Sabin's rules with Doo's boundary
};

/// What a scheme takes and how its levels repeat: what the engine, the
/// analysis, depth, limit and the CLI ask instead of its name.
struct SchemeTraits {
  /// Control vertices stay on every level (and so on the limit surface).
  bool interpolating = false;
  /// Refuses control meshes with faces other than triangles.
  bool needs_triangles = false;
  /// Refuses control meshes with faces other than quads (a scheme whose
  /// rules read quads; its split keeps every face a quad).
  bool needs_quads = false;
  /// Refuses meshes with a boundary (a scheme without boundary rules whose
  /// boundary would degenerate). The analysis lifts it: its ring mesh's outer
  /// boundary lies outside the neighbourhood it reads.
  bool needs_closed_mesh = false;
  /// Refinement steps per analysis step: the number of steps after which a
  /// configuration repeats (1 for the primal and dual splits; 2 for schemes
  /// such as sqrt3 and 4-8 whose layout turns on every step). The analysis
  /// reads the matrix of `period` composed steps.
  int period = 1;
  /// Face rings around a vertex that the analysis tries at least before
  /// calling a neighbourhood not invariant (composite schemes of high degree
  /// read further than the analysis' default); 0: the default.
  int analysis_rings = 0;
  /// The published depth bound that applies, if any.
  PaperDepthBound paper_depth_bound = PaperDepthBound::none;
  /// Face-varying channels follow the face-varying interpolation option
  /// (Tags::face_varying_interpolation) as OpenSubdiv's, with this scheme's
  /// masks where a channel is continuous and the cubic B-spline along its
  /// seams; otherwise they are interpolated linearly whatever it says.
  bool smooth_face_varying = false;
  /// Refines faces that repeat a vertex, with non-manifold input allowed
  /// (RuleOptions::allow_non_manifold), as OpenSubdiv does: a side joining
  /// a vertex to itself is an edge of its own, the vertices of such edges
  /// are corners (the rules' sharp cases read no further than those edges).
  bool degenerate_faces = false;
};

/// The masks that make one level's child vertices (which ones a split
/// needs: topology/split.h).
struct SchemeMasks {
  FaceMask face_point = nullptr;      ///< quad, sqrt3 and sqrt2 splits
  EdgeMask edge_point = nullptr;      ///< primal splits
  VertexMask vertex_point = nullptr;  ///< primal, identity, sqrt3 and sqrt2 splits
  CornerMask corner_point = nullptr;  ///< dual split only
  BoundaryPointMask boundary_point = nullptr;  ///< dual split, sqrt3 split
  /// The curve scheme (curves/curve_scheme.h) whose masks the boundary and
  /// crease rules apply along the curve, or nullptr where they are the
  /// scheme's own: limits on the boundary are that curve's.
  const CurveScheme* boundary_curve = nullptr;
  /// Quad split: the face mask weights the level's new edge points
  /// (MaskBuilder::add_edge_point), so the engine makes edge and vertex
  /// points first and face points last; the edge and vertex masks must then
  /// not weight face points.
  bool face_points_read_edge_points = false;
  /// The vertices these masks keep in place, computed by the engine once per
  /// level into LevelView::held; nullptr: none.
  HeldVertices held_vertices = nullptr;
};

/// A quad-split scheme's rule on regular regions, as a tensor product: one
/// step along a grid line makes the point at even position 2i from the coarse
/// points i-2 .. i+2 with weights `even`, and the point at 2i+1 from
/// i-1 .. i+2 with `odd`; a surface point takes the product of its two
/// directions' weights. Declared where the scheme's masks at interior
/// vertices of valence 4 with no sharp edge are this product (a test derives
/// it from them). Catmull-Clark's reads one point each side (even[0],
/// even[4], odd[0] and odd[3] are 0); Kobbelt's four-point rule and the
/// quintic B-spline read two for odd points, the septic B-spline two for
/// both.
struct RegularGrid {
  std::array<double, 5> even;  ///< weights on coarse points i-2 .. i+2 of fine point 2i
  std::array<double, 4> odd;   ///< weights on coarse points i-1 .. i+2 of fine point 2i+1

  /// How many coarse points beyond a face's two corners its patch takes on
  /// each side of a grid line: the fewest from which the stencil makes the
  /// same reach of points again at the finer level.
  /// \return 1 (Catmull-Clark's 4 x 4 patch), 2 (6 x 6, where odd points
  ///   read two points each side) or 3 (8 x 8, where even points do too).
  int patch_reach() const noexcept {
    if (even[0] != 0.0 || even[4] != 0.0) return 3;
    if (odd[0] != 0.0 || odd[3] != 0.0) return 2;
    return 1;
  }
};

/// A triangle-split scheme's rule on regular regions (interior vertices of
/// valence 6, no sharp edge), on the triangular lattice: a new vertex point
/// is `centre` times its vertex plus `ring` times each of its six
/// neighbours; a new edge point is `near` times each end of its edge plus
/// `far` times each of the two vertices opposite it plus `wing` times each
/// of the four vertices across the other edges of the edge's two triangles
/// (the Butterfly's wings). Declared where the scheme's masks there are
/// these (a test derives them from the masks).
struct RegularTriangleGrid {
  double centre;      ///< vertex point: weight on the vertex itself
  double ring;        ///< vertex point: weight on each of its six neighbours
  double near;        ///< edge point: weight on each end of the edge
  double far;         ///< edge point: weight on each of the two vertices opposite the edge
  double wing = 0.0;  ///< edge point: weight on each of its four wing vertices

  /// How many steps beyond a triangle its patch takes.
  /// \return 1 (its corners' rings, 12 points), or 2 where edge points
  ///   read wings (27 points).
  int patch_reach() const noexcept { return wing != 0.0 ? 2 : 1; }
};

/// Shortcuts of the fast path (refine()), each held to the masks by tests.
struct FastPath {
  /// The level's positions (PositionEvaluator); nullptr: the masks. Vertex
  /// channels always take the masks.
  PositionEvaluator positions = nullptr;
  /// A shortcut per child vertex (PointEvaluator); nullptr: the masks.
  /// Unused where vertex channels need the masks anyway.
  PointEvaluator point = nullptr;
  /// A quad-split scheme one level of which is two steps of this one (4-8:
  /// two sqrt2 steps make the quad split). The engine refines with it where
  /// two steps remain and the level is closed, manifold and carries no
  /// face-varying channel; its child numbers the vertices [face points |
  /// edge points | vertex points] as every quad split does. nullptr: none.
  const Scheme* two_steps = nullptr;
  /// The regular rule as a grid stencil (RegularGrid): refine() and
  /// refine_stencil_table() then refine the faces whose corners are regular
  /// as grids (src/refine/grid_refine.h). nullptr: none.
  const RegularGrid* regular_grid = nullptr;
  /// The same for a family whose regular rule follows its parameters (a
  /// tension, a degree): the rule for `parameters`, or nullopt where those
  /// parameters make no tensor product. Used where regular_grid is nullptr.
  std::optional<RegularGrid> (*regular_grid_of)(const SchemeParameters& parameters) = nullptr;
  /// The same for a triangle-split scheme (RegularTriangleGrid).
  const RegularTriangleGrid* regular_triangle_grid = nullptr;
  /// The same for a triangle-split family whose regular rule follows its
  /// parameters (the Butterfly's tension). Used where regular_triangle_grid
  /// is nullptr.
  std::optional<RegularTriangleGrid> (*regular_triangle_grid_of)(const SchemeParameters& parameters) = nullptr;
};

/// A subdivision scheme, declared by its rule file with designated
/// initializers:
///
///     static const Scheme scheme{
///         .name = "loop", .summary = "...", .citation = "...",
///         .split = SplitRule::triangle,
///         .traits = {.needs_triangles = true},
///         .masks = {.edge_point = edge_point, .vertex_point = vertex_point},
///         .limit_masks = limit_masks};
struct Scheme {
  std::string_view name = {};      ///< as users type it
  std::string_view summary = {};   ///< one line
  std::string_view citation = {};  ///< the paper the rules come from
  SplitRule split = SplitRule::quad;  ///< how a level's faces are split (a composite's overall split)
  SchemeTraits traits = {};          ///< what the scheme takes and how its levels repeat
  SchemeMasks masks = {};            ///< the masks of one step
  /// Composite schemes (generalized Catmull-Clark, midpoint, quasi 4-8): one
  /// level is these steps in turn: a split of the level's parent (R, a quad
  /// split; quasi 4-8's bisection), smoothing steps (identity splits of its
  /// child) and possibly A, a dual split of the level's parent whose masks
  /// weight the smoothed vertices; `split` is then the level's overall
  /// split (the first step's, or dual when the steps end with A). nullptr
  /// otherwise.
  StepList steps = nullptr;
  /// Closed-form limit masks for the scheme's standard rules, or nullptr:
  /// limit positions then use the masks the analysis reads off the rules.
  LimitMaskFunction limit_masks = nullptr;
  FastPath fast_path = {};  ///< shortcuts of refine(); empty: the masks everywhere
  /// The family's parameters (the registered scheme's defaults); masks read
  /// them from LevelView::parameters.
  SchemeParameters parameters = {};
  /// The family's own parameter check (ParameterCheck); nullptr: none.
  ParameterCheck parameter_check = nullptr;
};

/// The scheme's regular rule as a grid stencil, for its parameters
/// (FastPath::regular_grid, else FastPath::regular_grid_of).
/// \param scheme the scheme, possibly a copy with changed parameters.
/// \return the rule; nullopt where the scheme declares none for them.
/// \throws std::bad_variant_access if the parameters are not of the
///   family's kind (a tension for Kobbelt and the Butterfly).
inline std::optional<RegularGrid> regular_grid_of(const Scheme& scheme) {
  if (scheme.fast_path.regular_grid) return *scheme.fast_path.regular_grid;
  if (scheme.fast_path.regular_grid_of) return scheme.fast_path.regular_grid_of(scheme.parameters);
  return std::nullopt;
}

/// The same for a triangle-split scheme (FastPath::regular_triangle_grid,
/// else FastPath::regular_triangle_grid_of).
/// \param scheme the scheme, possibly a copy with changed parameters.
/// \return the rule; nullopt where the scheme declares none for them.
/// \throws std::bad_variant_access if the parameters are not of the
///   family's kind (a tension for Kobbelt and the Butterfly).
inline std::optional<RegularTriangleGrid> regular_triangle_grid_of(const Scheme& scheme) {
  if (scheme.fast_path.regular_triangle_grid) return *scheme.fast_path.regular_triangle_grid;
  if (scheme.fast_path.regular_triangle_grid_of) return scheme.fast_path.regular_triangle_grid_of(scheme.parameters);
  return std::nullopt;
}

/// Whether the scheme's masks read a tension (the CLI's --tension).
/// \param scheme the scheme.
/// \return true where its parameters hold TensionParameters.
inline bool takes_tension(const Scheme& scheme) noexcept { return tension_parameters(scheme.parameters) != nullptr; }

/// Checks that the scheme's parameters are valid: a finite tension where
/// the masks read it, and the family's own check (Scheme::parameter_check).
/// Every refinement entry point calls it.
/// \param scheme the scheme, possibly a copy with changed parameters.
/// \throws ParameterError if a parameter is out of range (the message names
///   the scheme and the parameter).
/// \throws std::bad_alloc if memory runs out.
void check_parameters(const Scheme& scheme);

/// The limit at a boundary (or crease) vertex along the curve, as weights on
/// (before, at, after): limit_at_point() of the scheme's boundary_curve.
/// \param scheme the scheme.
/// \return the three weights; all 0 where the curve's limit mask is not
///   known (CurveScheme::limit empty).
/// \throws InvalidInputError if \p scheme declares no boundary_curve, or its
///   curve's limit mask reaches beyond the two neighbours.
/// \throws std::bad_alloc if memory runs out.
std::array<double, 3> boundary_vertex_limit(const Scheme& scheme);

/// Every scheme, in the order `subdiv schemes` lists them.
/// \return a view of a static array, valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the registered schemes.
std::span<const Scheme* const> all_schemes();

/// The scheme every command uses when none is named: Catmull-Clark, which
/// takes any polygon mesh.
/// \return catmull_clark_scheme().
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the scheme.
const Scheme& default_scheme();

/// The registered scheme with this name (Scheme::name, as users type it), or
/// the composite scheme a "composite:..." spec writes (rules/composite.h).
/// \param name the name, compared exactly.
/// \return the scheme, or nullptr where none has the name.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the registered schemes.
/// \throws ParameterError for a composite spec that does not parse.
const Scheme* find_scheme(std::string_view name);

}  // namespace subdiv
