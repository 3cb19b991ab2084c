// subdiv: one program, one subcommand per task. Every failure ends in one
// line on stderr and a non-zero exit code: 1 for bad input or arguments,
// 2 for an internal error.

#include <cstdio>
#include <new>
#include <string>
#include <vector>
#include <algorithm>

#include <CLI/CLI.hpp>

#include "subdiv/version.h"

#include "cli_terms.h"
#include "commands.h"
#include "output_checks.h"
#include "wording.h"
#include "subdiv/core/error.h"

namespace {

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

void print_error(const std::string& message) { std::fprintf(stderr, "subdiv: %s\n", one_line(message).c_str()); }

}  // namespace

int main(int argc, char** argv) {
  using namespace subdiv::cli;
  CLI::App app{"subdiv: subdivision surfaces on polygon meshes", "subdiv"};
  app.set_version_flag("--version", std::string("subdiv ") + subdiv::version());
  app.require_subcommand(1);
  bool quiet_flag = false;
  app.add_flag("-q,--quiet", quiet_flag, "Print errors only: no warnings, no progress lines (any command)");
  app.fallthrough();  // -q after the command's own options too
  app.footer(
      "Examples:\n"
      "  subdiv info data/meshes/cube.obj\n"
      "  subdiv convert data/meshes/elephant.obj /tmp/elephant.ply\n"
      "  subdiv refine data/meshes/spot_control_mesh.obj -s catmull-clark -l 2 -o /tmp/spot.obj\n"
      "  subdiv schemes\n"
      "  subdiv analyze -s loop -k 3..8\n"
      "Run 'subdiv COMMAND --help' for a command's options.");

  const Command info = add_info_command(app);
  const Command convert = add_convert_command(app);
  const Command refine = add_refine_command(app);
  const Command schemes = add_schemes_command(app);
  const Command limit = add_limit_command(app);
  const Command analyze = add_analyze_command(app);
  const Command depth = add_depth_command(app);
  const Command adaptive = add_adaptive_command(app);
  const Command render = add_render_command(app);
  const Command compare = add_compare_command(app);
  const Command eval = add_eval_command(app);
  const Command tessellate = add_tessellate_command(app);
  const Command project = add_project_command(app);

  // A first word that names no command: say which one was meant.
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
    const std::string typed = argv[1];
    if (std::find(names.begin(), names.end(), typed) == names.end()) {
      const std::string guess = closest_name(typed, names);
      print_error("unknown command '" + typed + "'" + (guess.empty() ? "" : "; did you mean '" + guess + "'?") +
                  " (run 'subdiv --help' for the commands)");
      return kExitBadInput;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_error(std::string(e.what()) + " (run 'subdiv --help' for usage)");
    return kExitBadInput;
  }

  set_quiet(quiet_flag);
  // Warnings are kept while the command runs and printed after it succeeds;
  // a failure prints its one line only.
  const auto finish = [](int code) {
    finish_warnings(code == kExitOk);
    return code;
  };
  try {
    if (app.got_subcommand("info")) return finish(info());
    if (app.got_subcommand("convert")) return finish(convert());
    if (app.got_subcommand("refine")) return finish(refine());
    if (app.got_subcommand("schemes")) return finish(schemes());
    if (app.got_subcommand("limit")) return finish(limit());
    if (app.got_subcommand("analyze")) return finish(analyze());
    if (app.got_subcommand("depth")) return finish(depth());
    if (app.got_subcommand("adaptive")) return finish(adaptive());
    if (app.got_subcommand("render")) return finish(render());
    if (app.got_subcommand("compare")) return finish(compare());
    if (app.got_subcommand("eval")) return finish(eval());
    if (app.got_subcommand("tessellate")) return finish(tessellate());
    if (app.got_subcommand("project")) return finish(project());
    print_error("no command given (run 'subdiv --help' for usage)");
    return kExitBadInput;
  } catch (const subdiv::Error& e) {
    print_error(subdiv::cli::in_cli_terms(e.what()));
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    print_error("internal error: out of memory");
    return kExitInternal;
  } catch (const std::exception& e) {
    print_error(std::string("internal error: ") + e.what());
    return kExitInternal;
  }
}
