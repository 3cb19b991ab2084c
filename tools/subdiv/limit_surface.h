#pragma once
// What eval, tessellate and project share: the mesh read and its limit
// evaluator built (errors name the input file), and files of number lines.

#include <CLI/CLI.hpp>
#include <array>
#include <string>
#include <vector>

#include "read_options.h"
#include "refinement_options.h"
#include "subdiv/eval/limit_evaluator.h"

namespace subdiv::cli {

/// How the evaluator is chosen: exact where it applies, else by refinement
/// to an accuracy (or refused, with --exact).
struct EvaluationChoice {
  double accuracy = 0.0;  ///< approximate evaluation's accuracy; 0: 1e-4 of the bounding-box diagonal
  bool exact = false;     ///< refuse rather than approximate
};

/// Adds --accuracy and --exact to a command.
void add_evaluation_options(CLI::App& command, EvaluationChoice& choice);

/// A control mesh as the options leave it, and its limit surface's evaluator.
struct LimitSurface {
  PolygonMesh mesh;
  LimitEvaluator evaluator;
};

/// Reads `input`, applies the refinement options (--triangulate, --crease)
/// and prepares the evaluator of its limit surface under the -s scheme: the
/// exact one where it applies, else (unless `choice.exact`) evaluation by
/// refinement, with a warning that says why and what was measured; an error
/// names the file.
LimitSurface limit_surface_of(const std::string& input, const ReadOptions& read, const RefinementOptionValues& values,
                              const EvaluationChoice& choice);

/// The lines of a text file of three numbers each (blank lines and lines
/// starting with '#' skipped). Throws InvalidInputError naming the file and
/// line of the first malformed one; `layout` names the columns ("face u v").
std::vector<std::array<double, 3>> read_number_triples(const std::string& path, const std::string& layout);

/// A number written so that reading it back gives the same double.
std::string exact_number(double value);

}  // namespace subdiv::cli
