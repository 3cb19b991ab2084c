#pragma once
/// \file
/// Exact evaluation of a Catmull-Clark or Loop face with one extraordinary
/// corner (Stam, "Exact evaluation of Catmull-Clark subdivision surfaces at
/// arbitrary parameter values" and "Evaluation of Loop subdivision
/// surfaces", SIGGRAPH 1998), with every matrix read off the project's own
/// refinement instead of published tables.
///
/// The model is the ring mesh of the corner's configuration: an interior
/// vertex of valence N (any face F), a dart (an interior vertex with an
/// infinitely sharp crease ending at it), or a sector of k faces between
/// sharp edges at a vertex with the crease rule (the boundary ring mesh) or
/// the corner rule (the corner ring mesh), F one of them. The centre is at
/// parameter (0, 0) of F, its next corner at (1, 0) and its previous one at
/// (0, 1). F's face ring (the vertices of the faces touching F, within the
/// sectors at its corners, in face_ring() order: 2N + 8 for an interior
/// quad, N + 6 for an interior triangle) is mapped one step down onto the
/// face ring of F's child at the centre by A, and onto the regular patch
/// points (16 or 12, reflections across sharp edges included) of each other
/// child by A_k; both come from refine_stencil_table() of the ring mesh. A
/// point whose parameter lies in F's level-n centre child but not in its
/// level-(n+1) one (max(s, t), or s + t, in [2^-(n+1), 2^-n)) lies in a
/// regular child k of level n: its value is b(s', t') A_k A^n C.
///
/// evaluate_in_eigenbasis() takes A^n = V Lambda^n V^-1 from the
/// eigen-decomposition of A (by repeated products where A is not
/// diagonalizable to working accuracy). evaluate() takes the same formula
/// by real products, with rows kept per model: A_k A^n for the first
/// kCachedLevels levels, then A_k A^n (I - 1 l) for as many more (the ring
/// moved onto the corner's limit l, which is added back: rows of decaying
/// size keep their digits), so that a point there costs one regular patch
/// over the ring's image. Closer to the corner than 2^-(2 kCachedLevels)
/// evaluate() takes the eigenbasis: there the products would lose digits of
/// the second derivatives (rounding in components whose second derivatives
/// vanish, grown by 4^n), which the eigenbasis drops. Where A has no
/// eigenbasis to working accuracy (Loop at valence 3, most boundary
/// sectors) the ring is stepped down by A^kCachedLevels to any depth, each
/// step moved back onto its limit. The tests hold the routes equal.

/// The quad split's children keep F's frame at half scale; the triangle
/// split's middle child is F's frame turned a half turn. Where that middle
/// child is no regular patch (Loop at valence 3, where the triangles around
/// its corners wrap around the corner; a sector of one face, where it
/// touches both sharp edges), its four children, one level further down,
/// are the pieces instead (read off two levels of the ring mesh).
#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "analysis/patch_basis.h"

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/configuration.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/topology/split.h"

namespace subdiv {

/// The vertices of the faces touching a face, in a canonical order: for each
/// corner of the face, starting at `corner`, the faces around its vertex
/// counter-clockwise from the face, each face's vertices from that corner
/// on, each vertex where it first appears. `signature` records, for every
/// face visited, its size and the list position of each of its vertices:
/// two faces whose rings have equal signatures have the same structure, so
/// their lists correspond point by point.
struct FaceRing {
  std::vector<Index> vertices;  ///< the ring's vertices in canonical order
  std::vector<int> signature;   ///< the walk's structure (see above)
};

/// The face ring of the face holding `corner` (FaceRing).
/// \param topology the mesh's topology.
/// \param corner the corner the walk starts at.
/// \param creasing the level's creasing, or null: without it every corner
///   must be an interior vertex with one closed fan; with it, around a
///   corner with sharp edges (or on a boundary) the walk covers the face's
///   sector between sharp edges only, from its first face, and the
///   signature records the corner's rule and the face's place in the
///   sector (the sectors beyond are decoupled by the sharp edges).
/// \return the ring; empty where the walk fails (see \p creasing, or a
///   vertex with several fans).
/// \pre \p corner is in [0, topology.corner_count()) (unchecked).
std::optional<FaceRing> face_ring(const MeshTopology& topology, Index corner,
                                  const LevelCreasing* creasing = nullptr);

/// The patch at an extraordinary corner of valence N, read off the scheme's
/// refinement of the ring mesh (see the file comment): Catmull-Clark for the
/// quad split, Loop for the triangle split.
class ExtraordinaryPatch {
 public:
  /// Builds the model for \p split at valence \p valence (>= 3).
  /// \throws InvalidInputError for a valence below 3, or a split other than
  ///   the quad and triangle splits.
  /// \throws std::logic_error where the ring mesh's refinement does not have
  ///   the expected structure (an internal inconsistency).
  ExtraordinaryPatch(SplitRule split, int valence);

