#pragma once
// A subdivision scheme as a runtime value: its refinement rule and its masks.
// A mask is a function from a local neighbourhood of the parent level to
// weights over parent vertices; masks never read or write positions. The same
// masks feed the fast path (positions written directly) and recorded stencil
// tables, so refinement and analysis share one code path.

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/topology/split.h"

namespace subdiv {

/// How a vertex is treated, from the sharp edges around it (boundary,
/// non-manifold and infinitely sharp crease edges) and its tags: the survey's
/// smooth, dart, crease and corner vertices.
enum class VertexRule : std::uint8_t {
  smooth,  ///< no sharp edge
  dart,    ///< one sharp edge (interior): smooth rule
  crease,  ///< two sharp edges: the curve rule along them
  corner,  ///< three or more sharp edges, a corner tag, a boundary corner, or no ordered ring: fixed
};

const char* to_string(VertexRule);

/// Everything a mask may look at: the parent level and its classification.
struct LevelView {
  const PolygonMesh& mesh;
  const MeshTopology& topology;
  std::span<const std::uint8_t> edge_sharp;  ///< per edge: boundary, non-manifold or infinitely sharp
  std::span<const VertexRule> vertex_rule;   ///< per vertex
};

/// Collects (parent vertex, weight) pairs for one child vertex.
class MaskBuilder {
 public:
  void clear() {
    vertices_.clear();
    weights_.clear();
  }
  void add(Index vertex, double weight) {
    vertices_.push_back(vertex);
    weights_.push_back(weight);
  }
  std::span<const Index> vertices() const { return vertices_; }
  std::span<const double> weights() const { return weights_; }
  std::size_t size() const { return vertices_.size(); }

 private:
  std::vector<Index> vertices_;
  std::vector<double> weights_;
};

using MaskFunction = void (*)(const LevelView& level, Index element, MaskBuilder& mask);

struct Scheme {
  std::string_view name;      ///< as users type it: "catmull-clark", "loop-warren"
  std::string_view summary;   ///< one line
  std::string_view citation;  ///< the paper the rules come from
  SplitRule split;
  bool needs_triangles = false;
  MaskFunction face_point = nullptr;  ///< quad split only
  MaskFunction edge_point = nullptr;
  MaskFunction vertex_point = nullptr;
};

/// Every scheme, in the order `subdiv schemes` lists them.
std::span<const Scheme* const> all_schemes();
/// The scheme with this name, or nullptr.
const Scheme* find_scheme(std::string_view name);

}  // namespace subdiv
