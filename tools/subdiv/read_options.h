#pragma once
// How every command reads its input mesh: the welding of STL and glTF
// vertices (--weld-tolerance), one definition for all of them.

#include <CLI/CLI.hpp>

#include "subdiv/io/mesh_io.h"

namespace subdiv::cli {

/// Adds --weld-tolerance, stored in `options.weld_tolerance`.
void add_read_options(CLI::App* cmd, ReadOptions& options);

}  // namespace subdiv::cli
