#pragma once
/// \file
/// Hierarchical edits: changes to one vertex, edge or face of a refined
/// level, named by a path from a control face, as OpenSubdiv's Hbr reads
/// them from `t vertexedit`, `t edgeedit` and `t faceedit` tags
/// (docs/formats.md, "Hierarchical edits").
///
/// A path is a control face, then one child per level (the child at the
/// parent's corner of that number), then a corner of the face it reaches.
/// Corners count as Hbr counts them: a quad's child keeps its parent's
/// parametric orientation, so child i's corner i is the parent's vertex;
/// another polygon's child starts at it.

#include <cstddef>
#include <vector>

#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/tags.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// What an edit does with the value it carries.
enum class EditOperation {
  set,       ///< replace the value
  add,       ///< add to the value
  subtract,  ///< subtract from the value
};

/// A control face, then the child taken at each level.
struct EditPath {
  Index face = kInvalidIndex;  ///< the control face
  std::vector<int> subfaces;   ///< one child per level; its size is the edit's level
  /// Member-wise equality.
  /// \param a first path.
  /// \param b second path.
  /// \return whether face and subfaces are equal.
  friend bool operator==(const EditPath& a, const EditPath& b) = default;
};

/// An edit of one vertex's position on the path's level (Hbr's vertex edit
/// of `P value`). The level's later levels are refined from the edited
/// position.
struct VertexValueEdit {
  EditPath path;                              ///< the face the vertex is a corner of
  int corner = 0;                             ///< the vertex's corner in that face
  EditOperation operation = EditOperation::add;  ///< set, add or subtract
  Vec3 value;                                 ///< the position, or the offset
};

/// An edit of a vertex's sharpness (corner sharpness, `vertexedit ... P
/// sharpness`) or of an edge's (`edgeedit ... P sharpness`: the edge from
/// the corner to the next) on the path's level. The result is clamped to
/// [0, kInfiniteSharpness], as Hbr clamps it.
struct SharpnessEdit {
  EditPath path;                                 ///< the face the vertex or edge belongs to
  int corner = 0;                                ///< the vertex's corner, or the edge's first corner
  bool edge = false;                             ///< an edge's sharpness rather than a vertex's
  EditOperation operation = EditOperation::set;  ///< set, add or subtract
  double sharpness = 0.0;                        ///< the sharpness, or the change
};

/// Every hierarchical edit of a mesh.
struct HierarchicalEdits {
  std::vector<VertexValueEdit> values;     ///< vertex position edits
  std::vector<SharpnessEdit> sharpnesses;  ///< vertex and edge sharpness edits
  std::vector<EditPath> holes;             ///< faces made holes (`faceedit ... hole`)

  /// Whether there is no edit.
  /// \return true when all three lists are empty.
  bool empty() const noexcept { return values.empty() && sharpnesses.empty() && holes.empty(); }
  /// The deepest level any edit applies on.
  /// \return the longest path's child count; -1 when empty().
  int deepest_level() const noexcept;
};

/// Whether `tag` is a hierarchical edit (`vertexedit`, `edgeedit` or
/// `faceedit`).
/// \param tag a tag kept verbatim.
/// \return true for the three edit tags.
bool is_hierarchical_edit(const RawTag& tag) noexcept;

/// The hierarchical edits among `tags.other`, read as Hbr reads them
/// (OpenSubdiv's regression/common/hbr_utils.h): each tag lists paths, each
/// path its length first; a vertex or edge edit's float arguments hold, for
/// each path, the values of its operations (three for a value, one for a
/// sharpness). Only the position `P` is edited. Paths are checked against
/// `mesh`: the control face exists, the first child is one of its corners,
/// later children and the corner are 0 to 3 (quads), or, on the control
/// face itself, one of its corners.
/// \param tags the mesh's tags.
/// \param mesh the control mesh the paths start from.
/// \return the edits, in the tags' order.
/// \throws InvalidInputError naming the tag (its rank among `tags.other`,
///   from 1) where a tag is malformed: a path too short or running past the
///   integer arguments, too few float arguments, an operation other than
///   set, add or subtract, a variable other than P, an edit other than value
///   (vertexedit), sharpness or hole, or a path that leaves the mesh.
HierarchicalEdits read_hierarchical_edits(const Tags& tags, const PolygonMesh& mesh);

/// The level one edit tag applies on: the deepest of its paths' levels.
/// \param tag an edit tag (is_hierarchical_edit()).
/// \param rank its rank among the mesh's `tags.other`, from 1, which errors
///   name.
/// \param mesh the control mesh the paths start from.
/// \return the number of children on its longest path.
/// \throws InvalidInputError where the tag is malformed, as
///   read_hierarchical_edits() says.
int hierarchical_edit_level(const RawTag& tag, std::size_t rank, const PolygonMesh& mesh);

/// Whether refine() and refine_hierarchy() apply a mesh's hierarchical edits
/// with `scheme`: schemes of a single step on the quad split (Catmull-Clark,
/// bilinear, Kobbelt, ...), whose children Hbr's paths name. Other schemes
/// ignore the edit tags, as every refined level drops uninterpreted tags.
/// \param scheme the scheme.
/// \return true where the paths name the scheme's faces.
bool applies_hierarchical_edits(const Scheme& scheme) noexcept;

}  // namespace subdiv
