// subdiv eval IN -s SCHEME --at POINTS.txt [--derivatives] [-o OUT.txt]: the
// limit surface at each "face u v" line (ptex faces), as
// "x y z nx ny nz" lines (then du and dv with --derivatives).

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "command_report.h"
#include "limit_surface.h"
#include "output_checks.h"
#include "subdiv/core/error.h"
#include "subdiv/io/file_io.h"

namespace subdiv::cli {

namespace {

struct EvalCommandOptions {
  ReadOptions read;
  std::string input;
  std::string at;
  std::string output;
  bool derivatives = false;
  RefinementOptionValues refinement;
  EvaluationChoice evaluation;
  ReportOptionValues report;
};

void append(std::string& out, const Vec3& v) {
  for (int a = 0; a < 3; ++a) {
    out += exact_number(v[a]);
    out += ' ';
  }
}

int run_eval(const EvalCommandOptions& opt) {
  if (!opt.output.empty()) {
    check_not_an_input(opt.input, opt.output);
    check_not_an_input(opt.at, opt.output);
  }
  PhaseClock clock;
  const LimitSurface surface = limit_surface_of(opt.input, opt.read, opt.refinement, opt.evaluation);
  const LimitEvaluator& evaluator = surface.evaluator;
  clock.lap("prepare");
  const auto rows = read_number_triples(opt.at, "face u v");
  std::vector<SurfaceLocation> at;
  at.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double face = rows[i][0];
    if (face != std::floor(face) || face < 0 || face >= static_cast<double>(evaluator.ptex_face_count()))
      throw InvalidInputError(opt.at + ": point " + std::to_string(i + 1) + ": face " + exact_number(face) +
                              " is not a ptex face of " + opt.input + " (0 to " +
                              std::to_string(evaluator.ptex_face_count() - 1) + ")");
    at.push_back({static_cast<Index>(face), rows[i][1], rows[i][2]});
  }
  std::vector<LimitPoint> points;
  try {
    points = evaluator.evaluate(at);
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(opt.at + ": " + e.what());
  }
  clock.lap("evaluate");
  std::string text;
  text.reserve(points.size() * (opt.derivatives ? 240 : 120));
  for (const LimitPoint& p : points) {
    append(text, p.position);
    append(text, p.normal);
    if (opt.derivatives) {
      append(text, p.du);
      append(text, p.dv);
    }
    text.back() = '\n';
  }
  if (opt.output.empty()) std::fwrite(text.data(), 1, text.size(), stdout);
  else write_file_atomically(opt.output, text);
  clock.lap("write");
  if (opt.report.json) {
    print_json({{"command", "eval"},
                {"input", opt.input},
                {"output", opt.output},
                {"points", points.size()},
                {"ptex_faces", evaluator.ptex_face_count()},
                {"patches", evaluator.patch_count()},
                {"isolation_levels", evaluator.isolation_levels()},
                {"exact", evaluator.exact()},
                {"measured_change", evaluator.measured_change()},
                {"seconds", clock.json()}});
    return kExitOk;
  }
  if (opt.report.stats) std::fprintf(stderr, "%s\n", clock.text().c_str());
  if (!opt.output.empty())
    std::printf("wrote %s: %zu limit points of %s (%lld ptex faces, %zu patches)\n", opt.output.c_str(),
                points.size(), opt.input.c_str(), static_cast<long long>(evaluator.ptex_face_count()),
                evaluator.patch_count());
  return kExitOk;
}

}  // namespace

Command add_eval_command(CLI::App& app) {
  auto opt = std::make_shared<EvalCommandOptions>();
  CLI::App* cmd = app.add_subcommand("eval", "Evaluate the limit surface at given parameters");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  cmd->add_option("--at", opt->at, "Text file of 'face u v' lines (ptex faces; '#' starts a comment line)")
      ->required();
  cmd->add_option("-o,--output", opt->output, "Where to write the results (default: standard output)");
  cmd->add_flag("--derivatives", opt->derivatives, "Also write du and dv on each line");
  add_refinement_options(*cmd, opt->refinement,
                         "Scheme: catmull-clark, loop or loop-warren (exact); other quad and triangle schemes by refinement");
  add_evaluation_options(*cmd, opt->evaluation);
  add_report_options(*cmd, opt->report, "Print the time of each phase (on standard error)");
  cmd->footer(
      "Each output line is 'x y z nx ny nz' (then 'dux duy duz dvx dvy dvz' with --derivatives).\n"
      "Faces are ptex faces: a quad (Catmull-Clark) or triangle (Loop) is one, u, v in [0, 1]\n"
      "(triangles: u + v <= 1); a Catmull-Clark n-gon is n, one per corner (docs/evaluation.md).\n"
      "Exact for catmull-clark, loop and loop-warren (docs/evaluation.md lists the configurations); elsewhere\n"
      "the surface is approximated by refinement to --accuracy, with a warning (--exact refuses instead).\n"
      "Example:\n"
      "  printf '0 0.5 0.5\\n3 0.25 0.75\\n' > /tmp/at.txt\n"
      "  subdiv eval data/meshes/cube.obj -s catmull-clark --at /tmp/at.txt --derivatives");
  return [opt] { return run_eval(*opt); };
}

}  // namespace subdiv::cli
