#pragma once
// Finds everything that makes a mesh unusable for subdivision, and says
// where: element index and, for meshes read from a file, the line.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "subdiv/core/error.h"
#include "subdiv/core/types.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/source_lines.h"

namespace subdiv {

class MeshTopology;

enum class IssueKind : std::uint8_t {
  index_out_of_range,       ///< a face refers to a vertex that does not exist
  face_too_small,           ///< a face with fewer than 3 vertices
  repeated_vertex,          ///< a face uses the same vertex twice
  non_finite_coordinate,    ///< NaN or infinite position
  non_manifold_edge,        ///< an edge shared by more than two faces
  non_manifold_vertex,      ///< the faces around a vertex form several fans
  inconsistent_orientation, ///< two faces traverse their shared edge the same way
  invalid_tag,              ///< a tag names a missing edge, vertex or face, or a bad value
  invalid_channel,          ///< a data channel's size or indices do not fit the mesh
  isolated_vertex,          ///< a vertex used by no face (a warning)
};
inline constexpr int kIssueKindCount = 10;

enum class Severity : std::uint8_t { warning, error };

struct ValidationIssue {
  IssueKind kind;
  Severity severity;
  Index element;        ///< face, vertex, edge or tag index, by kind
  std::uint32_t line;   ///< 1-based line in the source file, 0 = unknown
  std::string message;  ///< names the element; no file or line prefix
};

struct ValidationOptions {
  /// Issues of one kind beyond this many are counted but not itemised.
  std::size_t max_issues_per_kind = 100;
};

struct ValidationReport {
  std::vector<ValidationIssue> issues;        ///< at most max_issues_per_kind of each kind
  std::array<std::size_t, kIssueKindCount> counts{};  ///< all issues, by kind

  std::size_t count(IssueKind k) const { return counts[static_cast<std::size_t>(k)]; }
  std::size_t error_count() const;
  std::size_t warning_count() const;
  bool ok() const { return error_count() == 0; }
  /// The first error's message with its location ("path:line: ..."), or "".
  std::string first_error(const std::string& path = {}) const;
};

const char* to_string(IssueKind);
Severity severity_of(IssueKind);

/// Reports every defect of the mesh. Never throws for a malformed mesh: an
/// out-of-range index is reported and the topological checks are skipped.
ValidationReport validate(const PolygonMesh& mesh, const SourceLines* lines = nullptr,
                          const ValidationOptions& options = {});
/// Same, reusing an already built topology.
ValidationReport validate(const PolygonMesh& mesh, const MeshTopology& topology,
                          const SourceLines* lines = nullptr, const ValidationOptions& options = {});

/// "path:line: message" (omitting what is unknown).
std::string format_issue(const ValidationIssue& issue, const std::string& path = {});

/// Thrown by require_valid(); carries the whole report.
class ValidationError : public TopologyError {
 public:
  ValidationError(ValidationReport report, const std::string& path);
  const ValidationReport& report() const { return report_; }

 private:
  ValidationReport report_;
};

/// Throws ValidationError naming the first error if the report has errors.
void require_valid(const ValidationReport& report, const std::string& path = {});

}  // namespace subdiv
