#pragma once
/// \file
/// The quasi 4-8 scheme's "numerical experiments on the eigenstructure"
/// (Velho, section 5.2). Its split depends on the geometry, so there is no
/// canonical ring mesh: the experiment refines a planar control mesh (the
/// n-regular neighbourhood of section 4.1, or any mesh and vertex) for
/// `warmup` binary steps, records the two next steps (one 4-8 step, the
/// scheme's period) as stencils, and reads the local subdivision matrix off
/// them around the centre:
///   - the r-ring of the centre at both levels is numbered canonically by a
///     breadth-first walk over the counter-clockwise rings, from a reference
///     edge followed through both steps (the centre's half of it when it
///     splits), each later vertex's ring from the edge to its parent;
///   - it is usable when both numbered neighbourhoods have the same
///     combinatorics (valences and adjacency inside the neighbourhood) and
///     every row of the finer one has its weights inside the coarser one
///     (invariance); the smallest such r is taken.
/// The matrix holds for this geometry only (another one may split otherwise),
/// which is what "quasi-stationary" means. The spectrum's eigenvalue part of
/// Reif's criterion is checked exactly; the characteristic map only through
/// a piecewise-linear approximation: the subdominant eigenvectors placed on
/// the coarse neighbourhood are refined `charmap_steps` more 4-8 steps with
/// the recorded stencils, and the faces whose three vertices depend on the
/// neighbourhood alone must all be oriented alike, with the centre's ring
/// winding once around the centre's image. A failure refutes C1 (at this
/// resolution); success is evidence, not a proof.

#include <Eigen/Core>
#include <complex>
#include <span>
#include <string>
#include <vector>

#include "subdiv/analysis/spectrum.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

/// The result of the quasi 4-8 experiment at one vertex: the local
/// subdivision matrix of this geometry, its spectrum, the eigenvalue
/// condition, and the piecewise-linear characteristic map's checks.
struct Quasi48Experiment {
  int warmup = 0;          ///< binary steps before the matrix
  int centre_valence = 0;  ///< at level `warmup`
  int rings = 0;           ///< of the invariant neighbourhood; 0: none found
  int size = 0;            ///< its vertices
  Eigen::MatrixXd S;       ///< two binary steps, neighbourhood to neighbourhood
  Spectrum spectrum;        ///< of S
  std::vector<std::complex<double>> leading;  ///< lambda_0 .. lambda_4
  /// lambda_0 = 1 simple, lambda_1 = lambda_2 real, 1 > lambda_1 > |lambda_3|.
  bool eigenvalue_condition = false;
  std::string note;  ///< why no matrix, or which condition fails
  /// The piecewise-linear characteristic map (checked when the eigenvalue
  /// condition holds and `charmap_steps` > 0): the faces checked.
  int charmap_faces = 0;
  int charmap_flipped = 0;  ///< of `charmap_faces`: against the majority orientation, or degenerate
  int charmap_winding = 0;  ///< the centre ring's winding number around the centre's image
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

/// Refines the map given by \p values on the neighbourhood \p vertices of
/// \p coarse \p steps 4-8 steps (2 * steps binary steps of quasi-4-8, with
/// the stencils of \p coarse's own geometry) and checks the image's faces
/// whose three vertices depend on the neighbourhood alone.
/// \param coarse The triangle mesh of the level the map is given on.
/// \param vertices The neighbourhood's vertices of \p coarse, the centre
///        first.
/// \param values Each neighbourhood vertex's image in the plane (x and y; z
///        is ignored), one per entry of \p vertices.
/// \param steps 4-8 steps to refine, at least 1.
/// \return The faces checked, the flipped ones, and the winding number.
/// \pre Every entry of \p vertices is a vertex of \p coarse.
/// \throws InvalidInputError if \p vertices and \p values differ in size or
///         are empty, \p steps < 1, or quasi-4-8 refinement rejects
///         \p coarse.
/// \throws std::bad_alloc if memory runs out.
PiecewiseLinearMap piecewise_linear_map(const PolygonMesh& coarse, std::span<const Index> vertices,
                                        std::span<const Vec3> values, int steps);

/// The experiment at vertex \p centre of a triangle mesh (quasi-4-8's
/// standard options, boundary fixed). rings are tried from 1 to max_rings.
/// \param control The planar triangle control mesh.
/// \param centre The vertex of \p control the matrix is read around (it
///        keeps its index through the warm-up steps).
/// \param warmup Binary steps taken before the matrix, at least 0.
/// \param max_rings The largest r-ring tried for the invariant neighbourhood.
/// \param charmap_steps 4-8 steps the piecewise-linear characteristic map is
///        refined; 0 skips the map.
/// \return The experiment; `rings` is 0 and `note` says why when no
///         invariant neighbourhood is found.
/// \throws InvalidInputError if \p warmup < 0, \p centre is not a vertex of
///         \p control or has no edges, or quasi-4-8 refinement rejects
///         \p control.
/// \throws Error if the Schur iteration of the eigenvalue computation does
///         not converge.
/// \throws std::bad_alloc if memory runs out.
Quasi48Experiment quasi_4_8_experiment(const PolygonMesh& control, Index centre, int warmup, int max_rings = 6,
                                       int charmap_steps = 2);

/// The same on the regular n-gon of radius 1 triangulated around its
/// centre (section 4.1's n-regular neighbourhood).
/// \param n The number of triangles around the centre, at least 3.
/// \param warmup Binary steps taken before the matrix, at least 0.
/// \param max_rings The largest r-ring tried for the invariant neighbourhood.
/// \param charmap_steps 4-8 steps the piecewise-linear characteristic map is
///        refined; 0 skips the map.
/// \return The experiment at the n-gon's centre.
/// \throws InvalidInputError if \p n < 3 or \p warmup < 0.
/// \throws Error if the Schur iteration of the eigenvalue computation does
///         not converge.
/// \throws std::bad_alloc if memory runs out.
Quasi48Experiment quasi_4_8_ngon_experiment(int n, int warmup, int max_rings = 6, int charmap_steps = 2);

}  // namespace subdiv
