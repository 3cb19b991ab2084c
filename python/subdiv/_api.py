"""Refinement, stencils, limits, analysis, depth and curves."""

import json

import numpy as np

from . import _subdiv
from ._errors import InvalidInputError
from ._mesh import Mesh, _array

# The rule and run options every refining call takes; any other keyword is a
# scheme parameter (tension; degree, alpha, beta, valence_weights).
_OPTION_NAMES = ("boundary", "boundary_rules", "corner_angles", "crease_method", "triangle_subdivision",
                 "face_varying", "flatness", "allow_non_manifold", "threads", "regular_grids")

#: The kinds of a child vertex's parent element, indexed by Level.origins' codes.
ORIGIN_KINDS = ("vertex", "edge", "face", "corner", "boundary_point")


def _core(mesh, what):
    if not isinstance(mesh, Mesh):
        raise InvalidInputError(f"{what}: expected a subdiv.Mesh, not {type(mesh).__name__}")
    return mesh._mesh


def _split(keywords):
    options = {k: v for k, v in keywords.items() if k in _OPTION_NAMES}
    parameters = {k: v for k, v in keywords.items() if k not in _OPTION_NAMES}
    return options, parameters


def _levels(levels):
    if isinstance(levels, bool) or not isinstance(levels, (int, np.integer)) or levels < 0:
        raise InvalidInputError(f"levels must be an integer >= 0, not {levels!r}")
    return int(levels)


def schemes():
    """Every surface scheme: a list of dicts with its name, summary, citation,
    split, traits (interpolating, needs_triangles, needs_quads,
    needs_closed_mesh, composite, limit_masks) and the parameters it takes."""
    return list(_subdiv.schemes())


def scheme(name, **parameters):
    """One scheme's description (as in schemes()), with parameters applied
    and checked: ``scheme("four-eight")``, ``scheme("gcc", degree=5)``."""
    return _subdiv.scheme(name, parameters)


class Level:
    """One level of a Hierarchy: ``mesh``, its ``level`` number, and
    ``origins``: (kinds, parents) arrays saying where each vertex comes from
    (kinds index ORIGIN_KINDS; parents index the parent level's vertices,
    edges, faces or corners), or None for the control mesh."""

    __slots__ = ("mesh", "level", "_core", "_origins")

    def __init__(self, core):
        self._core = core
        self._origins = None
        self.mesh = Mesh._wrap(core.mesh)
        self.level = core.level

    @property
    def origins(self):
        if self._core is not None:  # computed on first use, then kept
            self._origins = self._core.origins
            self._core = None
        return self._origins

    def __reduce__(self):
        return (_level_from_state, (self.mesh, self.level, self.origins))

    def __repr__(self):
        return f"subdiv.Level({self.level}: {self.mesh!r})"


def _level_from_state(mesh, level, origins):
    restored = Level.__new__(Level)
    restored.mesh, restored.level, restored._core, restored._origins = mesh, level, None, origins
    return restored


class Hierarchy:
    """The result of refine(): ``levels`` (coarsest kept first) and ``mesh``,
    the finest level's mesh."""

    __slots__ = ("levels", "scheme")

    def __init__(self, levels, scheme_name):
        self.levels = levels
        self.scheme = scheme_name

    @property
    def mesh(self):
        """The finest level's mesh."""
        return self.levels[-1].mesh

    def __repr__(self):
        return f"subdiv.Hierarchy({self.scheme}, levels {[l.level for l in self.levels]}, finest {self.mesh!r})"


