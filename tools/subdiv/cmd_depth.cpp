// subdiv depth IN -s SCHEME --eps E [--verify]: how many uniform steps bring
// the control mesh within E of the limit surface, what each level up to that
// depth costs, the accuracy/depth trade-off, and (--verify) a refinement that
// measures how tight the bound is.

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "commands.h"
#include "input_mesh.h"
#include "output_checks.h"
#include "scheme_option.h"
#include "subdiv/core/error.h"
#include "subdiv/depth/depth.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/refine/refine.h"

namespace subdiv::cli {

namespace {

// The largest level --verify refines: 2^28 faces (about 4 GiB of face
// arrays for quads); Index is 32-bit, so also at most 2^31 - 1 corners.
constexpr std::int64_t kMaxVerifyFaces = std::int64_t{1} << 28;

struct DepthCommandOptions {
  std::string input;
  std::string scheme = std::string(default_scheme().name);
  double eps = 0.0;
  bool verify = false;
  bool triangulate = false;
  bool allow_non_manifold = false;
};

void print_bound(const DepthBound& bound, double eps) {
  std::printf("bound (%s): distance to the limit after k >= %d %s <= max of\n", bound.source.c_str(), bound.start,
              bound.steps_per_level > 1 ? "levels" : "steps");
  for (const DepthTerm& term : bound.terms) {
    DepthBound alone = bound;
    alone.terms = {term};
    std::printf("  %.6g x %.6g^(k - %d)   (alone: depth %d)   %s\n", term.amplitude, term.rate, bound.start,
                alone.depth_for(eps), term.what.c_str());
  }
}

void print_costs(const std::vector<LevelCost>& costs) {
  std::printf("\n%6s %14s %14s %16s\n", "level", "vertices", "faces", "bytes");
  for (const LevelCost& c : costs)
    std::printf("%6d %14lld %14lld %16lld\n", c.level, static_cast<long long>(c.vertices),
                static_cast<long long>(c.faces), static_cast<long long>(c.bytes));
}

void print_trade_off(const DepthBound& bound, double eps) {
  std::printf("\n%12s %6s\n", "accuracy", "depth");
  for (const double divisor : {1.0, 2.0, 10.0, 100.0, 1000.0})
    std::printf("%12.6g %6d\n", eps / divisor, bound.depth_for(eps / divisor));
}

int run_depth(const DepthCommandOptions& opt) {
  const Scheme& scheme = scheme_named(opt.scheme);
  MeshFile file = read_mesh(opt.input);
  print_warnings(opt.input, file.warnings);
  triangulate_if_asked(scheme, opt.triangulate, file);

  DepthOptions options;
  options.refine.allow_non_manifold = opt.allow_non_manifold;
  check_refinable(file.mesh, scheme, options.refine, &file.lines);  // errors with the file's lines
  const DepthBound bound = depth_bound(file.mesh, scheme, options, &file.lines);
  const int depth = bound.depth_for(opt.eps);

  std::printf("%s: %d vertices, %d faces, scheme %s\n", opt.input.c_str(), file.mesh.vertex_count(),
              file.mesh.face_count(), std::string(scheme.name).c_str());
  print_bound(bound, opt.eps);
  const int steps = bound.steps_per_level;
  std::printf("\ndepth for accuracy %g: %d (bound there: %.6g)\n", opt.eps, depth, bound.at(depth));
  if (steps > 1)
    std::printf("levels count %d %s steps each (its two-step quad split): refine -l %d\n", steps,
                std::string(scheme.name).c_str(), steps * depth);
  print_costs(level_costs(file.mesh, scheme, depth));
  print_trade_off(bound, opt.eps);

  if (opt.verify) {
    const LevelCost size = level_costs(file.mesh, scheme, depth).back();
    if (size.faces > kMaxVerifyFaces || size.corners > std::numeric_limits<std::int32_t>::max() ||
        size.vertices > std::numeric_limits<std::int32_t>::max())
      throw InvalidInputError("--verify: depth " + std::to_string(depth) + " has " + std::to_string(size.faces) +
                              " faces and " + std::to_string(size.vertices) + " vertices (" +
                              std::to_string(size.bytes) + " bytes), over the verification budget of 2^28 faces; "
                              "verify a larger --eps");
    const DepthCheck check = check_depth(file.mesh, scheme, bound, depth, options);
    std::printf("\nverify: after %d steps the largest vertex-to-limit distance is %.6g (bound %.6g, accuracy %g): %s\n",
                steps * depth, check.measured, check.bound, opt.eps, check.measured <= opt.eps ? "within" : "NOT within");
    if (check.has_previous)
      std::printf("verify: after %d steps it is %.6g: depth %d %s\n", steps * (depth - 1), check.measured_previous, depth - 1,
                  check.measured_previous <= opt.eps ? "would already have been enough (the bound is not tight)"
                                                     : "would not have been enough (the bound is tight)");
    if (check.approximated > 0)
      warnf("subdiv: warning: %d vertices match no canonical configuration: their limit is approximated\n",
                   check.approximated);
    if (check.measured > opt.eps) return kExitInternal;
  }
  return kExitOk;
}

}  // namespace

Command add_depth_command(CLI::App& app) {
  auto opt = std::make_shared<DepthCommandOptions>();
  CLI::App* cmd = app.add_subcommand("depth", "Uniform steps needed to come within an accuracy of the limit surface");
  cmd->add_option("input", opt->input, "Mesh (.obj, .ply or .off)")->required();
  cmd->add_option("-s,--scheme", opt->scheme, "Scheme: loop, catmull-clark, doo-sabin or any in 'subdiv schemes'")
      ->capture_default_str();
  cmd->add_option("--eps", opt->eps, "Accuracy: largest allowed distance of a control vertex to the limit surface")
      ->required()
      ->check(positive_number());
  cmd->add_flag("--verify", opt->verify, "Refine to the depth and measure the distances (exit 2 if one exceeds eps)");
  cmd->add_flag("--triangulate", opt->triangulate, "Triangulate polygons first (for triangle schemes such as loop)");
  cmd->add_flag("--allow-non-manifold", opt->allow_non_manifold, "Treat non-manifold elements as sharp");
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
