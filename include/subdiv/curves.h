#pragma once
/// \file
/// subdiv's curves module: curve schemes and the refinement of polylines.

#include "subdiv/curves/curve_scheme.h"