def refine(mesh, scheme="catmull-clark", levels=1, keep="last", **keywords):
    """Refines mesh `levels` times with `scheme` and returns a Hierarchy.

    keep: "last" (the finest level only: the least memory and the fastest
    path, regular regions refined as grids; no origins) or "all" (every
    level, the control mesh first, each refined level with its vertices'
    origins).
    Rule options: boundary ("edge-only", "edge-and-corner"; default: the
    mesh's tag), boundary_rules ("standard", "piecewise-smooth"),
    corner_angles ("fixed", "measured"), crease_method ("uniform",
    "chaikin"), triangle_subdivision ("catmark", "smooth": Catmull-Clark's
    edge rule next to triangles; default: the mesh's tag), face_varying
    ("none", "corners-only", "corners-plus1", "corners-plus2", "boundaries",
    "all": how Catmull-Clark and Loop refine face-varying channels, as
    OpenSubdiv's option; default: the mesh's tag, else "all", linear),
    flatness, allow_non_manifold. Run options: threads (0: all
    cores; the result does not depend on it), regular_grids. Any other
    keyword is a scheme parameter: tension (butterfly, kobbelt, ...),
    degree, alpha, beta, valence_weights (gcc, midpoint).

    The mesh is validated first (ValidationError lists the issues); the GIL
    is released while refining, and Ctrl-C stops between levels
    (KeyboardInterrupt)."""
    if keep not in ("last", "all"):
        raise InvalidInputError(f"keep must be 'last' or 'all', not {keep!r}")
    options, parameters = _split(keywords)
    cores = _subdiv.refine(_core(mesh, "refine"), scheme, _levels(levels), options, parameters, keep == "all")
    return Hierarchy([Level(c) for c in cores], scheme)


def stencils(mesh, scheme="catmull-clark", levels=1, **keywords):
    """The stencil table from mesh's points to the points of level `levels`,
    as a scipy.sparse.csr_matrix S of shape (refined points, points):
    ``S @ mesh.points`` is refine(mesh, scheme, levels).mesh.points (to
    rounding), for any moved points. Keywords as for refine()."""
    import scipy.sparse

    options, parameters = _split(keywords)
    offsets, columns, weights, rows, sources = _subdiv.stencils(_core(mesh, "stencils"), scheme, _levels(levels),
                                                                options, parameters)
    return scipy.sparse.csr_matrix((weights, columns, offsets), shape=(rows, sources))


class Limit:
    """limit()'s result: ``positions`` (n, 3), ``normals`` (n, 3) or None,
    ``sources`` (per vertex: "closed_form", "generic" eigenvector masks, or
    "refined_position" where no mask applies), ``approximated`` (how many
    vertices are only at a refined position), ``levels_refined``."""

    __slots__ = ("positions", "normals", "sources", "approximated", "levels_refined")

    def __init__(self, d):
        for name in self.__slots__:
            setattr(self, name, d[name])


def limit(mesh, scheme="catmull-clark", normals=True, route="closed_form", **keywords):
    """Where each control vertex ends up after infinitely many steps, and the
    unit normal there: the scheme's closed-form limit masks where it has
    them (route="closed_form"), else the eigenvectors of its subdivision
    matrices (route="generic" uses those everywhere). Keywords as for refine()."""
    if route not in ("closed_form", "generic"):
        raise InvalidInputError(f"route must be 'closed_form' or 'generic', not {route!r}")
    options, parameters = _split(keywords)
    return Limit(_subdiv.limit(_core(mesh, "limit"), scheme, bool(normals), route == "generic", options, parameters))


def _arrays(document):
    """The analysis document with its eigenvalues and masks as numpy arrays."""
    def complex_array(values):
        return np.array([complex(v["re"], v["im"]) for v in values], dtype=np.complex128)

    for key in ("leading_eigenvalues", "eigenvalues"):
        if key in document:
            document[key] = complex_array(document[key])
    for key in ("limit_mask", "tangent_mask", "tangent_masks", "layout"):
        if document.get(key) is not None:
            document[key] = np.array(document[key], dtype=np.float64)
    if document.get("ring_of") is not None:
        document["ring_of"] = np.array(document["ring_of"], dtype=np.int64)
    return document


