#pragma once
/// \file
/// subdiv's depth module: a-priori subdivision depth and adaptive refinement.

#include "subdiv/depth/adaptive.h"
#include "subdiv/depth/depth.h"
#include "subdiv/depth/depth_bound.h"
#include "subdiv/depth/mesh_measures.h"
