#pragma once
/// \file
/// subdiv's mesh module: polygon meshes, their tags, topology, validation and statistics.

#include "subdiv/mesh/mesh_stats.h"
#include "subdiv/mesh/polygon_mesh.h"
#include "subdiv/mesh/primvar.h"
#include "subdiv/mesh/source_lines.h"
#include "subdiv/mesh/tags.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/mesh/validation.h"
