#pragma once
/// \file
/// subdiv's analysis module: subdivision matrices, eigen-analysis, smoothness verdicts and limit positions.

#include "subdiv/analysis/analyze.h"
#include "subdiv/analysis/characteristic_map.h"
#include "subdiv/analysis/curve_analysis.h"
#include "subdiv/analysis/generalized_catmull_clark.h"
#include "subdiv/analysis/limit.h"
#include "subdiv/analysis/quasi_4_8_experiment.h"
#include "subdiv/analysis/regular_smoothness.h"
#include "subdiv/analysis/spectrum.h"
#include "subdiv/analysis/verdict.h"
