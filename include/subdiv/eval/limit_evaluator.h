#pragma once
/// \file
/// The limit surface of Catmull-Clark, Loop and loop-warren at any parameter, exact:
/// regular faces are the bicubic B-spline and the quartic box spline of
/// their control points (reflected across boundaries and infinitely sharp
/// creases), and a face with one extraordinary corner (an interior vertex,
/// a dart, or a sector between sharp edges) is evaluated through the powers
/// of the scheme's own subdivision matrix at that corner (Stam, SIGGRAPH
/// 1998), with every matrix read off the project's refinement. Other faces,
/// Catmull-Clark's non-quads and faces near semi-sharp features are refined
/// uniformly (isolated) until each face below them is one of those kinds.
///
/// Parameterization (ptex faces, as OpenSubdiv's Far::PtexIndices):
/// - a Catmull-Clark quad is one ptex face, (u, v) in [0, 1]^2: its corner 0
///   at (0, 0), corner 1 at (1, 0), corner 2 at (1, 1), corner 3 at (0, 1);
/// - a Catmull-Clark face of n != 4 sides is n ptex faces, one per corner k
///   in order: the sub-face of the first refinement with (0, 0) at corner k,
///   (1, 0) at the midpoint of the edge to corner k + 1, (1, 1) at the face's
///   centre and (0, 1) at the midpoint of the edge from corner k - 1;
/// - a Loop triangle is one ptex face, u, v >= 0 and u + v <= 1: corner 0 at
///   (0, 0), corner 1 at (1, 0), corner 2 at (0, 1).
/// Ptex faces are numbered face by face, in face order.
///
/// Scope (docs/evaluation.md lists it by configuration): manifold meshes with
/// boundaries, infinitely sharp creases, darts, corners between two or more
/// sharp edges, and semi-sharp features up to sharpness 4. Refused at
/// construction, with the element named: sharper semi-sharp features, hole
/// tags, interior vertices of valence 2, corner tags where fewer than two
/// sharp edges meet, non-manifold vertices, coordinates beyond 1e300.
///
/// Approximate evaluation (by_refinement()) covers the other schemes of the
/// quad and triangle splits (bilinear, Kobbelt, linear, the Butterflies)
/// and Catmull-Clark, Loop and loop-warren meshes outside the exact scope
/// but for holes, non-manifold vertices and huge coordinates: the mesh is
/// refined uniformly until, at two levels in a row, the limit points of the
/// level's new vertices lie within the requested accuracy of the previous
/// level's interpolant (the piecewise bilinear or linear surface through its
/// vertices' limits), and the last level's interpolant is evaluated, with
/// the interpolated limit normals. The accuracy is measured at that level's vertices, not bounded
/// everywhere (docs/evaluation.md); second derivatives are the
/// interpolant's (zero but for the bilinear twist).

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

class ExtraordinaryPatch;

/// The limit surface at one parameter: position, derivatives with respect to
/// the ptex face's (u, v), and the unit normal.
///
/// At an extraordinary vertex itself (a ptex corner there) the parametric
/// derivatives are 0 or unbounded depending on the valence; they are
/// reported as zero, and the normal comes from the scheme's tangent masks.
struct LimitPoint {
  Vec3 position;  ///< the limit point
  Vec3 du;        ///< d position / du
  Vec3 dv;        ///< d position / dv
  Vec3 duu;       ///< d2 position / du2
  Vec3 duv;       ///< d2 position / du dv
  Vec3 dvv;       ///< d2 position / dv2
  /// Unit normal, du x dv normalised (the side the faces are counter-clockwise
  /// on); zero where the surface is degenerate there (du x dv = 0 away from an
  /// extraordinary vertex).
  Vec3 normal;
};

/// A parameter on the limit surface: a ptex face and (u, v) in it.
struct SurfaceLocation {
  Index face = 0;  ///< the ptex face
  double u = 0.0;  ///< first parameter
  double v = 0.0;  ///< second parameter
};

