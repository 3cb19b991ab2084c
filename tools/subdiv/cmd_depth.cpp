// subdiv depth IN -s SCHEME --eps E [--verify]: how many uniform steps bring
// the control mesh within E of the limit surface, what each level up to that
// depth costs, the accuracy/depth trade-off, and (--verify) a refinement that
// measures how tight the bound is.

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <vector>
#include <string>

#include "commands.h"
#include "read_options.h"
#include "input_mesh.h"
#include "output_checks.h"
#include "command_report.h"
#include "memory_guard.h"
#include "refinement_options.h"
#include "wording.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/depth.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

// --verify's peak memory, in multiples of the measured level's mesh arrays
// (level_costs() bytes): the hierarchy's last two levels, the limit
// positions or the linear surface's own refinement, and topologies. Measured
// (peak RSS over those bytes): 5.7 for Catmull-Clark's vertex-to-limit
// distances, 3.1 for the Butterfly's linear surface, 5.1 for
// interpolatory-sqrt3's (two steps, nested).
constexpr std::int64_t kVerifyPeakFactor = 6;

// The largest level --verify refines: 2^28 faces (about 4 GiB of face
// arrays for quads); Index is 32-bit, so also at most 2^31 - 1 corners.
constexpr std::int64_t kMaxVerifyFaces = std::int64_t{1} << 28;

struct DepthCommandOptions {
  ReadOptions read;  ///< --weld-tolerance
  std::string input;
  double eps = 0.0;
  bool verify = false;
  bool no_memory_check = false;
  RefinementOptionValues refinement;
  ReportOptionValues report;
};

// What the bound measures, as the report says it.
const char* measured_distance(const DepthBound& bound) {
  return bound.measure == DepthMeasure::surface_to_limit
             ? "distance of the level's linear surface to the limit (the vertices are on it)"
             : "distance to the limit";
}

void print_bound(const DepthBound& bound, double eps) {
  std::printf("bound (%s): %s after k >= %d %s <= max of\n", bound.source.c_str(), measured_distance(bound),
              bound.start, bound.steps_per_level > 1 ? "levels" : "steps");
  for (const DepthTerm& term : bound.terms) {
    DepthBound alone = bound;
    alone.terms = {term};
    std::printf("  %.6g x %.6g^(k - %d)   (alone: depth %d)   %s\n", term.amplitude, term.rate, bound.start,
                alone.depth_for(eps), term.what.c_str());
  }
}

void print_costs(const std::vector<LevelCost>& costs) {
  std::printf("\n%6s %14s %14s %12s\n", "level", "vertices", "faces", "size");
  for (const LevelCost& c : costs)
    std::printf("%6d %14lld %14lld %12s\n", c.level, static_cast<long long>(c.vertices),
                static_cast<long long>(c.faces), format_bytes(static_cast<double>(c.bytes)).c_str());
}

void print_trade_off(const DepthBound& bound, double eps) {
  std::printf("\n%12s %6s\n", "accuracy", "depth");
  for (const double divisor : {1.0, 2.0, 10.0, 100.0, 1000.0})
    std::printf("%12.6g %6d\n", eps / divisor, bound.depth_for(eps / divisor));
}

nlohmann::ordered_json bound_json(const DepthBound& bound, double eps) {
  nlohmann::ordered_json terms = nlohmann::ordered_json::array();
  for (const DepthTerm& term : bound.terms) {
    DepthBound alone = bound;
    alone.terms = {term};
    terms.push_back({{"amplitude", term.amplitude}, {"rate", term.rate}, {"depth_alone", alone.depth_for(eps)},
                     {"what", term.what}});
  }
  return {{"source", bound.source}, {"measure", to_string(bound.measure)}, {"start", bound.start},
          {"steps_per_level", bound.steps_per_level}, {"terms", terms}};
}

nlohmann::ordered_json costs_json(const std::vector<LevelCost>& costs) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const LevelCost& c : costs)
    out.push_back({{"level", c.level}, {"vertices", c.vertices}, {"faces", c.faces}, {"bytes", c.bytes}});
  return out;
}

