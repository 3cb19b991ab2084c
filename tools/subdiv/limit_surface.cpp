#include "limit_surface.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "output_checks.h"
#include "subdiv/core/error.h"
#include "subdiv/io/file_io.h"
#include "subdiv/io/mesh_io.h"

namespace subdiv::cli {

void add_evaluation_options(CLI::App& command, EvaluationChoice& choice) {
  command
      .add_option("--accuracy", choice.accuracy,
                  "Where exact evaluation does not apply: refine until the limit moves less than this from the "
                  "previous level's interpolant (default: 1e-4 of the bounding-box diagonal)")
      ->check(CLI::PositiveNumber);
  command.add_flag("--exact", choice.exact, "Refuse where exact evaluation does not apply, instead of approximating");
}

namespace {

double bounding_box_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0.0;
  Vec3 low = points.front(), high = points.front();
  for (const Vec3& p : points) {
    for (int a = 0; a < 3; ++a) {
      low[a] = std::min(low[a], p[a]);
      high[a] = std::max(high[a], p[a]);
    }
  }
  return norm(high - low);
}

}  // namespace

LimitSurface limit_surface_of(const std::string& input, const ReadOptions& read, const RefinementOptionValues& values,
                              const EvaluationChoice& choice) {
  const Scheme scheme = chosen_scheme(values);
  MeshFile file = read_mesh(input, read);
  print_warnings(input, file.warnings);
  RefineOptions options;
  apply_refinement_options(values, scheme, file, options);
  check_refinable(file.mesh, scheme, options, &file.lines);
  try {
    const auto reason = LimitEvaluator::exact_evaluation_unavailable(file.mesh, scheme, options);
    if (!reason || choice.exact) {
      LimitEvaluator evaluator(file.mesh, scheme, options);
      return {std::move(file.mesh), std::move(evaluator)};
    }
    double accuracy = choice.accuracy;
    if (accuracy == 0.0) accuracy = 1e-4 * bounding_box_diagonal(file.mesh.positions);
    if (!(accuracy > 0.0)) accuracy = 1e-12;  // a mesh of one point
    LimitEvaluator evaluator = LimitEvaluator::by_refinement(file.mesh, scheme, accuracy, options);
    warnf(
        "subdiv: warning: %s: approximate evaluation: %s; refined %d levels, the limit moved at most %.3g from "
        "the previous level's interpolant (accuracy %.3g)%s\n",
        input.c_str(), reason->c_str(), evaluator.isolation_levels(), evaluator.measured_change(), accuracy,
        evaluator.unresolved_vertices() > 0
            ? (", " + std::to_string(evaluator.unresolved_vertices()) + " vertices without a limit mask").c_str()
            : "");
    return {std::move(file.mesh), std::move(evaluator)};
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(input + ": " + e.what());
  }
}

std::vector<std::array<double, 3>> read_number_triples(const std::string& path, const std::string& layout) {
  const std::string text = read_file(path);
  std::vector<std::array<double, 3>> rows;
  std::size_t line_start = 0;
  for (int line = 1; line_start < text.size(); ++line) {
    std::size_t end = text.find('\n', line_start);
    if (end == std::string::npos) end = text.size();
    std::string_view rest(text.data() + line_start, end - line_start);
    line_start = end + 1;
    const auto skip_space = [&] {
      while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t' || rest.front() == '\r')) rest.remove_prefix(1);
    };
    skip_space();
    if (rest.empty() || rest.front() == '#') continue;
    std::array<double, 3> row{};
    for (double& value : row) {
      skip_space();
      const auto [next, error] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
      if (error != std::errc() || !std::isfinite(value))
        throw ParseError(path, line, "expected three finite numbers per line (" + layout + ")");
      rest.remove_prefix(static_cast<std::size_t>(next - rest.data()));
    }
    skip_space();
    if (!rest.empty()) throw ParseError(path, line, "expected three numbers per line (" + layout + "), found more");
    rows.push_back(row);
  }
  return rows;
}

std::string exact_number(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("nan");
}

}  // namespace subdiv::cli
