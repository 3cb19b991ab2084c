// subdiv info MESH: what the mesh is made of, its tags, and what is wrong
// with it. Exit 0 when the mesh is valid (warnings allowed), 1 otherwise.

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "commands.h"
#include "report.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/topology.h"

namespace subdiv::cli {

namespace {

struct InfoOptions {
  std::string path;
  std::size_t max_issues = 20;
};

int run_info(const InfoOptions& opt) {
  const MeshFile file = read_mesh(opt.path);
  ValidationOptions vopt;
  vopt.max_issues_per_kind = std::max<std::size_t>(opt.max_issues, 1);
  std::string text = fmt::format("file            {} ({})\n", opt.path, to_string(format_from_path(opt.path)));

  // Readers guarantee in-range indices, which is all the topology needs; any
  // other defect is represented and reported by validate().
  const MeshTopology topo(file.mesh);
  const ValidationReport report = validate(file.mesh, topo, &file.lines, vopt);
  text += format_stats(compute_stats(file.mesh, topo));
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
  text += format_validation(report, opt.path, opt.max_issues);
  std::fwrite(text.data(), 1, text.size(), stdout);
  std::fflush(stdout);

  if (!report.ok()) {
    std::fprintf(stderr, "subdiv: %s: invalid mesh (%zu errors): %s\n", opt.path.c_str(), report.error_count(),
                 report.first_error(opt.path).c_str());
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

Command add_info_command(CLI::App& app) {
  auto opt = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "Print counts, histograms, tags and a validation report for a mesh");
  cmd->add_option("mesh", opt->path, "Mesh file (.obj, .ply or .off)")->required();
  cmd->add_option("--max-issues", opt->max_issues, "Validation issues listed (and kept per kind)")
      ->capture_default_str()
      ->check(positive_number());
  cmd->footer(
      "Exit code 0 when the mesh is valid for subdivision (warnings such as isolated\n"
      "vertices allowed), 1 when it is not or cannot be read.\n"
      "Example:\n"
      "  subdiv info data/meshes/cube.obj");
  return [opt] { return run_info(*opt); };
}

}  // namespace subdiv::cli
