"""subdiv.Mesh: arrays in, views out, tags, channels, files, pickling, and
bad input as clear exceptions."""

import os
import pickle

import numpy as np
import pytest

import subdiv
from conftest import MESHES, TEST_DATA

CUBE_POINTS = [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]]
CUBE_FACES = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def cube(**keywords):
    return subdiv.Mesh(np.array(CUBE_POINTS, dtype=float), np.array(CUBE_FACES), **keywords)


def test_arrays_round_trip():
    mesh = cube()
    assert mesh.vertex_count == 8 and mesh.face_count == 6
    np.testing.assert_array_equal(mesh.points, CUBE_POINTS)
    np.testing.assert_array_equal(mesh.faces, CUBE_FACES)
    np.testing.assert_array_equal(mesh.face_offsets, np.arange(0, 28, 4))
    assert mesh.points.dtype == np.float64 and mesh.faces.dtype == np.int32


def test_face_forms_agree():
    ragged = subdiv.Mesh(CUBE_POINTS, [list(f) for f in CUBE_FACES])
    offsets = np.arange(0, 28, 4)
    split = subdiv.Mesh(CUBE_POINTS, (offsets, np.ravel(CUBE_FACES)))
    for mesh in (ragged, split):
        np.testing.assert_array_equal(mesh.faces, CUBE_FACES)
    mixed = subdiv.Mesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]], [[0, 1, 2, 3], [1, 4, 2]])
    np.testing.assert_array_equal(mixed.face_sizes, [4, 3])
    with pytest.raises(ValueError, match="mixed sizes"):
        mixed.faces


def test_views_share_memory_without_copies():
    mesh = cube()
    points = mesh.points
    assert not points.flags.owndata and points.flags.writeable
    assert np.shares_memory(points, mesh.points)
    points[0] = [5, 5, 5]
    np.testing.assert_array_equal(mesh.points[0], [5, 5, 5])
    assert not mesh.face_indices.flags.writeable
    with pytest.raises(ValueError):
        mesh.face_indices[0] = 3
    # A view keeps the mesh alive after the last reference to it goes.
    view = subdiv.Mesh(CUBE_POINTS, CUBE_FACES).points
    np.testing.assert_array_equal(view, CUBE_POINTS)


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_large_result_is_not_copied():
    # A 10M-point refinement result (a 400 x 400 torus, three levels): its
    # points and faces are views of the library's arrays, so reading them
    # all adds nothing resident, where a copy would add 240 MB.
    n = 400
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    u, v = 2 * np.pi * i / n, 2 * np.pi * j / n
    points = np.stack([(2 + np.cos(v)) * np.cos(u), (2 + np.cos(v)) * np.sin(u), np.sin(v)], -1).reshape(-1, 3)
    quad = np.stack([j * n + i, j * n + (i + 1) % n, ((j + 1) % n) * n + (i + 1) % n, ((j + 1) % n) * n + i], -1)
    fine = subdiv.refine(subdiv.Mesh(points, quad.reshape(-1, 4)), "catmull-clark", 3).mesh
    assert fine.vertex_count == 10_240_000
    before = resident_bytes()
    a, b = fine.points, fine.points
    total = a.sum() + fine.face_indices.sum()
    assert np.isfinite(total)
    assert resident_bytes() - before < 16 << 20
    assert a.__array_interface__["data"][0] == b.__array_interface__["data"][0]
    assert not a.flags.owndata


def test_tags():
    mesh = cube(creases=[[0, 1], [1, 2]], corners=[6], holes=[5])
    edges, sharpness = mesh.creases
    np.testing.assert_array_equal(edges, [[0, 1], [1, 2]])
    assert np.all(np.isinf(sharpness))
    vertices, corner_sharpness = mesh.corners
    np.testing.assert_array_equal(vertices, [6])
    np.testing.assert_array_equal(mesh.holes, [5])
    semi = cube(creases=np.array([[0, 1, 2.5]]), corners=([6], [1.5]))
    assert semi.creases[1][0] == 2.5 and semi.corners[1][0] == 1.5


def test_channels():
    colors = np.arange(24, dtype=float).reshape(8, 3)
    uv_values = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    uv_indices = np.tile([0, 1, 2, 3], 6)
    mesh = cube(vertex_channels={"color": colors}, uvs=(uv_values, uv_indices))
    np.testing.assert_array_equal(mesh.vertex_channels["color"], colors)
    values, indices = mesh.uvs
    np.testing.assert_array_equal(values, uv_values)
    np.testing.assert_array_equal(indices, uv_indices)


