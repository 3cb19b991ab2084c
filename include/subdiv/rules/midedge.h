#pragma once
// Midedge subdivision (midedge split, QD arity sqrt 2, closed polygon
// meshes); every weight is in midedge.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& midedge_scheme();

}  // namespace subdiv
