#pragma once
/// \file
/// Finds everything that makes a mesh unusable for subdivision, and says
/// where: element index and, for meshes read from a file, the line.

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

/// What kind of defect a ValidationIssue reports.
enum class IssueKind : std::uint8_t {
  index_out_of_range,       ///< a face refers to a vertex that does not exist, or the face offsets are malformed
  face_too_small,           ///< a face with fewer than 3 vertices
  repeated_vertex,          ///< a face uses the same vertex twice
  non_finite_coordinate,    ///< NaN or infinite position
  non_manifold_edge,        ///< an edge shared by more than two faces
  non_manifold_vertex,      ///< the faces around a vertex form several fans
  inconsistent_orientation, ///< two faces traverse their shared edge the same way
  invalid_tag,              ///< a tag names a missing edge, vertex or face, or a bad value
  invalid_channel,          ///< a data channel's size or indices do not fit the mesh
  isolated_vertex,          ///< a vertex used by no face nor polyline (a warning)
};
/// Number of IssueKind values (the size of ValidationReport::counts).
inline constexpr int kIssueKindCount = 10;

/// How bad an issue is: errors make a mesh unusable for subdivision,
/// warnings do not.
enum class Severity : std::uint8_t {
  warning,  ///< worth reporting; the mesh can still be subdivided
  error,    ///< the mesh cannot be subdivided as it is
};

/// One defect found by validate().
struct ValidationIssue {
  IssueKind kind;       ///< what is wrong
  Severity severity;    ///< severity_of(kind)
  Index element;        ///< face, vertex, edge or tag index, by kind
  std::uint32_t line;   ///< 1-based line in the source file, 0 = unknown
  std::string message;  ///< names the element; no file or line prefix
};

/// How much validate() itemises.
struct ValidationOptions {
  /// Issues of one kind beyond this many are counted but not itemised.
  std::size_t max_issues_per_kind = 100;
};

/// Everything validate() found: the issues, itemised up to a limit per
/// kind, and the full count of each kind.
struct ValidationReport {
  std::vector<ValidationIssue> issues;        ///< at most max_issues_per_kind of each kind, in discovery order
  std::array<std::size_t, kIssueKindCount> counts{};  ///< all issues, by kind

  /// Number of issues of kind \p k, itemised or not.
  /// \param k the kind; must be one of the enumerators.
  /// \return counts[k].
  std::size_t count(IssueKind k) const noexcept { return counts[static_cast<std::size_t>(k)]; }
  /// \return the number of issues whose kind is an error, itemised or not.
  std::size_t error_count() const noexcept;
  /// \return the number of issues whose kind is a warning, itemised or not.
  std::size_t warning_count() const noexcept;
  /// Whether the mesh is usable for subdivision; warnings do not count.
  /// \return error_count() == 0.
  bool ok() const noexcept { return error_count() == 0; }
  /// The first itemised error with its location, formatted by format_issue().
  /// \param path the file to name in the location; may be empty.
  /// \return "path:line: message" of the first listed error (omitting what
  ///         is unknown); when no error is listed (max_issues_per_kind = 0),
  ///         "path: N x KIND (not listed)" for the first kind counted; "" when
  ///         the report has no error.
  /// \throws std::bad_alloc if memory runs out.
  std::string first_error(const std::string& path = {}) const;
};

/// A readable name for an issue kind ("non-manifold edge", ...).
/// \param k the kind.
/// \return a static string; "?" for a value outside the enumeration.
const char* to_string(IssueKind k) noexcept;
/// The severity of an issue kind: isolated_vertex is a warning, every other
/// kind an error.
/// \param k the kind.
/// \return the kind's severity.
Severity severity_of(IssueKind k) noexcept;

/// Reports every defect of the mesh: face arrays, coordinates, channels,
/// topology (non-manifold elements, orientation, isolated vertices) and tags.
/// Never throws for a malformed mesh: an out-of-range index is reported and
/// the topological checks are skipped. Polyline indices are not checked.
/// \param mesh the mesh to check.
/// \param lines where the mesh's elements came from, to fill
///        ValidationIssue::line; may be null.
/// \param options how much to itemise.
/// \return the report.
/// \throws std::bad_alloc if memory runs out.
ValidationReport validate(const PolygonMesh& mesh, const SourceLines* lines = nullptr,
                          const ValidationOptions& options = {});
/// Same, reusing an already built topology.
/// \pre \p topology was built from \p mesh (not checked; it implies
///      well-formed face arrays).
/// \param mesh the mesh to check.
/// \param topology the mesh's topology.
/// \param lines where the mesh's elements came from; may be null.
/// \param options how much to itemise.
/// \return the report.
/// \throws std::bad_alloc if memory runs out.
ValidationReport validate(const PolygonMesh& mesh, const MeshTopology& topology,
                          const SourceLines* lines = nullptr, const ValidationOptions& options = {});

/// An issue with its location: "path:line: message", "path: message",
/// "line N: message" or the bare message, by what is known.
/// \param issue the issue.
/// \param path the file to name; may be empty.
/// \return the formatted issue, on one line.
/// \throws std::bad_alloc if memory runs out.
std::string format_issue(const ValidationIssue& issue, const std::string& path = {});

/// Thrown by require_valid(); carries the whole report.
class ValidationError : public TopologyError {
 public:
  /// An error whose message (what()) is report.first_error(path).
  /// \param report the report; taken over.
  /// \param path the file to name in the message; may be empty.
  /// \throws std::bad_alloc if memory runs out.
  ValidationError(ValidationReport report, const std::string& path);
  /// \return the report the error was made from.
  const ValidationReport& report() const noexcept { return report_; }

 private:
  ValidationReport report_;
};

/// Throws if the report has errors; warnings alone pass.
/// \param report the report to check.
/// \param path the file to name in the exception's message; may be empty.
/// \throws ValidationError naming the first error if !report.ok().
/// \throws std::bad_alloc if memory runs out.
void require_valid(const ValidationReport& report, const std::string& path = {});

}  // namespace subdiv
