#pragma once
/// \file
/// Composite schemes: one upsampling, then averaging operators, as a user
/// writes them (P. Oswald, P. Schroeder, "Composite primal/dual
/// sqrt3-subdivision schemes", CAGD 20(3), 2003; the operator names are
/// OpenMesh's CompositeT). A level of
///
///     composite:Tvv4,VdE,EVc(loop),VdE,EVc(loop)
///
/// splits every triangle (Tvv4: the triangle split; Tvv3: the sqrt3 split),
/// gives each old vertex 4 (Tvv4) or 3 (Tvv3) times its position and each
/// new vertex 0 (upsampling by zeros), then applies the averages in turn,
/// each from the values on one kind of element of the split mesh (V
/// vertices, E edges, F faces) to another:
///
///   VF    face = mean of its vertices      FF     face = mean of its edge neighbours
///   FV    vertex = mean of its faces       FFc(c) (1 - c) mean of edge neighbours + c face
///   VV    vertex = mean of its one-ring    VVc(c) (1 - c) mean of one-ring + c vertex
///   VE    edge = mean of its ends          VdE    edge = mean of ends and opposite vertices
///   EV    vertex = mean of its edges       VdEc(c) c (ends) + (1/2 - c) (opposite vertices)
///   EF    face = mean of its edges         FE     edge = mean of its faces
///   EdE   edge = mean of the other edges of its faces
///   EdEc(c) c edge + (1 - c) mean of the other edges of its faces
///   FVc(c) vertex = mean over its faces F of c F + (1 - c) flap(F), the
///          face across F's edge opposite the vertex
///   EVc(c) vertex = mean over its faces of c (the face's edge leaving the
///          vertex) + (1 - c) (the face's edge opposite it)
///
/// The sequence must end on vertices. c is a number, or `loop` (c(n) =
/// (3/2 + cos(2 pi/n))^2 / 2 - 1) or `sqrt3` (c(n) = 2/3 (1 + cos(2 pi/n)))
/// of the valence n of the element the operator writes (a vertex's valence,
/// a face's size, an edge's 2).
/// Each level is refined by the engine as a composite scheme (Scheme::steps):
/// the split, then one smoothing step whose vertex masks are the averages
/// composed over the split mesh's topology. Closed triangle meshes without
/// sharp tags; a sequence whose masks do not sum to one at some vertex (it
/// does not reach the old vertices evenly) is refused when refinement meets
/// that vertex (ParameterError naming the sum and the valence).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "subdiv/rules/scheme.h"

namespace subdiv {

/// The elements an averaging operator reads from or writes to.
enum class CompositeElement { vertex, edge, face };

/// An averaging operator's coefficient: none, a number, or a function of
/// the valence named by the preset it comes from.
struct CompositeCoefficient {
  /// Which coefficient: none, a number, or a named function of the valence.
  enum class Kind {
    none,      ///< the operator takes none
    constant,  ///< `value`
    loop,      ///< (3/2 + cos(2 pi/n))^2 / 2 - 1
    sqrt3,     ///< 2/3 (1 + cos(2 pi/n))
  };
  Kind kind = Kind::none;  ///< which coefficient
  double value = 0.0;  ///< Kind::constant
  /// The coefficient at valence n.
  /// \param n the valence of the element written (>= 1).
  /// \return the number, or the named function at n; 0 for Kind::none.
  double at(int n) const noexcept;
};

/// One averaging operator of a composite scheme.
struct CompositeOperator {
  std::string name;  ///< as written: "VdE", "EVc", ...
  CompositeElement from = CompositeElement::vertex;  ///< the elements it reads
  CompositeElement to = CompositeElement::vertex;    ///< the elements it writes
  CompositeCoefficient c;                            ///< its coefficient, where it takes one
};

/// A parsed composite scheme: its upsampling and its averages.
struct CompositeProgram {
  std::string spec;                      ///< the text it was parsed from, "composite:..."
  SplitRule split = SplitRule::triangle;  ///< Tvv4: triangle; Tvv3: sqrt3
  double upsampling = 4.0;               ///< old vertices' factor: 4 (Tvv4) or 3 (Tvv3)
  std::vector<CompositeOperator> operators;  ///< the averages, in order
};

/// The composite scheme a spec names, built on first use and kept for the
/// program's lifetime (later calls with the same spec return the same
/// object).
/// \param spec "composite:" then the upsampling and the operators, comma
///   separated, as in the file comment.
/// \return the scheme.
/// \throws ParameterError if the spec does not parse (the message names the
///   operator), does not start with an upsampling or does not end on
///   vertices.
const Scheme& composite_scheme(std::string_view spec);

/// Whether \p name is a composite spec ("composite:..."): find_scheme()
/// builds those.
/// \param name a scheme name as a user typed it.
/// \return true where it starts with "composite:".
bool is_composite_spec(std::string_view name) noexcept;

/// The registered "composite-loop": Tvv4, VdE, EVc(loop), VdE, EVc(loop),
/// which is Loop's scheme (tests/rules/composite_test.cpp).
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call.
const Scheme& composite_loop_scheme();

/// The registered "composite-sqrt3": Tvv3, then two primal/dual cycles VF,
/// FF, FVc(sqrt3). The project's reading of Oswald and Schroeder's schemes,
/// whose sequences are not in the reachable sources: two cycles, and at low
/// valences Kobbelt's coefficient (plain means fail Reif's condition at
/// valence 3); the analysis finds it C1 at valences 3..16
/// (docs/schemes/composite.md).
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call.
const Scheme& composite_sqrt3_scheme();

/// The registered "composite-sqrt3-kobbelt": Tvv3, VF, FF, FVc(sqrt3), which
/// is Kobbelt's sqrt3 scheme.
/// \return the scheme, a static object valid for the program's lifetime.
/// \throws std::bad_alloc if memory runs out on the first call.
const Scheme& composite_sqrt3_kobbelt_scheme();

}  // namespace subdiv
