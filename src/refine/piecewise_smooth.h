#pragma once
// The level data of the piecewise-smooth rules (Biermann, Levin and Zorin
// 2000, "Piecewise smooth subdivision surfaces with normal control"; Zorin's
// survey, sections 3.2 and 3.3), which the engine computes and the masks
// read:
//
// - Sector angles. An edge point on a smooth edge (v, w) next to a crease,
//   boundary or corner vertex v weights v with 3/4 - gamma(theta_k) and w
//   with gamma(theta_k) (each scheme's rule file has its gamma), where
//   theta_k = alpha / k, k the faces of v's sector that contains the edge
//   and alpha the angle the sector spans: pi at crease and boundary
//   vertices; at corners the tag's angle, else (boundary corners) pi/2
//   convex or untyped, 3 pi/2 concave, or the control mesh's angle when
//   measured; interior corners split the full turn evenly among their
//   sectors.
// - The flatness modification at concave corners: after each step, the
//   corner's one-ring p becomes (1 - s) p + s P p, P the spectral projector
//   of the corner's subdivision matrix onto the eigenvalues 1 and 1/2 (the
//   limit point and the two boundary-curve tangents, whose eigenvectors form
//   the concave corner), so every other eigenvalue is scaled by 1 - s. The
//   default s = 1 - (1/4) / lambda_3 brings the largest other eigenvalue
//   lambda_3 (> 1/2 at a concave corner: the "flip") down to 1/4. The
//   matrix is read off the scheme's own rules (refine/subdivision_matrix.h)
//   at the corner's configuration, with the modification off.

#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/refine/refine.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/topology/split.h"

namespace subdiv::detail {

/// Per vertex of the level: the angle alpha of its sectors, 0 where the
/// vertex is smooth or a dart (LevelView::sector_angle).
std::vector<double> sector_angles(const PolygonMesh& mesh, const MeshTopology& topology, const LevelCreasing& creasing);

/// Gives every corner tag on a boundary vertex that has no angle the angle
/// between the vertex's two boundary edges (2 pi minus it for a concave tag).
void measure_corner_angles(PolygonMesh& mesh, const MeshTopology& topology);

/// One concave corner: its one-ring one level down, in the order of the
/// corner configuration's subdivision matrix (centre, then counter-clockwise
/// from the first boundary edge), and the matrix that modifies it.
struct FlatnessSite {
  std::vector<Index> child_ring;
  std::shared_ptr<const Eigen::MatrixXd> modification;
};

/// The concave corners of a level where the flatness modification applies:
/// boundary corners whose single sector has alpha > pi and k >= 2 faces.
/// Empty unless options ask for the piecewise-smooth rules with s != 0.
std::vector<FlatnessSite> flatness_sites(const Scheme& scheme, const MeshTopology& parent,
                                         const LevelCreasing& creasing, std::span<const double> sector_angle,
                                         const SplitMap& map, const RefineOptions& options);

/// The modification applied to the child's positions and vertex channels.
void apply_flatness(const std::vector<FlatnessSite>& sites, PolygonMesh& child);
/// The same applied to the rows of a level's (or a composed) stencil table.
void apply_flatness(const std::vector<FlatnessSite>& sites, StencilTable& table);

/// The corner's flatness data, for tests and analysis: the projector P and
/// lambda_3 of `scheme`'s concave corner with k faces and angle alpha.
struct FlatnessSpectrum {
  Eigen::MatrixXd projector;
  double lambda3 = 0.0;
};
std::shared_ptr<const FlatnessSpectrum> flatness_spectrum(const Scheme& scheme, int k, double alpha);

}  // namespace subdiv::detail