/// Exact evaluation of the limit surface of a control mesh (see the file
/// comment for the parameterization and scope). Construction isolates the
/// extraordinary vertices and gathers every patch's control points once;
/// evaluation reads them only, so concurrent calls are safe. Later changes to
/// the mesh are not seen.
class LimitEvaluator {
 public:
  /// Prepares the evaluator of \p mesh under \p scheme.
  /// \param mesh a manifold mesh in the scope above (Loop: triangles).
  /// \param scheme catmull-clark, loop or loop-warren.
  /// \param options rule choices for the isolating refinement (threads
  ///   included); RefineOptions::levels and start_level are not read.
  /// \throws InvalidInputError, ParameterError or ValidationError as
  ///   check_refinable() does; InvalidInputError also for another scheme or
  ///   anything outside the scope above, naming the element.
  /// \throws std::bad_alloc if memory runs out.
  LimitEvaluator(const PolygonMesh& mesh, const Scheme& scheme, const RefineOptions& options = {});

  /// Why the exact evaluator would refuse \p mesh under \p scheme for
  /// reasons approximate evaluation does not share (another scheme, an
  /// interior vertex of valence 2, sharper semi-sharp features, corner tags
  /// on fewer than two sharp edges), or nullopt. The refusals both share
  /// (check_refinable(), holes, non-manifold vertices, huge coordinates)
  /// are not looked at.
  /// \param mesh the control mesh.
  /// \param scheme the scheme.
  /// \param options the rule choices (creasing).
  /// \return the reason, naming the element, or nullopt.
  /// \throws std::bad_alloc if memory runs out.
  static std::optional<std::string> exact_evaluation_unavailable(const PolygonMesh& mesh, const Scheme& scheme,
                                                                 const RefineOptions& options = {});

  /// Prepares approximate evaluation by uniform refinement (see the file
  /// comment): levels are added until, at two levels in a row, the limit
  /// points of the level's new vertices lie within \p accuracy of the
  /// previous level's interpolant at their parameters (measured_change()).
  /// \param mesh a manifold mesh without hole tags.
  /// \param scheme a scheme of the quad or triangle split with limit
  ///   positions (not a composite scheme).
  /// \param accuracy the largest change accepted, in the mesh's units (> 0).
  /// \param options rule choices for the refinement (threads included);
  ///   RefineOptions::levels and start_level are not read.
  /// \param max_levels the most levels refined.
  /// \return the evaluator; exact() is false.
  /// \throws InvalidInputError for another scheme, a mesh outside that
  ///   scope, an accuracy not positive and finite, or an accuracy not reached
  ///   within \p max_levels or before a level would exceed 2^22 faces (the
  ///   message gives the change measured so far).
  /// \throws ParameterError or ValidationError as check_refinable() does.
  /// \throws std::bad_alloc if memory runs out.
  static LimitEvaluator by_refinement(const PolygonMesh& mesh, const Scheme& scheme, double accuracy,
                                      const RefineOptions& options = {}, int max_levels = 10);
  /// Frees the prepared patches.
  ~LimitEvaluator() noexcept;
  /// Moves the prepared patches.
  /// \param other the evaluator moved from (left empty).
  LimitEvaluator(LimitEvaluator&& other) noexcept;
  /// Moves the prepared patches.
  /// \param other the evaluator moved from (left empty).
  /// \return this evaluator.
  LimitEvaluator& operator=(LimitEvaluator&& other) noexcept;

