// Hierarchical edits: read from OpenSubdiv's tag syntax, then followed down
// the quad split's levels and applied to each level as it is made.

#include "subdiv/refine/hierarchical_edits.h"

#include <algorithm>
#include <string>

#include "subdiv/core/error.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "hierarchical_edits_detail.h"

namespace subdiv {

namespace {

// Reads one tag; `rank` (from 1) names it in errors.
class EditTagReader {
 public:
  EditTagReader(const RawTag& tag, std::size_t rank, const PolygonMesh& mesh)
      : tag_(tag), mesh_(mesh), what_(tag.name + " tag " + std::to_string(rank)) {}

  void read_into(HierarchicalEdits& edits) const {
    if (tag_.name == "faceedit") return read_face_edit(edits);
    // Each operation is three strings: set/add/subtract, the variable, and
    // what is edited; its floats follow those of the operations before it.
    if (tag_.strings.empty() || tag_.strings.size() % 3 != 0)
      fail("expected operations of three strings (add P value, set P sharpness, ...)");
    struct Operation {
      EditOperation op;
      bool sharpness;
      std::size_t first_float;
    };
    std::vector<Operation> ops;
    std::size_t stride = 0;
    for (std::size_t j = 0; j < tag_.strings.size(); j += 3) {
      const std::string& modifier = tag_.strings[j];
      const std::string& variable = tag_.strings[j + 1];
      const std::string& what = tag_.strings[j + 2];
      if (variable != "P") fail("edits the variable '" + variable + "': only P is supported");
      const bool sharpness = what == "sharpness";
      if (!sharpness && !(what == "value" && tag_.name == "vertexedit"))
        fail("cannot edit '" + what + "' (vertexedit: value or sharpness; edgeedit: sharpness)");
      ops.push_back({operation(modifier), sharpness, stride});
      stride += sharpness ? 1 : 3;
    }
    std::size_t path_rank = 0;
    for (std::size_t k = 0; k < tag_.ints.size(); ++path_rank) {
      const long long length = tag_.ints[k];
      if (length < 2) fail("path " + std::to_string(path_rank + 1) + " has length " + std::to_string(length) +
                           " (a face, its children, then a corner: at least 2)");
      if (k + static_cast<std::size_t>(length) >= tag_.ints.size())
        fail("path " + std::to_string(path_rank + 1) + " runs past the integer arguments");
      const auto* p = tag_.ints.data() + k + 1;
      const EditPath path = checked_path(p, static_cast<std::size_t>(length) - 1);
      const int corner = checked_corner(path, p[length - 1]);
      const std::size_t floats = (path_rank + 1) * stride;
      if (tag_.floats.size() < floats)
        fail("has " + std::to_string(tag_.floats.size()) + " float arguments, path " + std::to_string(path_rank + 1) +
             " needs " + std::to_string(floats));
      for (const Operation& op : ops) {
        const double* f = tag_.floats.data() + path_rank * stride + op.first_float;
        if (op.sharpness)
          edits.sharpnesses.push_back({path, corner, tag_.name == "edgeedit", op.op, f[0]});
        else
          edits.values.push_back({path, corner, op.op, Vec3{f[0], f[1], f[2]}});
      }
      k += static_cast<std::size_t>(length) + 1;
    }
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw InvalidInputError(what_ + ": " + why); }

  EditOperation operation(const std::string& modifier) const {
    if (modifier == "set") return EditOperation::set;
    if (modifier == "add") return EditOperation::add;
    if (modifier == "subtract") return EditOperation::subtract;
    fail("unknown operation '" + modifier + "' (set, add or subtract)");
  }

  // A face edit's paths: the length counts the face and its children.
  void read_face_edit(HierarchicalEdits& edits) const {
    if (tag_.strings.size() != 1 || tag_.strings[0] != "hole")
      fail("only the face edit 'hole' is supported");
    std::size_t path_rank = 0;
    for (std::size_t k = 0; k < tag_.ints.size(); ++path_rank) {
      const long long length = tag_.ints[k];
      if (length < 1 || k + static_cast<std::size_t>(length) >= tag_.ints.size())
        fail("path " + std::to_string(path_rank + 1) + " has length " + std::to_string(length) +
             ", past the integer arguments");
      edits.holes.push_back(checked_path(tag_.ints.data() + k + 1, static_cast<std::size_t>(length)));
      k += static_cast<std::size_t>(length) + 1;
    }
  }

  // A control face then `count - 1` children.
  EditPath checked_path(const long long* p, std::size_t count) const {
    EditPath path;
    if (p[0] < 0 || p[0] >= static_cast<long long>(mesh_.face_count()))
      fail("face " + std::to_string(p[0]) + " is not a face of the mesh (" + std::to_string(mesh_.face_count()) +
           " faces)");
    path.face = static_cast<Index>(p[0]);
    for (std::size_t i = 1; i < count; ++i) {
      const long long bound = i == 1 ? mesh_.face_size(path.face) : 4;
      if (p[i] < 0 || p[i] >= bound)
        fail("child " + std::to_string(p[i]) + " of face " + std::to_string(path.face) + "'s path is not in 0.." +
             std::to_string(bound - 1));
      path.subfaces.push_back(static_cast<int>(p[i]));
    }
    return path;
  }

  int checked_corner(const EditPath& path, long long corner) const {
    const long long bound = path.subfaces.empty() ? mesh_.face_size(path.face) : 4;
    if (corner < 0 || corner >= bound)
      fail("corner " + std::to_string(corner) + " on face " + std::to_string(path.face) + "'s path is not in 0.." +
           std::to_string(bound - 1));
    return static_cast<int>(corner);
  }

