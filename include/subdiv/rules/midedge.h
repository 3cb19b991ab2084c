#pragma once
/// \file
/// Midedge subdivision (midedge split, QD arity sqrt 2, closed polygon
/// meshes); every weight is in midedge.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The registered "midedge" scheme (Peters and Reif 1997): midedge split,
/// each child vertex its edge's midpoint; closed polygon meshes.
/// \return the scheme, a static object valid for the program's lifetime.
const Scheme& midedge_scheme() noexcept;

}  // namespace subdiv
