// Midedge: all of its weights (J. Peters, U. Reif, "The simplest subdivision
// scheme for smoothing polyhedra", ACM TOG 16(4), 1997; Zorin's survey,
// section 4.2). The simplest rule: the point of an edge is the average of
// its ends. On a regular quad mesh two steps are the four-direction box
// spline's refinement; at extraordinary faces the limit is smooth but the
// surface quality is poor (the survey). Peters and Reif's improved rule for
// such faces is not implemented: its weights were in a part of the paper
// the survey does not reproduce.
//
// Two steps give a child vertex per parent corner: the midpoint of the
// midpoints of the corner's two edges, v/2 + (prev + next)/4, a Doo-Sabin
// type corner-cutting rule (checked in tests/rules/midedge_test.cpp).

#include "subdiv/rules/midedge.h"

#include "rule_helpers.h"

namespace subdiv {

namespace {

void edge_point(const LevelView& level, Index e, EdgeRule, MaskBuilder& mask) { detail::add_edge_midpoint(level, e, mask); }

}  // namespace

const Scheme& midedge_scheme() noexcept {
  static const Scheme scheme{
      .name = "midedge",
      .summary = "approximating, midedge split (arity sqrt 2), closed polygon meshes; edge midpoints (the simplest "
                 "rule)",
      .citation = "J. Peters, U. Reif: The simplest subdivision scheme for smoothing polyhedra, ACM Transactions on "
                  "Graphics 16(4), 1997",
      .split = SplitRule::midedge,
      .traits = {.needs_closed_mesh = true, .period = 2},  // two steps map a face configuration onto itself
      .masks = {.edge_point = edge_point}};
  return scheme;
}

}  // namespace subdiv
