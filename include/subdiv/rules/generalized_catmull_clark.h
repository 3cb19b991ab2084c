#pragma once
/// \file
/// Generalized Catmull-Clark subdivision of any degree n >= 2 (Q.\ Chen and
/// H.\ Prautzsch, "Generalized Catmull-Clark subdivision", Karlsruhe Reports
/// in Informatics 2012,16), with the midpoint schemes M_n (Prautzsch and
/// Chen 2011) as the special case alpha = 1/4, beta = 1/2:
///
///     M_n-bar = B_r ... B_1 R      (n = 2r + 1, primal: a quad split),
///     M_n-bar = A B_r ... B_1 R    (n = 2r + 2, dual: a dual split),
///
/// R the refinement operator (face centres, edge midpoints, old vertices),
/// B_i = B_{alpha_i, beta_i} the smoothing operators (SmoothingWeights), A
/// the averaging operator (the dual mesh of face centres). Each operator is
/// one step of an ordinary mask-driven level (Scheme::steps), so refinement,
/// stencil tables and the analysis treat these schemes like any other.
/// Every weight is in generalized_catmull_clark.cpp.

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// "gcc": M_3-bar with Catmull-Clark's parameters alpha(m) = 1 - 3/m,
/// beta(m) = 2/m (Catmull-Clark itself on quad meshes); set other degrees
/// with set_degree and other weights in its DegreeParameters' smoothing;
/// its parameter check validates them (ParameterError).
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the scheme's smoothing list.
const Scheme& generalized_catmull_clark_scheme();

/// "midpoint": the midpoint scheme M_3 (alpha = 1/4, beta = 1/2 at every
/// valence, so B = A^2); other degrees with set_degree. Other weights are
/// refused (ParameterError).
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call, which builds
///   the scheme's smoothing list.
const Scheme& midpoint_scheme();

/// Sets the degree n of a generalized Catmull-Clark scheme, and with it the
/// split (quad for odd n, dual for even n) and the face rings the analysis
/// reads (SchemeTraits::analysis_rings). The smoothing list is not checked
/// against the new degree here: check_parameters() and refinement do that.
/// \param scheme a copy of generalized_catmull_clark_scheme() or
///   midpoint_scheme() (or another scheme with DegreeParameters and steps);
///   modified in place.
/// \param degree the degree n, >= 2.
/// \throws ParameterError if \p scheme has no DegreeParameters or no step
///   list, or \p degree < 2; \p scheme is then unchanged.
void set_degree(Scheme& scheme, int degree);

/// The operators of one level of a generalized Catmull-Clark scheme with
/// these parameters: R (bilinear_scheme()), B_1 .. B_r (identity splits,
/// r = (n - 1) / 2 rounded down), and A (a dual split) for even degrees.
/// \param parameters the scheme's parameters, holding DegreeParameters.
/// \return the steps in the order they apply, r + 1 or r + 2 schemes.
/// \throws ParameterError for parameters without a degree, a degree below 2,
///   a smoothing list of another length than 1 or r (when r > 0), a
///   SmoothingWeights::AtValence entry for a valence below 3, or weights
///   outside the paper's range (alpha, beta >= 0, 0 < alpha + beta < 1).
/// \throws std::bad_alloc if memory runs out.
std::vector<Scheme> generalized_catmull_clark_steps(const SchemeParameters& parameters);

/// The parameters of a generalized Catmull-Clark scheme as one line:
/// "n=5, B_1: alpha=0.25 beta=0.5; B_2: alpha=1-3/m beta=2/m", with any
/// per-valence weights appended; one entry "B_1..B_r" where a single set of
/// weights serves every operator.
/// \param parameters the scheme's parameters, holding DegreeParameters.
/// \return the description.
/// \throws std::bad_variant_access if \p parameters hold no DegreeParameters.
/// \throws std::bad_alloc if memory runs out.
std::string describe_smoothing(const SchemeParameters& parameters);

}  // namespace subdiv
