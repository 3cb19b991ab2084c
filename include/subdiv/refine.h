#pragma once
// subdiv's refine module: uniform refinement, the level hierarchy and stencil tables.

#include "subdiv/refine/creasing.h"
#include "subdiv/refine/hierarchy.h"
#include "subdiv/refine/refine.h"
#include "subdiv/refine/stencil_table.h"