nlohmann::ordered_json trade_off_json(const DepthBound& bound, double eps) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const double divisor : {1.0, 2.0, 10.0, 100.0, 1000.0})
    out.push_back({{"accuracy", eps / divisor}, {"depth", bound.depth_for(eps / divisor)}});
  return out;
}

// The costs of the bound's levels, `steps_per_level` steps each (4-8's
// level_costs() already counts its two-step levels).
std::vector<LevelCost> bound_level_costs(const PolygonMesh& mesh, const Scheme& scheme, const DepthBound& bound,
                                         int levels) {
  const int steps = bound.steps_per_level;
  if (steps == 1 || scheme.fast_path.two_steps) return level_costs(mesh, scheme, levels);
  std::vector<LevelCost> costs;
  for (const LevelCost& c : level_costs(mesh, scheme, levels * steps))
    if (c.level % steps == 0) {
      costs.push_back(c);
      costs.back().level = c.level / steps;
    }
  return costs;
}

int run_depth(const DepthCommandOptions& opt) {
  const Scheme scheme = chosen_scheme(opt.refinement);
  const std::string name(scheme.name);
  PhaseClock clock;
  MeshFile file = read_mesh(opt.input, opt.read);
  print_warnings(opt.input, file.warnings);
  DepthOptions options;
  apply_refinement_options(opt.refinement, scheme, file, options.refine);
  clock.lap("read");
  check_refinable(file.mesh, scheme, options.refine, &file.lines);  // errors with the file's lines
  const DepthBound bound = depth_bound(file.mesh, scheme, options, &file.lines);
  const int depth = bound.depth_for(opt.eps);
  const int steps = bound.steps_per_level;
  const std::vector<LevelCost> costs = bound_level_costs(file.mesh, scheme, bound, depth);
  clock.lap("bound");

  if (!opt.report.json) {  // the bound before the verification, which can take long
    std::printf("%s: %s, %s, scheme %s\n", opt.input.c_str(),
                count_of(file.mesh.vertex_count(), "vertex", "vertices").c_str(),
                count_of(file.mesh.face_count(), "face", "faces").c_str(), name.c_str());
    print_bound(bound, opt.eps);
    std::printf("\ndepth for accuracy %g: %d (bound there: %.6g)\n", opt.eps, depth, bound.at(depth));
    if (steps > 1)
      std::printf("levels count %d %s steps each (%s): refine -l %d\n", steps, name.c_str(),
                  scheme.fast_path.two_steps ? "its two-step quad split" : "after two steps the split's faces nest",
                  steps * depth);
    print_costs(costs);
    print_trade_off(bound, opt.eps);
    std::fflush(stdout);
  }

  std::optional<DepthCheck> check;
  if (opt.verify) {
    // The linear surface is measured at the vertices one level further down.
    const bool one_more = bound.measure == DepthMeasure::surface_to_limit;
    const LevelCost size = one_more ? bound_level_costs(file.mesh, scheme, bound, depth + 1).back() : costs.back();
    if (size.faces > kMaxVerifyFaces || size.corners > std::numeric_limits<std::int32_t>::max() ||
        size.vertices > std::numeric_limits<std::int32_t>::max())
      throw InvalidInputError("--verify: level " + std::to_string(depth + (one_more ? 1 : 0)) + " has " +
                              count_of(size.faces, "face", "faces") +
                              " and " + count_of(size.vertices, "vertex", "vertices") + " (" +
                              format_bytes(static_cast<double>(size.bytes)) +
                              "), over the verification budget of 2^28 faces; verify a larger --eps");
    check_fits_in_memory(kVerifyPeakFactor * size.bytes, opt.no_memory_check,
                         "--verify at level " + std::to_string(depth + (one_more ? 1 : 0)) + " (" +
                             format_bytes(static_cast<double>(size.bytes)) + " of mesh arrays)");
    check = check_depth(file.mesh, scheme, bound, depth, options);
    clock.lap("verify");
    if (check->approximated > 0)
      warnf("subdiv: warning: %s no canonical configuration: %s approximated\n",
            count_of(check->approximated, "vertex matches", "vertices match").c_str(),
            check->approximated == 1 ? "its limit is" : "their limits are");
  }
  const bool within = !check || check->measured <= opt.eps;

  if (opt.report.json) {
    nlohmann::ordered_json verify = nullptr;
    if (check) {
      verify = {{"steps", steps * depth}, {"measured", check->measured}, {"bound", check->bound}, {"within", within},
                {"approximated", check->approximated}};
      if (check->has_previous) verify["measured_previous"] = check->measured_previous;
    }
    print_json({{"command", "depth"}, {"input", opt.input}, {"scheme", name},
                {"vertices", file.mesh.vertex_count()}, {"faces", file.mesh.face_count()}, {"eps", opt.eps},
                {"bound", bound_json(bound, opt.eps)}, {"depth", depth}, {"bound_at_depth", bound.at(depth)},
                {"refine_levels", steps * depth}, {"levels", costs_json(costs)},
                {"trade_off", trade_off_json(bound, opt.eps)}, {"verify", verify}, {"seconds", clock.json()}});
    return within ? kExitOk : kExitInternal;
  }

  if (check) {
    std::printf("\nverify: after %s the largest %s is %.6g (bound %.6g, accuracy %g): %s\n",
                count_of(steps * depth, "step", "steps").c_str(),
                bound.measure == DepthMeasure::surface_to_limit
                    ? "distance of the linear surface to the limit, at the next level's vertices,"
                    : "vertex-to-limit distance",
                check->measured, check->bound, opt.eps, within ? "within" : "NOT within");
    if (check->has_previous)
      std::printf("verify: after %s it is %.6g: depth %d %s\n", count_of(steps * (depth - 1), "step", "steps").c_str(),
                  check->measured_previous, depth - 1,
                  check->measured_previous <= opt.eps ? "would already have been enough (the bound is not tight)"
                                                      : "would not have been enough (the bound is tight)");
  }
  if (opt.report.stats) std::printf("\n%s\n", clock.text().c_str());
  return within ? kExitOk : kExitInternal;
}

}  // namespace

