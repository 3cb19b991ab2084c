#include "read_options.h"

namespace subdiv::cli {

void add_read_options(CLI::App* cmd, ReadOptions& options) {
  cmd->add_option("--weld-tolerance", options.weld_tolerance,
                  "STL and glTF input (glTF not written by subdiv): corners whose positions differ by at most this "
                  "in every coordinate become one vertex; 0 merges equal positions only, -1 keeps every file "
                  "vertex apart")
      ->capture_default_str();
}

}  // namespace subdiv::cli
