#pragma once
// Members of the generalized Catmull-Clark and midpoint families for the
// tests: copies of the registered schemes with another degree or weights.

#include "subdiv/rules/generalized_catmull_clark.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::test {

inline Scheme midpoint(int degree) {
  Scheme s = midpoint_scheme();
  set_degree(s, degree);
  return s;
}

/// Degree n with one constant (alpha, beta) for every smoothing operator.
inline Scheme gcc(int degree, double alpha, double beta) {
  Scheme s = generalized_catmull_clark_scheme();
  set_degree(s, degree);
  SmoothingWeights w;
  w.alpha = alpha;
  w.beta = beta;
  std::get<DegreeParameters>(s.parameters).smoothing = {w};
  return s;
}

}  // namespace subdiv::test
