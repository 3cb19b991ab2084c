#pragma once
/// \file
/// The local configurations a scheme is analysed at (Zorin's survey, section
/// 2.1): an interior vertex of valence k, a boundary (or crease) vertex with k
/// faces in its sector, and a convex or concave corner with k faces.

#include <string>

#include "subdiv/mesh/tags.h"

namespace subdiv {

/// One local configuration: the kind of centre and its number of faces.
struct Configuration {
  /// The kind of centre vertex.
  enum class Kind {
    interior,  ///< an interior vertex of valence k
    boundary,  ///< a boundary (or crease) vertex with k faces in its sector
    corner,    ///< a corner with k faces (CornerType: convex or concave)
  };
  Kind kind = Kind::interior;  ///< the kind of centre
  /// Valence (interior) or number of faces in the sector (boundary, corner).
  int k = 6;
  /// Corners only: convex (sector angle pi/2 by default) or concave (3 pi/2).
  CornerType corner = CornerType::convex;
  /// Corners only: the sector angle alpha in radians; 0 for the type's
  /// default (pi/2 convex, 3 pi/2 concave).
  double angle = 0.0;

  /// The angle the k faces span in the canonical layout: 2 pi, pi, or the
  /// corner's angle (by default pi/2 convex, 3 pi/2 concave).
  /// \return the angle in radians.
  double sector_angle() const noexcept;
  /// "interior k=5", "boundary k=3", "convex corner k=2"; a corner with an
  /// angle adds it in whole degrees ("concave corner k=3 alpha=270deg").
  /// \return the name.
  /// \throws std::bad_alloc if memory runs out.
  std::string name() const;
};

}  // namespace subdiv
