#pragma once
// subdiv's core module: errors and basic types.

#include "subdiv/core/error.h"
#include "subdiv/core/types.h"
