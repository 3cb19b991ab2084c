"""subdiv: subdivision surfaces over numpy.

Every scheme of Zorin's survey with exact boundary, crease and corner rules,
stencil tables, limit positions and normals, the analysis of a scheme's
subdivision matrices, a priori depth and adaptive refinement, and curve
schemes. A tour: docs/python.md.

    import subdiv
    mesh = subdiv.read("cube.obj")
    fine = subdiv.refine(mesh, "catmull-clark", levels=2).mesh
    fine.points          # (n, 3) float64, no copy
"""

from ._errors import (Error, InvalidInputError, IoError, ParameterError, ParseError, TopologyError,
                      ValidationError)
from ._mesh import Mesh, read, read_with_warnings, validate, write
from ._api import (ORIGIN_KINDS, Adaptive, Hierarchy, Level, Limit, adaptive, analyze, curve_schemes, depth, limit,
                   refine, refine_curve, scheme, schemes, stencils)
from ._subdiv import __version__

__all__ = [
    "Error", "InvalidInputError", "IoError", "ParameterError", "ParseError", "TopologyError", "ValidationError",
    "Mesh", "read", "read_with_warnings", "validate", "write",
    "ORIGIN_KINDS", "Adaptive", "Hierarchy", "Level", "Limit", "adaptive", "analyze", "curve_schemes", "depth",
    "limit", "refine", "refine_curve", "scheme", "schemes", "stencils",
    "__version__",
]
