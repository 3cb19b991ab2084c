#pragma once
/// \file
/// subdiv's core module: errors, basic types and stencil tables.

#include "subdiv/core/error.h"
#include "subdiv/core/stencil_table.h"
#include "subdiv/core/types.h"
