#pragma once
/// \file
/// 4-8 subdivision on quads (sqrt2 split, QP arity sqrt 2, closed polygon
/// meshes); every weight is in four_eight.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The registered "four-eight" scheme (Velho and Zorin 2001): sqrt2 split,
/// closed polygon meshes, period 2.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& four_eight_scheme() noexcept;

/// Two four-eight steps as one quad-split level of a closed mesh, which the
/// engine takes where two steps remain (FastPath::two_steps); not listed
/// among the schemes.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& four_eight_two_steps_scheme() noexcept;

}  // namespace subdiv
