#pragma once
/// \file
/// subdiv's topology module: the splits: how one level's faces and vertices make the next level's.

#include "subdiv/topology/bisection_split.h"
#include "subdiv/topology/split.h"