def analyze(scheme, k=None, configuration="interior", corner="convex", angle=None, characteristic_map=True,
            boundary_rules="standard", flatness=None, **parameters):
    """A scheme's behaviour at local configurations: the same document as
    ``subdiv analyze --json``, with eigenvalues (complex), masks and layouts
    as numpy arrays.

    k: the valence (interior) or the faces of the sector (boundary, corner):
    an int or a sequence; default 3..12 (interior) or 1..12.
    configuration: "interior", "boundary" or "corner" (corner: "convex" or
    "concave", angle in degrees). A curve scheme's name (cubic-bspline,
    chaikin, four-point) analyses the curve rule; then only tension applies."""
    curve_names = {s["name"] for s in _subdiv.curve_schemes()}
    if scheme in curve_names:
        if k is not None or configuration != "interior" or set(parameters) - {"tension"}:
            raise InvalidInputError(f"{scheme} is a curve scheme: only tension applies")
        return _arrays(json.loads(_subdiv.analyze_curve_json(scheme, parameters.get("tension"))))
    if k is None:
        ks = list(range(3, 13)) if configuration == "interior" else list(range(1, 13))
    elif isinstance(k, (int, np.integer)) and not isinstance(k, bool):
        ks = [int(k)]
    else:
        ks = [int(v) for v in k]
    document = json.loads(_subdiv.analyze_json(scheme, ks, configuration, corner, angle, bool(characteristic_map),
                                               boundary_rules, flatness, parameters))
    document["configurations"] = [_arrays(c) for c in document["configurations"]]
    return document


def depth(mesh, scheme="catmull-clark", eps=1e-3, verify=False, **keywords):
    """How many uniform steps bring every vertex within eps of its limit,
    from the control mesh alone (the a priori bound): a dict with depth,
    bound (the bound there), source ("paper" or "analysis"), measure
    ("vertex-to-limit", or "surface-to-limit" for the interpolating schemes,
    whose bound is on the level's linear surface), start, terms.
    verify=True also refines to that depth and reports the measured
    largest distance (and one level less)."""
    options, parameters = _split(keywords)
    return _subdiv.depth(_core(mesh, "depth"), scheme, float(eps), bool(verify), options, parameters)


class Adaptive:
    """adaptive()'s result: ``mesh`` (conforming), ``source_levels`` and
    ``source_indices`` (each output vertex is vertex source_indices[i] of
    uniform level source_levels[i]), ``distances`` (to the limit),
    ``uniform_depth`` and ``uniform_faces`` (uniform refinement to the same
    eps), ``transition_faces``, ``approximated`` (output vertices whose limit
    is only approximated: eps is not established there), ``steps_per_level``
    (refinement steps per level: 2 for four-eight, the sqrt3 and sqrt2
    splits and midedge; 1 otherwise), ``measure`` ("vertex-to-limit", or "surface-to-limit" for
    interpolating schemes, whose faces are refined until their next level's
    vertices lie within ``displacement_threshold`` = eps (1 - r) of them,
    r the depth bound's rate; ``largest_displacement`` is the largest such
    distance left)."""

    __slots__ = ("mesh", "source_levels", "source_indices", "distances", "uniform_depth", "uniform_faces",
                 "transition_faces", "approximated", "steps_per_level", "measure", "largest_displacement",
                 "displacement_threshold")

    def __init__(self, d):
        for name in self.__slots__:
            setattr(self, name, Mesh._wrap(d[name]) if name == "mesh" else d[name])


def adaptive(mesh, scheme="catmull-clark", eps=1e-3, max_level=12, **keywords):
    """Refines only where control vertices are further than eps from their
    limit, and joins the levels without cracks (Loop, Catmull-Clark and the
    other schemes whose split it covers)."""
    options, parameters = _split(keywords)
    return Adaptive(_subdiv.adaptive(_core(mesh, "adaptive"), scheme, float(eps), int(max_level), options,
                                     parameters))


def curve_schemes():
    """The curve schemes: name, summary, citation, interpolating, dual, end rule."""
    return list(_subdiv.curve_schemes())


def refine_curve(points, scheme="cubic-bspline", levels=1, closed=False, tension=None):
    """Refines a polyline: points (n, 2) or (n, 3); returns the refined
    points with as many columns. closed joins the last point to the first.
    tension: four-point's w (default 1/16)."""
    array = _array("points", points, np.float64, 2)
    if array.shape[1] not in (2, 3):
        raise InvalidInputError(f"points must have 2 or 3 columns, not {array.shape[1]}")
    if not np.all(np.isfinite(array)):
        row = int(np.argwhere(~np.isfinite(array))[0][0])
        raise InvalidInputError(f"point {row} has a non-finite coordinate")
    padded = array if array.shape[1] == 3 else np.hstack([array, np.zeros((len(array), 1))])
    refined = _subdiv.refine_curve(padded, scheme, _levels(levels), bool(closed), tension)
    return refined[:, :array.shape[1]].copy() if array.shape[1] == 2 else refined
