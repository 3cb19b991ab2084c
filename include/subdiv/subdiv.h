#pragma once
/// \file
/// Everything subdiv offers, one header per module.

#include "subdiv/version.h"
#include "subdiv/core.h"
#include "subdiv/mesh.h"
#include "subdiv/io.h"
#include "subdiv/topology.h"
#include "subdiv/rules.h"
#include "subdiv/curves.h"
#include "subdiv/refine.h"
#include "subdiv/analysis.h"
#include "subdiv/depth.h"
#include "subdiv/eval.h"
