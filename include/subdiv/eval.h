#pragma once
/// \file
/// subdiv's eval module: exact evaluation of the limit surface at any parameter.

#include "subdiv/eval/limit_evaluator.h"
#include "subdiv/eval/tessellate.h"
#include "subdiv/eval/closest_point.h"
