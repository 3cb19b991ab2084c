#pragma once
// The local configurations a scheme is analysed at (Zorin's survey, section
// 2.1): an interior vertex of valence k, a boundary (or crease) vertex with k
// faces in its sector, and a convex or concave corner with k faces.

#include <string>

#include "subdiv/mesh/tags.h"

namespace subdiv {

struct Configuration {
  enum class Kind { interior, boundary, corner };
  Kind kind = Kind::interior;
  /// Valence (interior) or number of faces in the sector (boundary, corner).
  int k = 6;
  /// Corners only: convex (sector angle pi/2 by default) or concave (3 pi/2).
  CornerType corner = CornerType::convex;
  /// Corners only: the sector angle alpha in radians; 0 for the type's
  /// default (pi/2 convex, 3 pi/2 concave).
  double angle = 0.0;

  /// The angle the k faces span in the canonical layout: 2 pi, pi, or the
  /// corner's angle (by default pi/2 convex, 3 pi/2 concave).
  double sector_angle() const;
  /// "interior k=5", "boundary k=3", "convex corner k=2".
  std::string name() const;
};

}  // namespace subdiv