  /// \return the number of ptex faces (see the file comment).
  Index ptex_face_count() const noexcept { return static_cast<Index>(ptex_leaves_.size()) - 1; }
  /// The first ptex face of control face \p face; a Catmull-Clark n-gon's
  /// others follow it, one per corner.
  /// \param face a face of the control mesh.
  /// \return its first ptex face.
  /// \throws InvalidInputError if \p face is not a face of the mesh.
  Index ptex_face_of(Index face) const;
  /// \return whether the ptex faces are triangles (Loop) rather than quads.
  bool triangles() const noexcept { return triangles_; }
  /// \return the deepest uniform refinement the isolation took (0: every
  ///   face was a patch already).
  int isolation_levels() const noexcept { return isolation_levels_; }
  /// \return the number of patches the ptex faces are made of (approximate
  ///   evaluation: the faces of the level interpolated).
  std::size_t patch_count() const noexcept { return leaves_.size(); }
  /// \return whether evaluation is exact (false: by_refinement()).
  bool exact() const noexcept { return exact_; }
  /// \return approximate evaluation: the largest distance between the limit
  ///   points of the last two levels' new vertices and the previous level's
  ///   interpolant at their parameters; 0 when exact.
  double measured_change() const noexcept { return measured_change_; }
  /// \return approximate evaluation: vertices of the interpolated level
  ///   whose limit no mask gave (left at their refined position); 0 when
  ///   exact.
  Index unresolved_vertices() const noexcept { return unresolved_vertices_; }

  /// The limit surface at (u, v) of ptex face \p face.
  /// \param face a ptex face.
  /// \param u first parameter.
  /// \param v second parameter.
  /// \return the point, its derivatives and normal.
  /// \throws InvalidInputError if \p face is not a ptex face or (u, v) lies
  ///   outside it by more than 1e-12 (NaN included); a point outside by less
  ///   is evaluated at the nearest point of the face.
  LimitPoint evaluate(Index face, double u, double v) const;

  /// evaluate() at every location, in parallel over the calling thread's
  /// task arena; the results do not depend on the thread count.
  /// \param at the locations.
  /// \return one point per location, in order.
  /// \throws InvalidInputError for the first bad location, as evaluate().
  /// \throws std::bad_alloc if memory runs out.
  std::vector<LimitPoint> evaluate(std::span<const SurfaceLocation> at) const;

  /// Where a ptex face's parameter (u, v) is origin + s axis_s + t axis_t in
  /// a patch's own parameters (s, t).
  struct Frame {
    double origin[2] = {0.0, 0.0};  ///< the patch's (0, 0) in (u, v)
    double axis_s[2] = {1.0, 0.0};  ///< the step of s = 1 in (u, v)
    double axis_t[2] = {0.0, 1.0};  ///< the step of t = 1 in (u, v)
  };

 private:
  /// A patch of an isolated face: its kind, its frame in the ptex face, and
  /// its control points (from control_[first_control]: 16, 12 or the
  /// extraordinary patch's ring size).
  struct Leaf {
    Frame frame;
    std::array<double, 4> inverse{};  ///< (s, t) = inverse ((u, v) - frame.origin), row-major
    const ExtraordinaryPatch* extraordinary = nullptr;  ///< null: regular
    std::size_t first_control = 0;
    Vec3 corner_normal;  ///< extraordinary: the unit normal at the corner
  };
  class Builder;

  LimitEvaluator() = default;
  void check_location(Index face, double u, double v) const;
  LimitPoint evaluate_leaf(const Leaf& leaf, double s, double t) const;
  std::size_t leaf_by_descent(std::size_t first, std::size_t count, double u, double v) const;
  LimitPoint evaluate_interpolant(const Leaf& leaf, double s, double t) const;

  bool triangles_ = false;
  bool exact_ = true;
  double measured_change_ = 0.0;
  Index unresolved_vertices_ = 0;
  int isolation_levels_ = 0;
  std::vector<Index> face_ptex_;    ///< first ptex face per control face, then the count
  std::vector<Index> ptex_leaves_;  ///< first leaf per ptex face, then the count
  std::vector<Leaf> leaves_;
  std::vector<Vec3> positions_;     ///< the kept levels' positions, coarse first
  std::vector<Vec3> normals_;       ///< approximate evaluation: limit normals, parallel to positions_
  std::vector<Index> control_;      ///< every leaf's control points (into positions_), leaf after leaf
  /// The extraordinary patches' models, by configuration kind, valence or
  /// face count, and place in the sector.
  std::map<std::array<int, 3>, std::unique_ptr<ExtraordinaryPatch>> patches_;
};

}  // namespace subdiv
