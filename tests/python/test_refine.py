"""Refinement from Python equals the library's through the program, bit for
bit; stencils reproduce it; limits, Ctrl-C and the option errors."""

import subprocess
import threading
import time
import _thread

import numpy as np
import pytest

import subdiv
from conftest import MESHES, TEST_DATA

SMALL_MESHES = ["cube", "tetrahedron", "l_shape", "spot_control_mesh"]
SCHEMES = [s["name"] for s in subdiv.schemes()]


def levels_for(scheme):
    # Two steps, or two of the two-step schemes' quad levels' worth.
    return 2


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("name", SMALL_MESHES)
def test_equals_the_program(cli, tmp_path, scheme, name):
    path = MESHES / f"{name}.obj"
    out = tmp_path / "out.obj"
    done = subprocess.run([cli, "refine", str(path), "-s", scheme, "-l", str(levels_for(scheme)), "-o", str(out),
                           "-q"], capture_output=True, text=True)
    mesh = subdiv.read(path)
    if done.returncode != 0:
        # The program refused: Python refuses too, with the same message
        # (the program adds the file and line, and names its own option
        # where the library's hint names a function).
        with pytest.raises(subdiv.Error) as refused:
            subdiv.refine(mesh, scheme, levels_for(scheme))
        assert str(refused.value).split(" (")[0] in done.stderr, (done.stderr, str(refused.value))
        return
    fine = subdiv.refine(mesh, scheme, levels_for(scheme)).mesh
    expected = subdiv.read(out)  # shortest round-trip decimals: the exact doubles
    np.testing.assert_array_equal(fine.points, expected.points)
    np.testing.assert_array_equal(fine.face_offsets, expected.face_offsets)
    np.testing.assert_array_equal(fine.face_indices, expected.face_indices)


def test_hierarchy_levels_and_origins():
    mesh = subdiv.read(MESHES / "cube.obj")
    h = subdiv.refine(mesh, "catmull-clark", 2, keep="all")
    assert [l.level for l in h.levels] == [0, 1, 2]
    assert [l.mesh.face_count for l in h.levels] == [6, 24, 96]
    assert h.levels[0].origins is None
    kinds, parents = h.levels[1].origins
    # Level 1 of a quad split: 6 face points, 12 edge points, 8 vertex points.
    names = [subdiv.ORIGIN_KINDS[k] for k in kinds]
    assert names.count("face") == 6 and names.count("edge") == 12 and names.count("vertex") == 8
    vertex_children = np.flatnonzero(kinds == subdiv.ORIGIN_KINDS.index("vertex"))
    assert sorted(parents[vertex_children]) == list(range(8))
    last = subdiv.refine(mesh, "catmull-clark", 2)
    assert len(last.levels) == 1 and last.levels[0].level == 2
    np.testing.assert_array_equal(last.mesh.points, h.mesh.points)


def test_moving_points_through_the_view_reposes():
    mesh = subdiv.read(MESHES / "cube.obj")
    before = subdiv.refine(mesh, "catmull-clark", 1).mesh.points.copy()
    mesh.points[:] *= 2.0
    after = subdiv.refine(mesh, "catmull-clark", 1).mesh.points
    np.testing.assert_allclose(after, 2.0 * before, rtol=0, atol=1e-15)


def test_stencils_reproduce_refine():
    mesh = subdiv.read(MESHES / "spot_control_mesh.obj")
    for scheme, levels in (("catmull-clark", 2), ("doo-sabin", 1), ("bilinear", 2)):
        S = subdiv.stencils(mesh, scheme, levels)
        fine = subdiv.refine(mesh, scheme, levels).mesh.points
        assert S.shape == (len(fine), mesh.vertex_count)
        scale = np.abs(mesh.points).max()
        np.testing.assert_allclose(S @ mesh.points, fine, rtol=0, atol=1e-14 * scale)
        # Any pose: the table does not depend on the points.
        moved = mesh.points + np.sin(mesh.points)
        mesh2 = mesh.copy()
        mesh2.points[:] = moved
        np.testing.assert_allclose(S @ moved, subdiv.refine(mesh2, scheme, levels).mesh.points, rtol=0,
                                   atol=1e-13 * np.abs(moved).max())
        np.testing.assert_allclose(np.asarray(S.sum(axis=1)).ravel(), 1.0, atol=1e-12)


