// subdiv info MESH: what the mesh is made of, its tags, and what is wrong
// with it. Exit 0 when the mesh is valid (warnings allowed), 1 otherwise.

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

#include <fmt/format.h>

#include "command_report.h"
#include "commands.h"
#include "read_options.h"
#include "report.h"
#include "wording.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"

namespace subdiv::cli {

namespace {

struct InfoOptions {
  ReadOptions read;  ///< --weld-tolerance
  std::string path;
  std::size_t max_issues = 20;
  bool json = false;
};

nlohmann::ordered_json histogram_json(const std::map<Index, Index>& counts) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [size, count] : counts) out[std::to_string(size)] = count;
  return out;
}

nlohmann::ordered_json info_json(const std::string& path, const MeshFile& file, const MeshStats& stats,
                                 const ValidationReport& report) {
  const PolygonMesh& mesh = file.mesh;
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const VertexChannel& c : mesh.vertex_channels)
    channels.push_back({{"name", c.name}, {"kind", "vertex"}, {"components", c.components}});
  for (const FaceVaryingChannel& c : mesh.face_varying_channels)
    channels.push_back({{"name", c.name}, {"kind", "face-varying"}, {"components", c.components}});
  nlohmann::ordered_json issues = nlohmann::ordered_json::array();
  for (const ValidationIssue& issue : report.issues)
    issues.push_back({{"kind", to_string(issue.kind)},
                      {"severity", issue.severity == Severity::error ? "error" : "warning"},
                      {"element", issue.element},
                      {"line", issue.line == 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(issue.line)},
                      {"message", issue.message}});
  return {{"command", "info"},
          {"input", path},
          {"format", to_string(format_from_path(path))},
          {"vertices", stats.vertices},
          {"faces", stats.faces},
          {"edges", stats.edges},
          {"corners", stats.corners},
          {"face_sizes", histogram_json(stats.face_sizes)},
          {"valences", histogram_json(stats.valences)},
          {"max_valence", stats.max_valence},
          {"boundary_edges", stats.boundary_edges},
          {"boundary_loops", stats.boundary_loops},
          {"components", stats.components},
          {"euler_characteristic", stats.euler_characteristic},
          {"bbox", {{"min", {stats.bbox_min.x, stats.bbox_min.y, stats.bbox_min.z}},
                    {"max", {stats.bbox_max.x, stats.bbox_max.y, stats.bbox_max.z}}}},
          {"channels", channels},
          {"polylines", mesh.polylines.size()},
          {"tags", {{"creases", mesh.tags.creases.size()}, {"corners", mesh.tags.corners.size()},
                    {"holes", mesh.tags.holes.size()}, {"other", mesh.tags.other.size()}}},
          {"read_notes", file.warnings},
          {"valid", report.ok()},
          {"errors", report.error_count()},
          {"warnings", report.warning_count()},
          {"issues", issues}};
}

std::string info_text(const std::string& path, const MeshFile& file, const MeshStats& stats,
                      const ValidationReport& report, std::size_t max_issues) {
  std::string text = fmt::format("file            {} ({})\n", path, to_string(format_from_path(path)));
  text += format_stats(stats);
  text += format_channels(file.mesh);
  if (!file.mesh.polylines.empty()) {  // OBJ l lines: curves beside the faces
    std::size_t closed = 0, points = 0;
    for (const MeshPolyline& l : file.mesh.polylines) {
      closed += l.closed ? 1 : 0;
      points += l.vertices.size();
    }
    text += fmt::format("polylines       {}  (closed {}, points {})\n", file.mesh.polylines.size(), closed, points);
  }
  text += format_tags(file.mesh.tags);
  for (const auto& w : file.warnings) text += fmt::format("read note       {}\n", w);
  text += format_validation(report, path, max_issues);
  return text;
}

int run_info(const InfoOptions& opt) {
  const MeshFile file = read_mesh(opt.path, opt.read);
  ValidationOptions vopt;
  vopt.max_issues_per_kind = std::max<std::size_t>(opt.max_issues, 1);
  // Readers guarantee in-range indices, which is all the topology needs; any
  // other defect is represented and reported by validate().
  const MeshTopology topo(file.mesh);
  const ValidationReport report = validate(file.mesh, topo, &file.lines, vopt);
  const MeshStats stats = compute_stats(file.mesh, topo);
  if (opt.json) {
    print_json(info_json(opt.path, file, stats, report));
  } else {
    const std::string text = info_text(opt.path, file, stats, report, opt.max_issues);
    std::fwrite(text.data(), 1, text.size(), stdout);
  }
  std::fflush(stdout);
  if (!report.ok()) {
    std::fprintf(stderr, "subdiv: %s: invalid mesh (%s): %s\n", opt.path.c_str(),
                 count_of(static_cast<std::int64_t>(report.error_count()), "error", "errors").c_str(),
                 report.first_error(opt.path).c_str());
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

Command add_info_command(CLI::App& app) {
  auto opt = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Print counts, histograms, tags and a validation report for a mesh");
  add_read_options(cmd, opt->read);
  cmd->add_option("mesh", opt->path, "Mesh file (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("--max-issues", opt->max_issues, "Validation issues listed (and kept per kind)")
      ->capture_default_str()
      ->check(positive_number());
  cmd->add_flag("--json", opt->json, "Print one JSON document instead of the text (schema in docs/cli.md)");
  cmd->footer(
      "Exit code 0 when the mesh is valid for subdivision (warnings such as isolated\n"
      "vertices allowed), 1 when it is not or cannot be read.\n"
      "Example:\n"
      "  subdiv info data/meshes/cube.obj");
  return [opt] { return run_info(*opt); };
}

}  // namespace subdiv::cli
