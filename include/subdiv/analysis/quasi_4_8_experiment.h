#pragma once
// The quasi 4-8 scheme's "numerical experiments on the eigenstructure"
// (Velho, section 5.2). Its split depends on the geometry, so there is no
// canonical ring mesh: the experiment refines a planar control mesh (the
// n-regular neighbourhood of section 4.1, or any mesh and vertex) for
// `warmup` binary steps, records the two next steps (one 4-8 step, the
// scheme's period) as stencils, and reads the local subdivision matrix off
// them around the centre:
//   - the r-ring of the centre at both levels is numbered canonically by a
//     breadth-first walk over the counter-clockwise rings, from a reference
//     edge followed through both steps (the centre's half of it when it
//     splits), each later vertex's ring from the edge to its parent;
//   - it is usable when both numbered neighbourhoods have the same
//     combinatorics (valences and adjacency inside the neighbourhood) and
//     every row of the finer one has its weights inside the coarser one
//     (invariance); the smallest such r is taken.
// The matrix holds for this geometry only (another one may split otherwise),
// which is what "quasi-stationary" means. The spectrum's eigenvalue part of
// Reif's criterion is checked exactly; the characteristic map only through
// a piecewise-linear approximation: the subdominant eigenvectors placed on
// the coarse neighbourhood are refined `charmap_steps` more 4-8 steps with
// the recorded stencils, and the faces whose three vertices depend on the
// neighbourhood alone must all be oriented alike, with the centre's ring
// winding once around the centre's image. A failure refutes C1 (at this
// resolution); success is evidence, not a proof.

#include <Eigen/Core>
#include <complex>
#include <span>
#include <string>
#include <vector>

#include "subdiv/analysis/spectrum.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

struct Quasi48Experiment {
  int warmup = 0;          ///< binary steps before the matrix
  int centre_valence = 0;  ///< at level `warmup`
  int rings = 0;           ///< of the invariant neighbourhood; 0: none found
  int size = 0;            ///< its vertices
  Eigen::MatrixXd S;       ///< two binary steps, neighbourhood to neighbourhood
  Spectrum spectrum;
  std::vector<std::complex<double>> leading;  ///< lambda_0 .. lambda_4
  /// lambda_0 = 1 simple, lambda_1 = lambda_2 real, 1 > lambda_1 > |lambda_3|.
  bool eigenvalue_condition = false;
  std::string note;  ///< why no matrix, or which condition fails
  /// The piecewise-linear characteristic map (when the eigenvalue
  /// condition holds): faces checked, faces against the majority
  /// orientation or degenerate, the centre ring's winding number.
  int charmap_faces = 0;
  int charmap_flipped = 0;
  int charmap_winding = 0;
  bool charmap_regular = false;  ///< charmap_faces > 0, none flipped, winding +-1
};

/// A map given on a neighbourhood of a level (`vertices`, the centre first;
/// `values`, their images in the plane: x and y), refined `steps` 4-8 steps
/// with the stencils of the level's own geometry and read where it depends
/// on the neighbourhood alone.
struct PiecewiseLinearMap {
  int faces = 0;         ///< faces whose three vertices are known
  int flipped = 0;       ///< against the majority orientation, or flat
  int winding = 0;       ///< of the centre's ring around the centre's image
  bool regular = false;  ///< faces > 0, none flipped, winding +-1
};
PiecewiseLinearMap piecewise_linear_map(const PolygonMesh& coarse, std::span<const Index> vertices,
                                        std::span<const Vec3> values, int steps);

/// The experiment at vertex `centre` of a triangle mesh (quasi-4-8's
/// standard options, boundary fixed). rings are tried from 1 to max_rings.
Quasi48Experiment quasi_4_8_experiment(const PolygonMesh& control, Index centre, int warmup, int max_rings = 6,
                                       int charmap_steps = 2);

/// The same on the regular n-gon of radius 1 triangulated around its
/// centre (section 4.1's n-regular neighbourhood).
Quasi48Experiment quasi_4_8_ngon_experiment(int n, int warmup, int max_rings = 6, int charmap_steps = 2);

}  // namespace subdiv
