#pragma once
/// \file
/// The local subdivision matrix of a scheme at one configuration, read off
/// the scheme's own refinement (Zorin's survey, section 2.1): build the
/// configuration's ring mesh, refine it one analysis step (the scheme's
/// period: one refinement step for most schemes) with the ordinary engine
/// into a stencil table, and restrict the rows of the neighbourhood's image
/// that many levels down to the neighbourhood's columns. No weight is written twice: the
/// matrix holds exactly what refinement computes.

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "subdiv/refine/configuration.h"
#include "subdiv/core/types.h"
#include "subdiv/mesh/topology.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The local subdivision matrix S of a scheme at one configuration, with
/// what it was read off (local_subdivision_matrix()).
struct LocalSubdivisionMatrix {
  Configuration configuration;  ///< the configuration at the centre
  /// The rules the ring mesh was refined with; levels = period.
  RefineOptions rules;
  /// Refinement steps S spans: the scheme's period (S is the matrix of that
  /// many composed steps, its eigenvalues those of one step to that power).
  int period = 1;
  /// The neighbourhood: the centre and the vertices of the faces within
  /// this many face rings of it (1: Catmull-Clark's 2k + 1, Loop's k + 1).
  int rings = 1;
  /// Row a: the neighbourhood's vertex a one analysis step (`period`
  /// levels) down, as weights on the neighbourhood's vertices now
  /// (p_next = S p).
  Eigen::MatrixXd S;
  /// Each neighbourhood vertex's position in the planar layout, in the
  /// order of S: the centre first, then ring by ring, counter-clockwise from
  /// the first ray.
  std::vector<Vec3> layout;
  /// The face ring (0 = centre) of each neighbourhood vertex.
  std::vector<int> ring_of;
  /// Interior configurations: index of each vertex's image under the
  /// rotation by 2 pi / k (S commutes with it). Empty otherwise.
  std::vector<int> rotate;
  /// True when the image rows use no vertex outside the neighbourhood; else
  /// the first offending row is named in `invariance_note`.
  bool invariant = true;
  std::string invariance_note;  ///< where `invariant` is false, the first offending row; else empty
};

/// The rings of faces of the ring mesh a neighbourhood of `rings` face rings
/// is analysed on: one more ring makes every edge and vertex of the
/// neighbourhood interior to the mesh, so the rules there are the ones the
/// configuration has; one more keeps the outer boundary's rules away from
/// the masks of the neighbourhood's image.
/// \param rings the neighbourhood's face rings.
/// \return \p rings + 2.
inline int ring_mesh_size(int rings) noexcept { return rings + 2; }

/// Each vertex's face ring about `centre` (ring 0: the centre's vertices;
/// ring r: the vertices of the faces touching ring r - 1), -1 beyond
/// `rings`: the neighbourhoods the matrices are read over.
/// \param topology the mesh's topology.
/// \param centre the vertices of ring 0 (a vertex, or a face's vertices).
/// \param rings the face rings to number, >= 0.
/// \return one entry per vertex of \p topology.
/// \pre every vertex of \p centre is in [0, topology.vertex_count())
///   (unchecked).
/// \throws std::bad_alloc if memory runs out.
std::vector<int> vertex_rings(const MeshTopology& topology, std::span<const Index> centre, int rings);

/// The matrix of `scheme` at `configuration` over a neighbourhood of `rings`
/// face rings, refined under `rules` (boundary rules, flatness; its level
/// count is ignored: the matrix spans scheme.traits.period levels; its
/// on_level is not called). The scheme's needs_closed_mesh is lifted: the
/// ring mesh's outer boundary lies outside the neighbourhood.
/// \param scheme the scheme.
/// \param configuration the configuration at the centre.
/// \param rings the neighbourhood's face rings, >= 1.
/// \param rules the rule choices.
/// \return the matrix, with its layout, rings, rotation and invariance.
/// \throws InvalidInputError for \p rings < 1, schemes or configurations the
///   ring layout does not cover (ring_mesh(), valence_two_ring_mesh()), a
///   period below 1, a period above 1 at interior k = 2, or a layout whose
///   images or rotation are not found.
/// \throws ParameterError, ValidationError or TopologyError where refining the
///   ring mesh fails (refine_stencil_table()), e.g. for parameters out of
///   range or options the scheme has no rules for.
/// \throws std::bad_alloc if memory runs out.
LocalSubdivisionMatrix local_subdivision_matrix(const Scheme& scheme, const Configuration& configuration, int rings,
                                                const RefineOptions& rules = {});

/// The smallest neighbourhood (1 .. max_rings face rings, or the scheme's
/// traits.analysis_rings where more) that is invariant, or the largest
/// tried, not invariant, when none is.
/// \param scheme the scheme.
/// \param configuration the configuration at the centre.
/// \param max_rings the most face rings to try, >= 1 (the scheme's
///   traits.analysis_rings where more).
/// \param rules the rule choices.
/// \return the matrix. Where no neighbourhood is tried (\p max_rings and
///   traits.analysis_rings both below 1), a default LocalSubdivisionMatrix
///   with an empty S.
/// \throws InvalidInputError, ParameterError, ValidationError or TopologyError
///   as local_subdivision_matrix() does.
/// \throws std::bad_alloc if memory runs out.
LocalSubdivisionMatrix invariant_subdivision_matrix(const Scheme& scheme, const Configuration& configuration,
                                                    int max_rings = 4, const RefineOptions& rules = {});

}  // namespace subdiv
