#pragma once
// 4-8 subdivision on quads (sqrt2 split, QP arity sqrt 2, closed polygon
// meshes); every weight is in four_eight.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

const Scheme& four_eight_scheme();
/// Two four-eight steps as one quad-split level of a closed mesh, which the
/// engine takes where two steps remain (Scheme::two_steps); not listed
/// among the schemes.
const Scheme& four_eight_two_steps_scheme();

}  // namespace subdiv
