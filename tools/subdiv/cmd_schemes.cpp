// subdiv schemes [--matrix]: the registered schemes with their rules and
// sources, or which command covers which scheme. The matrix asks the
// library's own checks (limit_unavailable, depth_bound_unavailable,
// adaptive_unavailable), the same that refuse a scheme when it is run.

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "commands.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/curves/curve_scheme.h"
#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/depth.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::cli {

namespace {

int name_width() {
  int width = 0;  // the longest name, so that the columns line up
  for (const Scheme* s : all_schemes()) width = std::max(width, static_cast<int>(s->name.size()));
  for (const CurveScheme* s : all_curve_schemes()) width = std::max(width, static_cast<int>(s->name.size()));
  return width;
}

int list_schemes() {
  const int width = name_width();
  for (const Scheme* s : all_schemes()) {
    std::printf("%-*s %s\n", width, std::string(s->name).c_str(), std::string(s->summary).c_str());
    std::printf("%-*s   %s; %s\n", width, "", to_string(s->split), std::string(s->citation).c_str());
  }
  // Curve schemes refine polylines (OBJ `l` lines), not faces.
  for (const CurveScheme* s : all_curve_schemes()) {
    std::printf("%-*s %s\n", width, std::string(s->name).c_str(), std::string(s->summary).c_str());
    std::printf("%-*s   curve scheme (polylines, %s); %s\n", width, "", s->dual ? "dual" : "primal",
                std::string(s->citation).c_str());
  }
  return kExitOk;
}

// One row of the matrix: the name, then the cells, padded but the last.
void print_row(int width, const std::string& name, std::span<const std::string> cells) {
  std::printf("%-*s", width, name.c_str());
  for (std::size_t i = 0; i < cells.size(); ++i)
    std::printf(i + 1 < cells.size() ? "  %-9s" : "  %s", cells[i].c_str());
  std::printf("\n");
}

// Which command covers which scheme: "yes", or "no (n)" with reason n listed
// below the table.
int print_matrix() {
  const int width = name_width();
  const std::string commands[] = {"refine", "limit", "depth", "adaptive", "analyze", "stencils"};
  std::vector<std::string> reasons;
  auto cell = [&](const std::optional<std::string>& reason) -> std::string {
    if (!reason) return "yes";
    auto it = std::find(reasons.begin(), reasons.end(), *reason);
    if (it == reasons.end()) it = reasons.insert(reasons.end(), *reason);
    return "no (" + std::to_string(it - reasons.begin() + 1) + ")";
  };
  print_row(width, "scheme", commands);
  for (const Scheme* s : all_schemes()) {
    const std::string row[] = {"yes", cell(limit_unavailable(*s)), cell(depth_bound_unavailable(*s)),
                               cell(adaptive_unavailable(*s)), "yes", "yes"};
    print_row(width, std::string(s->name), row);
  }
  const std::string curve = cell("a curve scheme: it refines and analyses polylines (OBJ 'l' lines), not surfaces");
  for (const CurveScheme* s : all_curve_schemes()) {
    const std::string row[] = {"yes", curve, curve, curve, "yes", "yes"};
    print_row(width, std::string(s->name), row);
  }
  std::printf("\n");
  for (std::size_t i = 0; i < reasons.size(); ++i) std::printf("(%zu) %s\n", i + 1, reasons[i].c_str());
  std::printf("stencils: the library's refine_stencils() and refine_stencil_table(); quasi-4-8's tables hold for "
              "the positions they were made from (its split reads them).\n");
  return kExitOk;
}

}  // namespace

Command add_schemes_command(CLI::App& app) {
  auto matrix = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("schemes", "List the subdivision schemes with their rules and sources");
  cmd->add_flag("--matrix", *matrix, "Which command covers which scheme, and why not where it does not");
  cmd->footer("Examples:\n  subdiv schemes\n  subdiv schemes --matrix");
  return [matrix] { return *matrix ? print_matrix() : list_schemes(); };
}

}  // namespace subdiv::cli
