// subdiv project IN -s SCHEME --points P.txt [-o OUT.txt]: the nearest point
// of the limit surface to each "x y z" line, as "face u v x y z
// distance" lines.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "command_report.h"
#include "limit_surface.h"
#include "output_checks.h"
#include "subdiv/eval/closest_point.h"
#include "subdiv/io/file_io.h"
#include "subdiv/io/mesh_io.h"

namespace subdiv::cli {

namespace {

struct ProjectCommandOptions {
  ReadOptions read;
  std::string input;
  std::string points;
  std::string output;
  int samples = 8;
  RefinementOptionValues refinement;
  EvaluationChoice evaluation;
  ReportOptionValues report;
};

int run_project(const ProjectCommandOptions& opt) {
  if (!opt.output.empty()) {
    check_not_an_input(opt.input, opt.output);
    check_not_an_input(opt.points, opt.output);
  }
  PhaseClock clock;
  const LimitSurface surface = limit_surface_of(opt.input, opt.read, opt.refinement, opt.evaluation);
  std::vector<Vec3> points;
  for (const auto& row : read_number_triples(opt.points, "x y z")) points.push_back({row[0], row[1], row[2]});
  clock.lap("prepare");
  const std::vector<ClosestPoint> nearest = closest_points(surface.mesh, surface.evaluator, points, opt.samples);
  clock.lap("project");
  std::string text;
  for (const ClosestPoint& c : nearest) {
    text += std::to_string(c.location.face);
    for (const double x : {c.location.u, c.location.v, c.position.x, c.position.y, c.position.z, c.distance}) {
      text += ' ';
      text += exact_number(x);
    }
    text += '\n';
  }
  if (opt.output.empty()) std::fwrite(text.data(), 1, text.size(), stdout);
  else write_file_atomically(opt.output, text);
  clock.lap("write");
  if (opt.report.json) {
    print_json({{"command", "project"},
                {"input", opt.input},
                {"output", opt.output},
                {"points", nearest.size()},
                {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) std::fprintf(stderr, "%s\n", clock.text().c_str());
  if (!opt.output.empty())
    std::printf("wrote %s: the nearest limit-surface points of %zu points\n", opt.output.c_str(), nearest.size());
  return kExitOk;
}

}  // namespace

Command add_project_command(CLI::App& app) {
  auto opt = std::make_shared<ProjectCommandOptions>();
  CLI::App* cmd = app.add_subcommand("project", "Find the nearest points of the limit surface");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("--points", opt->points, "Text file of 'x y z' lines ('#' starts a comment line)")->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the results (default: standard output)");
  cmd->add_option("--samples", opt->samples,
                  "Samples per face edge that seed the search (even; more find the nearest point on thinner "
                  "features)")
      ->capture_default_str()
      ->check(CLI::Range(2, 64));
  add_refinement_options(*cmd, opt->refinement,
                         "Scheme: catmull-clark, loop or loop-warren (exact); other quad and triangle schemes by refinement");
  add_evaluation_options(*cmd, opt->evaluation);
  add_report_options(*cmd, opt->report, "Print the time of each phase (on standard error)");
  cmd->footer(
      "Each output line is 'face u v x y z distance' (ptex face, see 'subdiv eval --help').\n"
      "Example:\n"
      "  printf '0.2 0.3 1.5\\n' > /tmp/p.txt\n"
      "  subdiv project data/meshes/cube.obj -s catmull-clark --points /tmp/p.txt");
  return [opt] { return run_project(*opt); };
}

}  // namespace subdiv::cli