  const RawTag& tag_;
  const PolygonMesh& mesh_;
  std::string what_;
};

double edited(double current, EditOperation op, double change) noexcept {
  switch (op) {
    case EditOperation::set: return change;
    case EditOperation::add: return current + change;
    case EditOperation::subtract: return current - change;
  }
  return current;
}

}  // namespace

int HierarchicalEdits::deepest_level() const noexcept {
  int deepest = -1;
  for (const auto& e : values) deepest = std::max(deepest, static_cast<int>(e.path.subfaces.size()));
  for (const auto& e : sharpnesses) deepest = std::max(deepest, static_cast<int>(e.path.subfaces.size()));
  for (const auto& p : holes) deepest = std::max(deepest, static_cast<int>(p.subfaces.size()));
  return deepest;
}

bool is_hierarchical_edit(const RawTag& tag) noexcept {
  return tag.name == "vertexedit" || tag.name == "edgeedit" || tag.name == "faceedit";
}

HierarchicalEdits read_hierarchical_edits(const Tags& tags, const PolygonMesh& mesh) {
  HierarchicalEdits edits;
  for (std::size_t i = 0; i < tags.other.size(); ++i)
    if (is_hierarchical_edit(tags.other[i])) EditTagReader(tags.other[i], i + 1, mesh).read_into(edits);
  return edits;
}

int hierarchical_edit_level(const RawTag& tag, std::size_t rank, const PolygonMesh& mesh) {
  HierarchicalEdits edits;
  EditTagReader(tag, rank, mesh).read_into(edits);
  return edits.deepest_level();
}

bool applies_hierarchical_edits(const Scheme& scheme) noexcept {
  return scheme.split == SplitRule::quad && !scheme.steps;
}

namespace detail {

EditFollower::EditFollower(HierarchicalEdits edits) : edits_(std::move(edits)) {
  for (const auto& e : edits_.values) located_.push_back({&e.path, e.path.face, 0});
  for (const auto& e : edits_.sharpnesses) located_.push_back({&e.path, e.path.face, 0});
  for (const auto& p : edits_.holes) located_.push_back({&p, p.face, 0});
}

bool EditFollower::edits_level(int level) const noexcept {
  return std::any_of(located_.begin(), located_.end(),
                     [&](const Located& at) { return at.path->subfaces.size() == static_cast<std::size_t>(level); });
}

void EditFollower::descend(const MeshTopology& parent, int parent_level) {
  const auto depth = static_cast<std::size_t>(parent_level);
  for (Located& at : located_) {
    if (at.path->subfaces.size() <= depth) continue;
    const int child = at.path->subfaces[depth];
    const Index n = parent.face_size(at.face);
    // Hbr's corner i is this face's corner i - rotation; the quad split's
    // child face of a corner is numbered as the corner (quad_split.cpp).
    const Index corner = ((child - at.rotation) % n + n) % n;
    at.face = parent.face_first_corner(at.face) + corner;
    at.rotation = n == 4 ? child : 0;
  }
}

void EditFollower::apply(int level, PolygonMesh& mesh) const {
  const auto depth = static_cast<std::size_t>(level);
  std::size_t i = 0;
  auto vertex_at = [&](const Located& at, int hbr_corner, int offset = 0) {
    const Index n = mesh.face_size(at.face);
    const Index corner = ((hbr_corner - at.rotation + offset) % n + n) % n;
    return mesh.face_indices[static_cast<std::size_t>(mesh.face_offsets[static_cast<std::size_t>(at.face)] + corner)];
  };
  for (const auto& e : edits_.values) {
    const Located& at = located_[i++];
    if (e.path.subfaces.size() != depth) continue;
    Vec3& p = mesh.positions[static_cast<std::size_t>(vertex_at(at, e.corner))];
    if (e.operation == EditOperation::set) p = e.value;
    else if (e.operation == EditOperation::add) p = p + e.value;
    else p = p - e.value;
  }
  for (const auto& e : edits_.sharpnesses) {
    const Located& at = located_[i++];
    if (e.path.subfaces.size() != depth) continue;
    const Index v = vertex_at(at, e.corner);
    // The tagged sharpness (0 where untagged), edited and clamped; a tag is
    // added only for a sharpness above 0.
    auto edit_tag = [&](auto& tags, auto is_it, auto make) {
      auto it = std::find_if(tags.begin(), tags.end(), is_it);
      const double s = std::clamp(edited(it == tags.end() ? 0.0 : it->sharpness, e.operation, e.sharpness), 0.0,
                                  kInfiniteSharpness);
      if (it != tags.end()) it->sharpness = s;
      else if (s > 0.0) tags.push_back(make(s));
    };
    if (e.edge) {
      const Index w = vertex_at(at, e.corner, 1);
      edit_tag(
          mesh.tags.creases,
          [&](const CreaseTag& t) { return (t.v0 == v && t.v1 == w) || (t.v0 == w && t.v1 == v); },
          [&](double s) { return CreaseTag{v, w, s}; });
    } else {
      edit_tag(
          mesh.tags.corners, [&](const CornerTag& t) { return t.vertex == v; },
          [&](double s) {
            CornerTag tag;
            tag.vertex = v;
            tag.sharpness = s;
            return tag;
          });
    }
  }
  for (const auto& p : edits_.holes) {
    const Located& at = located_[i++];
    if (p.subfaces.size() != depth) continue;
    auto& holes = mesh.tags.holes;
    if (std::find(holes.begin(), holes.end(), at.face) == holes.end()) holes.push_back(at.face);
  }
}

}  // namespace detail

}  // namespace subdiv