def test_limit_of_a_tetrahedron():
    # Loop at valence 3: beta = 3/16, chi = 1/(3/(8 beta) + 3) = 1/5, so the
    # limit of vertex (1,1,1) is 2/5 (1,1,1) + 1/5 (-1,-1,-1) = (0.2, 0.2, 0.2).
    mesh = subdiv.read(MESHES / "tetrahedron.obj")
    result = subdiv.limit(mesh, "loop")
    np.testing.assert_allclose(result.positions[0], [0.2, 0.2, 0.2], atol=1e-15)
    np.testing.assert_allclose(result.normals[0], np.ones(3) / np.sqrt(3), atol=1e-15)
    assert result.sources[0] == "closed_form" and result.approximated == 0
    generic = subdiv.limit(mesh, "loop", route="generic", normals=False)
    assert generic.normals is None and generic.sources[0] == "generic"
    np.testing.assert_allclose(generic.positions, result.positions, atol=1e-12)


def test_limit_equals_the_program(cli, tmp_path):
    path = MESHES / "spot_control_mesh.obj"
    out = tmp_path / "limit.obj"
    subprocess.run([cli, "limit", str(path), "-s", "catmull-clark", "-o", str(out), "-q"], check=True)
    result = subdiv.limit(subdiv.read(path), "catmull-clark")
    np.testing.assert_array_equal(result.positions, subdiv.read(out).points)


def test_scheme_parameters_and_options():
    # (On a tetrahedron the butterfly's wings are the edge's own neighbours,
    # and the tension cancels: a larger triangle mesh shows it.)
    mesh = subdiv.read(MESHES / "elephant.obj")
    plain = subdiv.refine(mesh, "butterfly", 1).mesh.points
    tense = subdiv.refine(mesh, "butterfly", 1, tension=0.0).mesh.points
    assert not np.array_equal(plain, tense)
    with pytest.raises(subdiv.InvalidInputError, match="takes no tension"):
        subdiv.refine(mesh, "loop", 1, tension=0.1)
    with pytest.raises(subdiv.InvalidInputError, match="unknown scheme parameter 'tensoin'"):
        subdiv.refine(mesh, "butterfly", 1, tensoin=0.1)
    with pytest.raises(subdiv.InvalidInputError, match="unknown scheme 'lop'"):
        subdiv.refine(mesh, "lop", 1)
    with pytest.raises(subdiv.InvalidInputError, match="boundary='edges'"):
        subdiv.refine(mesh, "loop", 1, boundary="edges")
    with pytest.raises(subdiv.InvalidInputError, match="levels"):
        subdiv.refine(mesh, "loop", -1)
    cube = subdiv.read(MESHES / "cube.obj")
    with pytest.raises(subdiv.ParameterError):
        subdiv.refine(cube, "kobbelt", 1, tension=-1.0)
    quintic = subdiv.refine(cube, "gcc", 1, degree=5).mesh
    assert quintic.face_count == 24
    with pytest.raises(subdiv.Error):
        subdiv.refine(cube, "gcc", 1, degree=1)


def test_invalid_mesh_raises_validation_error():
    mesh = subdiv.read(TEST_DATA / "nonmanifold_edge.obj")
    with pytest.raises(subdiv.ValidationError) as invalid:
        subdiv.refine(mesh, "loop", 1)
    assert "shared by 3 faces" in str(invalid.value)
    assert invalid.value.issues and isinstance(invalid.value, subdiv.TopologyError)
    with pytest.raises(subdiv.InvalidInputError, match="expected a subdiv.Mesh"):
        subdiv.refine("cube.obj", "loop", 1)


def test_threads_give_the_same_result():
    mesh = subdiv.read(MESHES / "spot_control_mesh.obj")
    one = subdiv.refine(mesh, "catmull-clark", 3, threads=1).mesh.points
    two = subdiv.refine(mesh, "catmull-clark", 3, threads=2).mesh.points
    np.testing.assert_array_equal(one, two)


def test_gil_is_released_while_refining():
    # A Python thread keeps running while another refines: with the GIL held
    # for the whole call it could not count at all during it.
    mesh = subdiv.read(MESHES / "spot_control_mesh.obj")
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    worker = threading.Thread(target=count)
    worker.start()
    time.sleep(0.01)
    start = time.perf_counter()
    subdiv.refine(mesh, "catmull-clark", 6, threads=1, regular_grids=False)
    end = time.perf_counter()
    stop.set()
    worker.join()
    during = [t for t in ticks if start < t < end]
    assert end - start > 0.05, "the refinement was too short to tell"
    assert len(during) >= 5, f"{len(during)} ticks in {end - start:.3f} s of refinement"