Command add_depth_command(CLI::App& app) {
  auto opt = std::make_shared<DepthCommandOptions>();
  CLI::App* cmd = app.add_subcommand("depth", "Uniform steps needed to come within an accuracy of the limit surface");
  add_read_options(cmd, opt->read);
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply, .off, .gltf, .glb or .stl)")->required();
  add_refinement_options(*cmd, opt->refinement, "Scheme (see 'subdiv schemes'; 'subdiv schemes --matrix' says which have a bound)");
  cmd->add_option("--eps", opt->eps, "Accuracy: largest allowed distance of a vertex to its limit (interpolating schemes: of the level's linear surface to the limit surface)")
      ->required()
      ->check(positive_number());
  cmd->add_flag("--verify", opt->verify, "Refine to the depth and measure the distances (exit 2 if one exceeds eps)");
  add_report_options(*cmd, opt->report, "Print the time of each phase");
  cmd->add_flag("--no-memory-check", opt->no_memory_check,
                "Verify even when the estimated peak memory exceeds what the machine has available");
  cmd->footer(
      "Loop, Catmull-Clark and Doo-Sabin use the bounds of 'A priori computation of the subdivision\n"
      "depth' (with a term for extraordinary vertices or faces from the analysis); other schemes a\n"
      "bound from their eigenvalues. Doo-Sabin measures a vertex against the limit of its V-face.\n"
      "Sizes are counted, not computed; --verify refuses levels over 2^28 faces.\n"
      "Example:\n"
      "  subdiv depth data/meshes/cube.obj -s catmull-clark --eps 0.01 --verify");
  return [opt] { return run_depth(*opt); };
}

}  // namespace subdiv::cli
