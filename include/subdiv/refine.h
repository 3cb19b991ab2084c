#pragma once
/// \file
/// subdiv's refine module: uniform refinement, the level hierarchy, its
/// stencil tables, and the local subdivision matrix of a configuration (the
/// stencils restricted to its neighbourhood).

#include "subdiv/refine/configuration.h"
#include "subdiv/refine/creasing.h"
#include "subdiv/refine/hierarchical_edits.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/refine.h"
#include "subdiv/refine/ring_mesh.h"
#include "subdiv/refine/subdivision_matrix.h"
