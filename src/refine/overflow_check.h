// Refinement of finite positions can still overflow: rules with negative
// weights (Kobbelt, the Butterfly schemes, large tensions) grow coordinates,
// so input near the double range comes out infinite. The engine refuses such
// a result rather than return it.
#pragma once

#include <vector>

#include "subdiv/core/types.h"

namespace subdiv {
struct Scheme;
}

namespace subdiv::detail {

/// The first position with a NaN or infinite coordinate, or -1 where all are
/// finite. Parallel over the calling thread's task arena.
Index first_non_finite(const std::vector<Vec3>& positions);

/// Throws InvalidInputError naming the scheme, the level and the first
/// non-finite vertex of `positions`, if there is one.
void refuse_overflow(const std::vector<Vec3>& positions, const Scheme& scheme, int level);

}  // namespace subdiv::detail
