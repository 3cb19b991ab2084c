#pragma once
/// \file
/// Interpolating sqrt2 subdivision (sqrt2 split, QP arity sqrt 2, closed quad
/// meshes): the 12-point face rule with virtual points at extraordinary
/// vertices, old vertices kept. Every weight is in interpolating_sqrt2.cpp;
/// C1 at valences 3..16 by the analysis (docs/schemes/interpolating-sqrt2.md).

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The registered "interpolating-sqrt2" scheme: sqrt2 split, closed quad
/// meshes, period 2.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& interpolating_sqrt2_scheme() noexcept;

}  // namespace subdiv
