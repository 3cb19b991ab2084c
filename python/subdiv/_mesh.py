"""subdiv.Mesh: a polygon mesh over numpy arrays, and files in and out."""

import os

import numpy as np

from . import _subdiv
from ._errors import InvalidInputError

_INDEX_MAX = np.iinfo(np.int32).max


def _array(name, value, dtype, ndim=None, columns=None):
    """value as a C-contiguous array of dtype, checked for shape and kind."""
    try:
        array = np.asarray(value)
    except Exception as e:  # ragged nested lists and the like
        raise InvalidInputError(f"{name}: not an array ({e})") from None
    if array.size == 0:
        array = np.empty(array.shape, dtype)
    elif dtype is np.int32:
        if not np.issubdtype(array.dtype, np.integer):
            raise InvalidInputError(f"{name} must hold integers, not {array.dtype}")
        elif array.min() < 0 or array.max() > _INDEX_MAX:
            bad = array.min() if array.min() < 0 else array.max()
            raise InvalidInputError(f"{name}: index {bad} is out of range")
    else:
        if not (np.issubdtype(array.dtype, np.floating) or np.issubdtype(array.dtype, np.integer)):
            raise InvalidInputError(f"{name} must hold numbers, not {array.dtype}")
    if ndim is not None and array.size == 0 and array.ndim != ndim:
        array = array.reshape((0,) + ((columns or 0,) if ndim == 2 else ()))
    if ndim is not None and array.ndim != ndim:
        raise InvalidInputError(f"{name} must be {ndim}-dimensional, not of shape {array.shape}")
    if columns is not None and array.shape[1] != columns:
        raise InvalidInputError(f"{name} must have {columns} columns, not {array.shape[1]}")
    return np.ascontiguousarray(array, dtype=dtype)


def _faces(faces):
    """(offsets, indices) from an (m, k) array, a list of index lists, or (offsets, indices)."""
    if isinstance(faces, tuple) and len(faces) == 2:
        return _array("face offsets", faces[0], np.int32, 1), _array("face indices", faces[1], np.int32, 1)
    if isinstance(faces, np.ndarray):
        sizes = None
    else:
        try:
            sizes = [len(f) for f in faces]
        except TypeError:
            raise InvalidInputError("faces must be an (m, k) integer array, a list of vertex index lists, "
                                    "or a tuple (offsets, indices)") from None
    if sizes is None or len(set(sizes)) == 1:
        array = _array("faces", faces, np.int32, 2)
        m, k = array.shape
        return (np.arange(m + 1, dtype=np.int64) * k).astype(np.int32), array.reshape(-1)
    offsets = np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)
    if offsets[-1] > _INDEX_MAX:
        raise InvalidInputError("faces: too many corners for 32-bit indices")
    indices = _array("faces", [i for f in faces for i in f], np.int32, 1)
    return offsets.astype(np.int32), indices


def _creases(creases):
    if creases is None:
        return np.zeros((0, 2), np.int32), np.zeros(0)
    if isinstance(creases, tuple) and len(creases) == 2:
        edges = _array("creases", creases[0], np.int32, 2, 2)
        return edges, _array("crease sharpness", creases[1], np.float64, 1)
    array = _array("creases", creases, np.float64)
    if array.ndim == 2 and array.shape[1] == 3:
        edges = array[:, :2]
        if not np.all(np.isfinite(edges)) or not np.all(edges == np.round(edges)):
            raise InvalidInputError("creases: the first two columns must be vertex indices")
        return _array("creases", edges.astype(np.int64), np.int32, 2, 2), _array(
            "crease sharpness", array[:, 2], np.float64, 1)
    edges = _array("creases", creases, np.int32, 2, 2)
    return edges, np.full(len(edges), np.inf)


def _corners(corners):
    if corners is None:
        return np.zeros(0, np.int32), np.zeros(0)
    if isinstance(corners, tuple) and len(corners) == 2:
        return _array("corners", corners[0], np.int32, 1), _array("corner sharpness", corners[1], np.float64, 1)
    vertices = _array("corners", corners, np.int32, 1)
    return vertices, np.full(len(vertices), np.inf)


def _library_sharpness(values):
    # The library writes infinitely sharp as its own constant (10, as OpenSubdiv).
    return np.where(np.isinf(values), 10.0, values)


