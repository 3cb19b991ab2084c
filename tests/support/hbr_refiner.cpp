// Built as C++17 (tests/CMakeLists.txt): Hbr's headers name destructors with
// template arguments, which C++20 forbids.

#include "support/hbr_refiner.h"

// In the order Hbr's headers need (each assumes the ones before it).
#include <cassert>
#include <opensubdiv/hbr/mesh.h>
#include <opensubdiv/hbr/catmark.h>
#include <opensubdiv/hbr/vertexEdit.h>
#include <opensubdiv/hbr/cornerEdit.h>
#include <opensubdiv/hbr/creaseEdit.h>
#include <opensubdiv/hbr/holeEdit.h>

namespace subdiv::test::hbr {

namespace {

// Hbr's vertex data: a float position, edited as the harness edits it.
class Point {
 public:
  Point() = default;
  explicit Point(int /*id*/) {}  // Hbr makes vertex data from a vertex id
  Point(double x, double y, double z) : p_{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)} {}
  void Clear(void* = nullptr) { p_[0] = p_[1] = p_[2] = 0.0f; }
  void AddWithWeight(const Point& src, float weight, void* = nullptr) {
    for (int i = 0; i < 3; ++i) p_[i] += weight * src.p_[i];
  }
  void AddVaryingWithWeight(const Point&, float, void* = nullptr) {}
  void ApplyVertexEdit(const OpenSubdiv::HbrVertexEdit<Point>& edit) {
    const float* e = edit.GetEdit();
    for (int i = 0; i < 3; ++i) {
      switch (edit.GetOperation()) {
        case OpenSubdiv::HbrHierarchicalEdit<Point>::Set: p_[i] = e[i]; break;
        case OpenSubdiv::HbrHierarchicalEdit<Point>::Add: p_[i] += e[i]; break;
        case OpenSubdiv::HbrHierarchicalEdit<Point>::Subtract: p_[i] -= e[i]; break;
      }
    }
  }
  void ApplyMovingVertexEdit(const OpenSubdiv::HbrMovingVertexEdit<Point>&) {}
  const float* position() const { return p_; }

 private:
  float p_[3] = {0.0f, 0.0f, 0.0f};
};

using HierarchicalEdit = OpenSubdiv::HbrHierarchicalEdit<Point>;

HierarchicalEdit::Operation operation(Edit::Operation op) {
  switch (op) {
    case Edit::Operation::set: return HierarchicalEdit::Set;
    case Edit::Operation::add: return HierarchicalEdit::Add;
    case Edit::Operation::subtract: return HierarchicalEdit::Subtract;
  }
  return HierarchicalEdit::Set;
}

HierarchicalEdit* make_edit(const Edit& e) {
  std::vector<int> subfaces = e.subfaces;
  const int n = static_cast<int>(subfaces.size());
  const auto sharpness = static_cast<float>(e.sharpness);
  switch (e.kind) {
    case Edit::Kind::value: {
      float value[3] = {static_cast<float>(e.value[0]), static_cast<float>(e.value[1]), static_cast<float>(e.value[2])};
      return new OpenSubdiv::HbrVertexEdit<Point>(e.face, n, subfaces.data(), e.corner, 0, 3, true,
                                                  operation(e.operation), value);
    }
    case Edit::Kind::corner_sharpness:
      return new OpenSubdiv::HbrCornerEdit<Point>(e.face, n, subfaces.data(), e.corner, operation(e.operation),
                                                  sharpness);
    case Edit::Kind::edge_sharpness:
      return new OpenSubdiv::HbrCreaseEdit<Point>(e.face, n, subfaces.data(), e.corner, operation(e.operation),
                                                  sharpness);
    case Edit::Kind::hole:
      return new OpenSubdiv::HbrHoleEdit<Point>(e.face, n, subfaces.data());
  }
  return nullptr;
}

}  // namespace

Level refine_catmark(const Input& input, int levels) {
  static OpenSubdiv::HbrCatmarkSubdivision<Point> catmark;
  OpenSubdiv::HbrMesh<Point> mesh(&catmark);
  for (std::size_t v = 0; v * 3 < input.positions.size(); ++v)
    mesh.NewVertex(static_cast<int>(v),
                   Point(input.positions[3 * v], input.positions[3 * v + 1], input.positions[3 * v + 2]));
  const int* corners = input.face_vertices.data();
  for (const int n : input.face_sizes) {
    mesh.NewFace(n, corners, 0);
    corners += n;
  }
  mesh.SetInterpolateBoundaryMethod(input.edge_only ? OpenSubdiv::HbrMesh<Point>::k_InterpolateBoundaryEdgeOnly
                                                    : OpenSubdiv::HbrMesh<Point>::k_InterpolateBoundaryEdgeAndCorner);
  for (const Edit& e : input.edits) mesh.AddHierarchicalEdit(make_edit(e));  // the mesh deletes them
  mesh.Finish();

  int first_face = 0, last_face = mesh.GetNumFaces(), first_vertex = 0, last_vertex = mesh.GetNumVertices();
  for (int l = 0; l < levels; ++l) {
    for (int f = first_face; f < last_face; ++f) mesh.GetFace(f)->Refine();
    first_face = last_face;
    last_face = mesh.GetNumFaces();
    first_vertex = last_vertex;
    last_vertex = mesh.GetNumVertices();
  }
  Level out;
  for (int v = first_vertex; v < last_vertex; ++v) {
    mesh.GetVertex(v)->GuaranteeNeighbors();  // applies the vertex's pending edits
    const float* p = mesh.GetVertex(v)->GetData().position();
    for (int c = 0; c < 3; ++c) out.positions.push_back(static_cast<double>(p[c]));
  }
  for (int f = first_face; f < last_face; ++f) {
    ++out.faces;
    out.holes += mesh.GetFace(f)->IsHole() ? 1 : 0;
  }
  return out;
}

}  // namespace subdiv::test::hbr
