#pragma once
// The scheme-comparison page: one self-contained HTML file (three.js inlined,
// the meshes embedded) showing the control mesh and each scheme's result side
// by side, seen by one camera, with wireframe and cage toggles. It opens from
// a file, offline.

#include <string>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::compare {

/// One panel: a refined mesh and what its caption says.
struct Panel {
  std::string title;    // the scheme (or "control mesh")
  std::string caption;  // level, vertex and face counts, notes
  PolygonMesh mesh;
};

/// The page's HTML: `title` at the top, the panels in order, the edges of
/// `cage` drawn over each when the cage toggle is on (the default). Faces
/// tagged as holes are left out. Throws InvalidInputError when a panel has
/// no face to draw or more vertices than 32-bit indices hold.
std::string comparison_page(const std::string& title, const PolygonMesh& cage, const std::vector<Panel>& panels);

}  // namespace subdiv::compare