class Mesh:
    """A polygon mesh: points, faces, sharpness tags and data channels.

    Mesh(points, faces, creases=None, corners=None, holes=None,
         vertex_channels=None, uvs=None, face_varying_channels=None)

    points: an (n, 3) array of float64 (other real dtypes are converted).
    faces: an (m, k) integer array (every face a k-gon), a list of vertex
        index lists (any sizes), or a tuple (offsets, indices): face f is
        indices[offsets[f]:offsets[f + 1]].
    creases: an (c, 2) array of edges (infinitely sharp), an (c, 3) array
        (v0, v1, sharpness), or a tuple (edges, sharpness).
    corners: vertex indices (infinitely sharp) or a tuple (vertices, sharpness).
    holes: face indices.
    vertex_channels: {name: (n, c) array}, data refined with the points.
    uvs: a tuple (values (u, 2), indices (one per face corner)): the
        face-varying channel "uv"; face_varying_channels: {name: (values, indices)}.

    The arrays the properties return share the mesh's memory (no copy):
    ``points`` and the channels are writable (moving points re-poses the
    mesh); the face arrays are read-only. Bad input raises
    InvalidInputError (or TopologyError) naming the element.
    """

    __slots__ = ("_mesh",)

    def __init__(self, points, faces, creases=None, corners=None, holes=None, vertex_channels=None, uvs=None,
                 face_varying_channels=None):
        points = _array("points", points, np.float64, 2, 3)
        offsets, indices = _faces(faces)
        crease_edges, crease_sharpness = _creases(creases)
        corner_vertices, corner_sharpness = _corners(corners)
        holes = _array("holes", [] if holes is None else holes, np.int32, 1)
        channels = {}
        for name, values in (vertex_channels or {}).items():
            channels[str(name)] = _array(f"vertex channel '{name}'", values, np.float64, 2)
        varying = {}
        if uvs is not None:
            varying["uv"] = uvs
        varying.update(face_varying_channels or {})
        fv = {}
        for name, pair in varying.items():
            if not (isinstance(pair, tuple) and len(pair) == 2):
                raise InvalidInputError(f"face-varying channel '{name}' must be a tuple (values, indices)")
            fv[str(name)] = (_array(f"face-varying channel '{name}' values", pair[0], np.float64, 2),
                             _array(f"face-varying channel '{name}' indices", pair[1], np.int32, 1))
        self._mesh = _subdiv.Mesh._from_arrays(points, offsets, indices, crease_edges,
                                               _library_sharpness(crease_sharpness), corner_vertices,
                                               _library_sharpness(corner_sharpness), holes, channels, fv)

    @classmethod
    def _wrap(cls, core):
        mesh = cls.__new__(cls)
        mesh._mesh = core
        return mesh

    @property
    def points(self):
        """(n, 3) float64 view of the positions (writable, shares memory)."""
        return self._mesh.points

    @property
    def face_offsets(self):
        """(m + 1,) int32 view: face f's corners are face_indices[face_offsets[f]:face_offsets[f + 1]]."""
        return self._mesh.face_offsets

    @property
    def face_indices(self):
        """int32 view of every face's vertex indices, faces concatenated."""
        return self._mesh.face_indices

    @property
    def faces(self):
        """(m, k) int32 view when every face has k corners; ValueError for mixed sizes."""
        offsets = self.face_offsets
        sizes = np.diff(offsets)
        if len(sizes) == 0:
            return self.face_indices.reshape(0, 0)
        if np.any(sizes != sizes[0]):
            raise ValueError("faces of mixed sizes: use face_offsets and face_indices (or face_sizes)")
        return self.face_indices.reshape(-1, int(sizes[0]))

    @property
    def face_sizes(self):
        """(m,) int32: the number of corners of each face."""
        return np.diff(self.face_offsets)

    @property
    def vertex_count(self):
        """The number of vertices (points)."""
        return self._mesh.vertex_count

    @property
    def face_count(self):
        """The number of faces."""
        return self._mesh.face_count

    @property
    def creases(self):
        """(edges (c, 2) int32, sharpness (c,) float64): a copy; inf for infinitely sharp."""
        edges, sharpness = self._mesh.creases
        return edges, np.where(sharpness >= 10.0, np.inf, sharpness)

    @property
    def corners(self):
        """(vertices (k,) int32, sharpness (k,) float64): a copy; inf for infinitely sharp."""
        vertices, sharpness = self._mesh.corners
        return vertices, np.where(sharpness >= 10.0, np.inf, sharpness)

    @property
    def holes(self):
        """(h,) int32 copy of the faces tagged as holes."""
        return self._mesh.holes

    @property
    def boundary_interpolation(self):
        """The mesh's boundary tag: "edge-only", "edge-and-corner" or "none"."""
        return self._mesh.boundary_interpolation

    @property
    def vertex_channels(self):
        """{name: (n, c) float64 view}: per-vertex data (writable, shares memory)."""
        return self._mesh.vertex_channels

    @property
    def face_varying_channels(self):
        """{name: (values (u, c) view, indices (corners,) read-only view)}: per-corner data."""
        return self._mesh.face_varying_channels

    @property
    def uvs(self):
        """The face-varying channel "uv" as (values, indices), or None."""
        return self.face_varying_channels.get("uv")

    @property
    def polylines(self):
        """[(vertex indices, closed)]: curves over the points (from OBJ `l` lines)."""
        return self._mesh.polylines

    def copy(self):
        """A deep copy: its arrays share nothing with this mesh."""
        return Mesh._wrap(self._mesh._copy())

    def validate(self):
        """What makes the mesh unfit for subdivision, as a list of
        (kind, severity, element, message) tuples; empty when it is valid."""
        return self._mesh_issues()

    def _mesh_issues(self):
        return _subdiv.validate(self._mesh)

    def __reduce__(self):
        # The OBJ text (shortest round-trip decimals) holds everything a mesh
        # from this module holds except channels other than "uv", "normal"
        # and "color"; pickling such a mesh raises InvalidInputError.
        return (_from_state, (self._mesh._obj_state(),))

    def __repr__(self):
        return f"subdiv.Mesh({self.vertex_count} vertices, {self.face_count} faces)"