@pytest.mark.parametrize("points, faces, message", [
    (np.zeros((4, 2)), [[0, 1, 2]], "3 columns"),
    (np.zeros(12), [[0, 1, 2]], "2-dimensional"),
    ([["a", "b", "c"]] * 3, [[0, 1, 2]], "numbers"),
    (np.zeros((3, 3)), np.array([[0.0, 1.0, 2.0]]), "integers"),
    (np.zeros((3, 3)), [[0, 1, -2]], "out of range"),
    (np.zeros((3, 3)), [[0, 1, 2**40]], "out of range"),
])
def test_bad_arrays_raise(points, faces, message):
    with pytest.raises(subdiv.InvalidInputError, match=message):
        subdiv.Mesh(points, faces)


def test_bad_meshes_name_the_element():
    with pytest.raises(subdiv.InvalidInputError, match="point 1 has a non-finite coordinate"):
        subdiv.Mesh([[0, 0, 0], [np.nan, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(subdiv.InvalidInputError, match="3"):
        subdiv.Mesh(np.zeros((3, 3)), [[0, 1, 3]])
    with pytest.raises(subdiv.InvalidInputError, match="crease 1 refers to vertex 100, but the mesh has 8"):
        cube(creases=[[0, 1], [0, 100]])
    with pytest.raises(subdiv.InvalidInputError, match="hole refers to face 6"):
        cube(holes=[6])
    with pytest.raises(subdiv.InvalidInputError):
        cube(vertex_channels={"color": np.zeros((7, 3))})
    # InvalidInputError is also a ValueError.
    with pytest.raises(ValueError):
        subdiv.Mesh(np.zeros((3, 3)), [[0, 1, 7]])


def test_read_write_round_trip(tmp_path):
    mesh = subdiv.read(TEST_DATA / "tagged_octagon.obj")
    assert mesh.face_count == 8
    np.testing.assert_array_equal(mesh.creases[0], [[0, 1]])
    for name in ("copy.obj", "copy.ply"):
        path = tmp_path / name
        subdiv.write(mesh, path)
        again = subdiv.read(path)
        np.testing.assert_array_equal(again.points, mesh.points)
        np.testing.assert_array_equal(again.faces, mesh.faces)
    np.testing.assert_array_equal(subdiv.read(tmp_path / "copy.obj").creases[0], mesh.creases[0])


def test_gltf_and_stl(tmp_path):
    mesh = subdiv.read(TEST_DATA / "tagged_octagon.obj")
    for name in ("copy.gltf", "copy.glb"):
        subdiv.write(mesh, tmp_path / name)
        again = subdiv.read(tmp_path / name)
        np.testing.assert_array_equal(again.points, mesh.points.astype(np.float32))
        np.testing.assert_array_equal(again.faces, mesh.faces)
        np.testing.assert_array_equal(again.creases[0], mesh.creases[0])
    assert any("no place for tags" in note for note in subdiv.write(mesh, tmp_path / "copy.stl", ascii=True))
    assert subdiv.read(tmp_path / "copy.stl").vertex_count == mesh.vertex_count
    assert subdiv.read(tmp_path / "copy.stl", weld_tolerance=-1).vertex_count == 3 * subdiv.read(
        tmp_path / "copy.stl").face_count


def test_file_errors():
    with pytest.raises(subdiv.IoError) as missing:
        subdiv.read(TEST_DATA / "no_such_file.obj")
    assert "no_such_file.obj" in str(missing.value) and isinstance(missing.value, OSError)
    with pytest.raises(subdiv.ParseError) as garbage:
        subdiv.read(TEST_DATA / "garbage.obj")
    assert garbage.value.line == 3 and garbage.value.path.endswith("garbage.obj")
    assert "garbage.obj:3" in str(garbage.value)
    with pytest.raises(subdiv.InvalidInputError, match="unknown mesh format"):
        subdiv.read(TEST_DATA / "README.md")


def test_validate():
    assert cube().validate() == []
    issues = subdiv.read(TEST_DATA / "nonmanifold_edge.obj").validate()
    assert issues[0][0] == "non-manifold edge" and issues[0][1] == "error"
    assert "shared by 3 faces" in issues[0][3]


def test_pickle_round_trip():
    mesh = subdiv.read(TEST_DATA / "tagged_octagon.obj")
    again = pickle.loads(pickle.dumps(mesh))
    np.testing.assert_array_equal(again.points, mesh.points)
    np.testing.assert_array_equal(again.faces, mesh.faces)
    np.testing.assert_array_equal(again.creases[0], mesh.creases[0])
    np.testing.assert_array_equal(again.corners[0], mesh.corners[0])
    irrational = cube()
    irrational.points[:] *= np.pi
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(irrational)).points, irrational.points)
    with pytest.raises(subdiv.InvalidInputError, match="pickle"):
        pickle.dumps(cube(vertex_channels={"pressure": np.zeros((8, 1))}))


def test_bundled_meshes_read():
    for path in sorted(MESHES.glob("*.obj")):
        mesh = subdiv.read(path)
        assert mesh.vertex_count > 0 and mesh.face_count > 0, path
