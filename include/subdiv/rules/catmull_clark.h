#pragma once
// Catmull-Clark subdivision (Catmull and Clark 1978), quad split, any polygon
// mesh; every weight of the scheme is in catmull_clark.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& catmull_clark_scheme();

}  // namespace subdiv
