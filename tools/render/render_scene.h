#pragma once
// What a render draws, in single precision for the rasterizer: the
// surface's triangles with a normal per vertex, and line sets (wireframe,
// boundaries, creases, the control cage) drawn over it. Built from the
// library's meshes; nothing here draws.

#include <cstdint>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"

namespace subdiv::render {

struct Rgb {
  float r = 0.0F, g = 0.0F, b = 0.0F;
};

/// Segments of one colour and width (in output pixels): xyz of both ends.
struct LineSet {
  std::vector<float> ends;
  Rgb colour;
  float width = 1.0F;
};

/// The triangles to shade and the lines to draw, and the sphere that holds
/// them (for framing).
struct Scene {
  std::vector<float> positions;  // xyz per vertex
  std::vector<float> normals;    // xyz per vertex, unit or zero
  std::vector<std::uint32_t> triangles;
  std::vector<LineSet> lines;
  Vec3 centre;
  double radius = 0.0;
};

/// Which edges of the surface are drawn over it.
struct EdgeStyle {
  bool wireframe = false;  // every edge
  bool features = true;    // boundaries, infinitely sharp and semi-sharp creases, in colour
  bool flat = false;       // each face shaded by its own normal (a control mesh's facets)
};

/// The colours of the drawn edges (also the legend of docs/cli.md).
inline constexpr Rgb kWireColour{0.12F, 0.12F, 0.14F};
inline constexpr Rgb kBoundaryColour{0.10F, 0.35F, 0.90F};
inline constexpr Rgb kSharpColour{0.85F, 0.08F, 0.08F};
inline constexpr Rgb kSemiSharpColour{0.95F, 0.55F, 0.05F};
inline constexpr Rgb kCageColour{0.05F, 0.60F, 0.20F};

/// The surface of `mesh` (faces tagged as holes left out; polygons as fans):
/// `vertex_normals` where it holds one usable (non-zero) normal per vertex,
/// turned to the side of the faces around it, else the area-weighted
/// normal of the faces around the vertex; with EdgeStyle::flat, each face by
/// its own normal (its corners then get vertices of their own). Throws
/// InvalidInputError when
/// the mesh has no face to draw or more vertices than 32-bit indices hold.
Scene surface_scene(const PolygonMesh& mesh, const std::vector<Vec3>& vertex_normals, const EdgeStyle& edges);

/// Adds the edges of `cage` (the control mesh) to the scene, tagged edges
/// in their feature colours, the others in kCageColour.
void add_cage(Scene& scene, const PolygonMesh& cage);

/// Gives every scene the same centre and radius: the smallest sphere about
/// the first scene's centre that holds every scene's sphere, so that
/// pictures drawn with the same view show the same part of space.
void frame_together(std::vector<Scene*> scenes);

}  // namespace subdiv::render
