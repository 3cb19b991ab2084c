#pragma once
// OpenSubdiv's Hbr (the header-only hierarchical refiner libosd-dev
// installs) behind an interface of standard types: Hbr's headers compile as
// C++17 only, so hbr_refiner.cpp is built as C++17 and includes nothing of
// subdiv.

#include <cstddef>
#include <vector>

namespace subdiv::test::hbr {

/// One hierarchical edit, as Hbr's edit classes take it.
struct Edit {
  enum class Kind { value, corner_sharpness, edge_sharpness, hole } kind = Kind::value;
  enum class Operation { set, add, subtract } operation = Operation::set;
  int face = 0;               ///< the control face
  std::vector<int> subfaces;  ///< one child per level
  int corner = 0;             ///< the vertex's corner, or the edge's first (not for holes)
  double value[3] = {0, 0, 0};  ///< a value edit's position or offset
  double sharpness = 0.0;       ///< a sharpness edit's sharpness or change
};

/// A control mesh for Hbr's Catmull-Clark.
struct Input {
  std::vector<double> positions;   ///< x, y, z per vertex
  std::vector<int> face_sizes;     ///< corners per face
  std::vector<int> face_vertices;  ///< every face's vertices in turn
  bool edge_only = false;          ///< boundary interpolation edge-only, else edge-and-corner
  std::vector<Edit> edits;         ///< in the order Hbr is given them
};

/// The finest level.
struct Level {
  std::vector<double> positions;  ///< x, y, z per vertex, in Hbr's order
  std::size_t faces = 0;          ///< faces of the level
  std::size_t holes = 0;          ///< of which holes
};

/// `input` refined `levels` times as OpenSubdiv's Hbr regression harness
/// refines (every face of a level, level after level), with every vertex of
/// the finest level asked for its pending edits (HbrVertex::
/// GuaranteeNeighbors) before it is read.
Level refine_catmark(const Input& input, int levels);

}  // namespace subdiv::test::hbr
