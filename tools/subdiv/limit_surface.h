#pragma once
// What eval, tessellate and project share: the mesh read and its limit
// evaluator built (errors name the input file), and files of number lines.

#include <array>
#include <string>
#include <vector>

#include "read_options.h"
#include "refinement_options.h"
#include "subdiv/eval/limit_evaluator.h"

namespace subdiv::cli {

/// A control mesh as the options leave it, and its limit surface's evaluator.
struct LimitSurface {
  PolygonMesh mesh;
  LimitEvaluator evaluator;
};

/// Reads `input`, applies the refinement options (--triangulate, --crease)
/// and prepares the exact evaluator of its limit surface under the -s
/// scheme; an error names the file.
LimitSurface limit_surface_of(const std::string& input, const ReadOptions& read, const RefinementOptionValues& values);

/// The lines of a text file of three numbers each (blank lines and lines
/// starting with '#' skipped). Throws InvalidInputError naming the file and
/// line of the first malformed one; `layout` names the columns ("face u v").
std::vector<std::array<double, 3>> read_number_triples(const std::string& path, const std::string& layout);

/// A number written so that reading it back gives the same double.
std::string exact_number(double value);

}  // namespace subdiv::cli