def test_ctrl_c_stops_between_levels():
    mesh = subdiv.read(MESHES / "spot_control_mesh.obj")
    start = time.perf_counter()
    subdiv.refine(mesh, "catmull-clark", 5, keep="all", threads=1, regular_grids=False)
    full = time.perf_counter() - start
    timer = threading.Timer(full / 10, _thread.interrupt_main)
    timer.start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        subdiv.refine(mesh, "catmull-clark", 6, keep="all", threads=1, regular_grids=False)
    timer.join()
    # Level 6 alone costs about four times levels 0-5: stopping between
    # levels ends well before the whole refinement would.
    assert time.perf_counter() - start < 3 * full


def test_results_pickle():
    # Results travel to other processes (a distributed engine's workers).
    import pickle

    mesh = subdiv.read(MESHES / "cube.obj")
    h = subdiv.refine(mesh, "catmull-clark", 2, keep="all")
    again = pickle.loads(pickle.dumps(h))
    assert [l.level for l in again.levels] == [0, 1, 2]
    np.testing.assert_array_equal(again.mesh.points, h.mesh.points)
    np.testing.assert_array_equal(again.levels[1].origins[1], h.levels[1].origins[1])
    assert again.levels[0].origins is None
    lim = pickle.loads(pickle.dumps(subdiv.limit(mesh, "catmull-clark")))
    np.testing.assert_array_equal(lim.normals, subdiv.limit(mesh, "catmull-clark").normals)
    original = subdiv.adaptive(mesh, "catmull-clark", 1e-2)
    adaptive = pickle.loads(pickle.dumps(original))
    assert adaptive.mesh.vertex_count == len(adaptive.source_levels) == original.mesh.vertex_count
    np.testing.assert_array_equal(adaptive.mesh.points, original.mesh.points)
    np.testing.assert_array_equal(adaptive.distances, original.distances)


def test_triangle_subdivision_option():
    pyramid = subdiv.Mesh(np.array([[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [1, 1, 1.5]], dtype=float),
                          [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
    plain = subdiv.refine(pyramid, "catmull-clark", 1).mesh.points
    smooth = subdiv.refine(pyramid, "catmull-clark", 1, triangle_subdivision="smooth").mesh.points
    assert not np.array_equal(plain, smooth)
    # The edge point between the triangles (0, 1, 4) and (3, 0, 4): 0.03 on each end, 0.47 on each face point.
    centroid = lambda *v: pyramid.points[list(v)].mean(axis=0)
    expected = 0.03 * (pyramid.points[0] + pyramid.points[4]) + 0.47 * (centroid(0, 1, 4) + centroid(3, 0, 4))
    assert np.isclose(smooth, expected, rtol=0, atol=1e-14).all(axis=1).any()
    with pytest.raises(subdiv.InvalidInputError, match="triangle_subdivision='round'"):
        subdiv.refine(pyramid, "catmull-clark", 1, triangle_subdivision="round")


def test_face_varying_option():
    # Spot's UVs: linear by default, smooth with face_varying="none"; the positions do not change.
    mesh = subdiv.read(MESHES / "spot_control_mesh.obj")
    linear = subdiv.refine(mesh, "catmull-clark", 2).mesh
    smooth = subdiv.refine(mesh, "catmull-clark", 2, face_varying="none").mesh
    np.testing.assert_array_equal(linear.points, smooth.points)
    assert not np.array_equal(linear.face_varying_channels["uv"][0], smooth.face_varying_channels["uv"][0])
    with pytest.raises(subdiv.InvalidInputError, match="face_varying='smooth'"):
        subdiv.refine(mesh, "catmull-clark", 1, face_varying="smooth")


def test_composite_specs():
    # A scheme written as averaging operators: Loop's, spelled out.
    mesh = subdiv.read(MESHES / "tetrahedron.obj")
    spelled = subdiv.refine(mesh, "composite:Tvv4,VdE,EVc(loop),VdE,EVc(loop)", 3).mesh
    native = subdiv.refine(mesh, "loop", 3).mesh
    assert np.array_equal(spelled.faces, native.faces)
    assert np.abs(spelled.points - native.points).max() < 1e-14
    with pytest.raises(subdiv.Error, match="ends on edges; it must end on vertices"):
        subdiv.refine(mesh, "composite:Tvv4,VdE", 1)
