#pragma once
/// \file
/// The characteristic map (Zorin's survey, section 5, after Reif 1995): the
/// planar limit map whose control points are the subdominant eigenvectors of
/// the local subdivision matrix. Refined several levels with the scheme's own
/// rules, its control net is tested for regularity (every face keeps one
/// orientation: the Jacobian has one sign) and injectivity (the outline of
/// the region is a simple polygon, so the locally injective map is one to
/// one). Only the part of the ring whose refinement depends on the
/// neighbourhood alone is used.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

/// The refined control net of a characteristic map and whether it is
/// regular and injective.
struct CharacteristicMap {
  int levels = 0;  ///< analysis steps (the scheme's period refinement steps each)
  /// The refined control net of the map: positions (x, y, 0), faces.
  PolygonMesh image;
  /// Per face of `image`: the sector of the ring it lies in (0 .. k-1).
  std::vector<int> face_sector;
  /// Per face of `image`: its orientation (+1, -1, or 0 when degenerate or
  /// folded).
  std::vector<int> face_orientation;
  /// Every face has one orientation (the Jacobian has one sign).
  bool regular = false;
  /// Regular, and the outline of the image is a simple polygon.
  bool injective = false;
  /// Why not regular or injective, when so.
  std::string note;
};

/// The map with control points (x_i, y_i) on the neighbourhood of \p matrix
/// (in its order), refined \p levels analysis steps (levels * matrix.period
/// refinement steps) with \p scheme, under `matrix.rules`, on the ring mesh
/// the matrix was read from. Only the faces whose vertices depend on the
/// neighbourhood alone are kept.
/// \param scheme The scheme the matrix was read from.
/// \param matrix The local subdivision matrix: its configuration, rings,
///        layout, period and rules place the control points.
/// \param x The first coordinate of each neighbourhood vertex (usually the
///        first subdominant eigenvector), one entry per row of `matrix.S`.
/// \param y The second coordinate, likewise.
/// \param levels Analysis steps to refine, at least 1.
/// \return The refined net, its sectors and orientations, and the
///         regularity and injectivity verdicts with a note when they fail.
/// \throws InvalidInputError if \p x or \p y does not have one entry per
///         row of `matrix.S`, \p levels is below 1, the matrix's layout is not
///         that of the scheme's ring mesh, or refinement rejects the ring mesh.
/// \throws std::bad_alloc if memory runs out.
CharacteristicMap characteristic_map(const Scheme& scheme, const LocalSubdivisionMatrix& matrix,
                                     const Eigen::VectorXd& x, const Eigen::VectorXd& y, int levels = 4);

}  // namespace subdiv
