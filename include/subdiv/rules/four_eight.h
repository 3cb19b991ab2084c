#pragma once
// 4-8 subdivision on quads (sqrt2 split, QP arity sqrt 2, closed polygon
// meshes); every weight is in four_eight.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& four_eight_scheme();

}  // namespace subdiv
