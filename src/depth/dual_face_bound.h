#pragma once
// The Doo-Sabin depth bound near extraordinary faces (faces with != 4
// sides), where the paper's Theorem 5 does not reach: the face's two-ring
// neighbourhood is followed through all further steps with the local
// subdivision matrix, and the supremum over steps of the distances (and
// second differences) it yields, scaled by |lambda_1|^-steps, is the
// amplitude of the face's term (docs/depth.md, "Doo-Sabin").

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The neighbourhood followed: the extraordinary face and two rings of
/// quads around it (the vertices of the faces touching the vertices of the
/// faces that touch it).
inline constexpr int kDualBoundRings = 2;

/// What the bound needs of one face size k, read off the scheme's own
/// refinement of the canonical ring mesh (subdiv/analysis).
struct DualFaceOperator {
  int k = 0;
  double rate = 0.0;  ///< |lambda_1| of the face configuration
  /// Maps the two-ring neighbourhood (columns in the analysis' layout order)
  /// to that of the face's child one step down.
  Eigen::MatrixXd S;
  /// The limit functional (left eigenvector of eigenvalue 1, summing to 1).
  Eigen::RowVectorXd limit;
  using SparseRow = std::vector<std::pair<Eigen::Index, double>>;
  /// Vertex-to-limit functionals of the face's vertices (the centroid of
  /// the vertex's V-face one step down minus the vertex).
  std::vector<SparseRow> distance;
  /// Second differences P_a - 2 P_v + P_b along the mesh lines through the
  /// neighbourhood's vertices, where a, v and b all lie in it.
  std::vector<SparseRow> second_difference;

  /// How to find the neighbourhood in another mesh: the faces touching the
  /// face's one-ring, each reached across an edge of an earlier one (step 0
  /// is the face itself), with what a match must reproduce.
  struct Step {
    int from = -1;       ///< earlier step whose face this one borders
    int from_corner = 0; ///< that face's local corner whose outgoing edge is crossed
    int corner = 0;      ///< this face's local corner on the crossed edge (starting at the far end)
    std::vector<Eigen::Index> columns;  ///< the column of each local corner's vertex
    std::vector<char> boundary;         ///< whether each local corner's outgoing edge is a boundary edge
  };
  struct OneRingVertex {
    int step = 0, corner = 0;  ///< where the pattern meets it
    VertexKind kind = VertexKind::interior;
    Index faces = 4;
  };
  struct Pattern {
    std::vector<Step> steps;
    std::vector<OneRingVertex> one_ring;
  };
  Pattern pattern;
};

/// The operator of `scheme` (a dual-split scheme) at a face of k sides.
/// Throws InvalidInputError where the two-ring neighbourhood is not
/// invariant or the analysis finds no subdominant eigenvalue.
DualFaceOperator dual_face_operator(const Scheme& scheme, int k, const RefineOptions& rules = {});

/// Face f's two-ring neighbourhood in the operator's column order, or
/// nothing when f does not have the canonical one (another face with != 4
/// sides, a vertex with != 4 faces or the boundary within it, or a mesh so
/// small that it wraps around).
std::optional<Eigen::MatrixXd> canonical_neighbourhood(const DualFaceOperator& op, const MeshTopology& topology,
                                                       const std::vector<Vec3>& positions, Index f);

/// sup over m >= 0 of rate^-m max(|D_v S^m P|, |sigma S^m P| / 4) over the
/// operator's functionals, for the neighbourhood P (rows in column order):
/// the amplitude of the face's term. The sequence settles geometrically
/// (ratio |lambda_3 / lambda_1|), so `powers` steps reach its supremum
/// to rounding.
/// Faces the canonical layout does not cover (at the boundary): the
/// operator read off the mesh itself, with the neighbourhood's vertices in
/// vertex order as columns. `step` is the stencil table of one step from
/// `parent` to `child`. Nothing when the child's neighbourhood of face f
/// (the F-face of f is child face f) does not repeat the parent's, when its
/// rows reach outside it, or when its spectrum is not 1 above |lambda_1| < 1.
/// `boundary_limit` weighs a boundary vertex's neighbours along the
/// boundary and itself (boundary_vertex_limit()).
std::optional<DualFaceOperator> local_face_operator(const MeshTopology& parent, const StencilTable& step,
                                                    const MeshTopology& child, Index f,
                                                    const std::array<double, 3>& boundary_limit);

/// Face f's two-ring neighbourhood in vertex order (local_face_operator's columns).
Eigen::MatrixXd local_neighbourhood(const MeshTopology& topology, const std::vector<Vec3>& positions, Index f);

double dual_face_amplitude(const DualFaceOperator& op, const Eigen::MatrixXd& neighbourhood, int powers = 64);

}  // namespace subdiv