  /// Builds the model of face `position` of a boundary or corner sector of
  /// k faces (Configuration), counted counter-clockwise from the face on the
  /// sector's first sharp edge: the quad split only. The sector's sharp
  /// edges keep the crease rule at the centre (a boundary of any face count,
  /// or one side of a crease) or its corner rule (a corner). An interior
  /// configuration is the (split, valence) model, or with `dart` the model
  /// of a dart: an infinitely sharp crease ending at the centre, F
  /// `position` faces counter-clockwise from the face whose edge leaving
  /// the centre is the crease. `scheme` refines the ring mesh: Catmull-Clark
  /// or Loop by the split when null; loop-warren (Loop's rules but for the
  /// extraordinary vertex's weight) may be given for the triangle split.
  /// \throws InvalidInputError for a position outside [0, k), a dart that
  ///   is not interior, or as the other constructor.
  /// \throws std::logic_error as the other constructor.
  ExtraordinaryPatch(SplitRule split, const Configuration& configuration, int position, bool dart = false,
                     const Scheme* scheme = nullptr);

  /// \return the split (quad: Catmull-Clark, triangle: Loop).
  SplitRule split() const noexcept { return split_; }
  /// \return the valence N (interior), or the sector's face count k.
  int valence() const noexcept { return valence_; }
  /// \return the configuration at the corner.
  const Configuration& configuration() const noexcept { return configuration_; }
  /// \return F's place in a boundary or corner sector, or from a dart's
  ///   crease (0 for interior).
  int position() const noexcept { return position_; }
  /// \return whether the model is a dart's.
  bool dart() const noexcept { return dart_; }
  /// \return the face-ring size: 2N + 8 (quad split), N + 6 (triangle split)
  ///   for an interior corner; a sector's own walk's size otherwise.
  int size() const noexcept { return static_cast<int>(A_.rows()); }
  /// \return the signature of the model face's ring: a mesh face whose ring
  ///   has it (from the extraordinary corner) is evaluated by this patch.
  const std::vector<int>& signature() const noexcept { return signature_; }
  /// \return the model's ring mesh positions of the ring's vertices (a
  ///   planar layout, the centre at the origin), in ring order.
  const std::vector<Vec3>& layout() const noexcept { return layout_; }
  /// \return A, the ring's map one step down onto the centre child's ring.
  const Eigen::MatrixXd& subdivision_matrix() const noexcept { return A_; }
  /// \return whether evaluate_in_eigenbasis() takes A^n through the
  ///   eigenbasis (else by products).
  bool uses_eigenbasis() const noexcept { return eigenbasis_; }

  /// The surface at (s, t) in F (the unit square, or the triangle s, t >= 0,
  /// s + t <= 1) over control points \p ring (in ring order). At (0, 0)
  /// itself the position is the limit of the corner and the derivatives are
  /// zero: the parametric derivatives there are 0 or unbounded depending on
  /// N (the normal comes from the tangent masks).
  /// \param ring size() control points.
  /// \param s the first parameter.
  /// \param t the second parameter.
  /// \return position and derivatives with respect to (s, t).
  /// \throws InvalidInputError for a ring of another size, or (s, t) outside
  ///   F (NaN included).
  PatchPoint evaluate(std::span<const Vec3> ring, double s, double t) const;

  /// evaluate() through the eigenbasis (Stam's route, see the file comment):
  /// slower, kept as the independent reference the tests compare with.
  /// \param ring size() control points.
  /// \param s the first parameter.
  /// \param t the second parameter.
  /// \return position and derivatives with respect to (s, t).
  /// \throws InvalidInputError as evaluate().
  PatchPoint evaluate_in_eigenbasis(std::span<const Vec3> ring, double s, double t) const;

  /// Half the levels n whose children's rows over the ring are kept, and
  /// the step of the deeper ones (see the file comment). Sixteen levels
  /// cost 48 matrices of 16 (12) x K per model.
  static constexpr int kCachedLevels = 8;

 private:
  /// A regular child: its patch's rows over the ring, and its frame (its
  /// parameter (u, v) is F's origin + (u axis_s, v axis_t)).
  struct Child {
    Eigen::MatrixXd rows;  // patch points x K
    std::array<double, 2> origin{};
    std::array<double, 2> axis{};
  };
  /// Where (s, t) lies: in regular child k of F's level-n centre child, at
  /// the child's parameter (u, v).
  struct Location {
    int level = 0;
    std::size_t child = 0;
    double u = 0.0, v = 0.0;
  };
  std::size_t child_holding(double s, double t) const noexcept;
  void check(std::span<const Vec3> ring, double s, double t) const;
  Location locate(double s, double t) const noexcept;
  Vec3 corner_limit(std::span<const Vec3> ring) const noexcept;
  PatchPoint evaluate_cached(std::span<const Vec3> ring, const Location& at) const;
  PatchPoint to_face(PatchPoint in_child, std::size_t child) const noexcept;

  SplitRule split_ = SplitRule::quad;
  int valence_ = 0;
  Configuration configuration_;
  int position_ = 0;
  bool dart_ = false;
  Eigen::MatrixXd A_;              // K x K
  // The regular pieces of F outside its centre child: its other three
  // children, except Loop at valence 3, where the middle child's four
  // children take its place (see the constructor).
  std::vector<Child> children_;
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::vector<RowMajor> level_rows_;  // level n < 2 kCachedLevels, piece k at [pieces n + k]
  RowMajor step_;                     // A^kCachedLevels
  std::vector<int> signature_;
  std::vector<Vec3> layout_;
  bool eigenbasis_ = false;
  Eigen::VectorXcd eigenvalues_;              // Lambda
  std::vector<Eigen::MatrixXcd> child_V_;    // A_k V, per piece
  Eigen::MatrixXcd V_inverse_;               // V^-1
  Eigen::VectorXd limit_row_;                // the limit of the corner: row of A^infinity
};

}  // namespace subdiv
