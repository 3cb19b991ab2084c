#pragma once
// The characteristic map (Zorin's survey, section 5, after Reif 1995): the
// planar limit map whose control points are the subdominant eigenvectors of
// the local subdivision matrix. Refined several levels with the scheme's own
// rules, its control net is tested for regularity (every face keeps one
// orientation: the Jacobian has one sign) and injectivity (the outline of
// the region is a simple polygon, so the locally injective map is one to
// one). Only the part of the ring whose refinement depends on the
// neighbourhood alone is used.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "subdiv/refine/subdivision_matrix.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv {

struct CharacteristicMap {
  int levels = 0;  ///< analysis steps (the scheme's period refinement steps each)
  /// The refined control net of the map: positions (x, y, 0), faces.
  PolygonMesh image;
  /// Per face of `image`: the sector of the ring it lies in (0 .. k-1) and
  /// its orientation (+1, -1, or 0 when degenerate or folded).
  std::vector<int> face_sector;
  std::vector<int> face_orientation;
  /// Every face has one orientation (the Jacobian has one sign).
  bool regular = false;
  /// Regular, and the outline of the image is a simple polygon.
  bool injective = false;
  /// Why not regular or injective, when so.
  std::string note;
};

/// The map with control points (x_i, y_i) on the neighbourhood of `matrix`
/// (in its order), refined `levels` analysis steps (levels * matrix.period
/// refinement steps) with `scheme`.
CharacteristicMap characteristic_map(const Scheme& scheme, const LocalSubdivisionMatrix& matrix,
                                     const Eigen::VectorXd& x, const Eigen::VectorXd& y, int levels = 4);

}  // namespace subdiv