def _from_state(state):
    return Mesh._wrap(_subdiv.Mesh._from_obj_state(state))


def read(path, weld_tolerance=0.0):
    """Reads a mesh from an OBJ (with crease, corner and hole tags), PLY, OFF,
    glTF (.gltf, .glb) or STL file, chosen by the extension. Raises IoError
    when the file cannot be read, ParseError (with .path and .line) when it is
    malformed. weld_tolerance: STL, and glTF not written by subdiv: corners
    within it in every coordinate become one vertex (0: equal positions only;
    negative: none). read_with_warnings() also returns the reader's notes."""
    mesh, _ = read_with_warnings(path, weld_tolerance)
    return mesh


def read_with_warnings(path, weld_tolerance=0.0):
    """(mesh, warnings): read() and the reader's notes, one line each."""
    core, warnings = _subdiv.read(os.fspath(path), float(weld_tolerance))
    return Mesh._wrap(core), list(warnings)


def write(mesh, path, ascii=False, tags=True, channels=True, hole_faces_as_faces=False, threads=0):
    """Writes mesh to path (OBJ, PLY, OFF, glTF or STL by the extension)
    atomically: a temporary file renamed into place, so a failure leaves no
    partial file.

    ascii: PLY and STL as text (default binary little-endian). tags: OBJ tag
    lines, glTF extras. channels: the uv, normal and colour channels (OBJ, PLY,
    glTF). hole_faces_as_faces: PLY, OFF and STL write hole faces as ordinary
    faces (default: left out, with a note).
    threads: formatting workers (0: all cores; the bytes are the same).
    Returns the notes about data the format cannot hold."""
    if not isinstance(mesh, Mesh):
        raise InvalidInputError(f"write: expected a subdiv.Mesh, not {type(mesh).__name__}")
    return list(_subdiv.write(mesh._mesh, os.fspath(path), bool(ascii), bool(tags), bool(channels),
                              bool(hole_faces_as_faces), int(threads)))


def validate(mesh):
    """mesh.validate(): the issues that make a mesh unfit for subdivision."""
    if not isinstance(mesh, Mesh):
        raise InvalidInputError(f"validate: expected a subdiv.Mesh, not {type(mesh).__name__}")
    return mesh.validate()
