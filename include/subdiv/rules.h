#pragma once
/// \file
/// subdiv's rules module: the surface schemes: their declarations, masks and registry.

#include "subdiv/rules/bilinear.h"
#include "subdiv/rules/butterfly.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/composite.h"
#include "subdiv/rules/doo_sabin.h"
#include "subdiv/rules/four_eight.h"
#include "subdiv/rules/generalized_catmull_clark.h"
#include "subdiv/rules/interpolating_sqrt2.h"
#include "subdiv/rules/interpolatory_sqrt3.h"
#include "subdiv/rules/kobbelt.h"
#include "subdiv/rules/limit_mask.h"
#include "subdiv/rules/linear.h"
#include "subdiv/rules/loop.h"
#include "subdiv/rules/midedge.h"
#include "subdiv/rules/quasi_4_8.h"
#include "subdiv/rules/scheme.h"
#include "subdiv/rules/sqrt3.h"
