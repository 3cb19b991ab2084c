#include "surface_normals.h"

#include "subdiv/analysis/limit.h"

namespace subdiv::cli {

std::vector<Vec3> limit_normals_for_picture(const PolygonMesh& surface, const Scheme& scheme,
                                            const RefineOptions& refine) {
  if (!scheme.limit_masks || limit_unavailable(scheme)) return {};
  LimitOptions options;
  options.refine = refine;
  options.refine.levels = 0;
  options.refine.on_level = nullptr;
  options.max_resolve_levels = 0;  // the picture's own level: no further refinement
  return limit_positions(surface, scheme, options).normals;
}

}  // namespace subdiv::cli
