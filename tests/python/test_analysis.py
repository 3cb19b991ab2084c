"""analyze, depth, adaptive and the curve schemes from Python."""

import json
import math
import subprocess

import numpy as np
import pytest

import subdiv
from conftest import MESHES


def test_analyze_equals_the_program(cli):
    for scheme, arguments, keywords in (("loop", ["-k", "3..6"], {"k": range(3, 7)}),
                                        ("catmull-clark", ["-k", "2..4", "--boundary"],
                                         {"k": [2, 3, 4], "configuration": "boundary"})):
        out = subprocess.run([cli, "analyze", "-s", scheme, *arguments, "--json"], check=True, capture_output=True,
                             text=True).stdout
        expected = json.loads(out)
        got = subdiv.analyze(scheme, **keywords)
        assert got["scheme"] == expected["scheme"]
        assert len(got["configurations"]) == len(expected["configurations"])
        for g, e in zip(got["configurations"], expected["configurations"]):
            assert set(g) == set(e)
            assert g["verdict"] == e["verdict"] and g["reason"] == e["reason"]
            np.testing.assert_array_equal(g["limit_mask"], e["limit_mask"])
            np.testing.assert_array_equal(g["tangent_masks"], e["tangent_masks"])
            np.testing.assert_array_equal(g["leading_eigenvalues"],
                                          [complex(v["re"], v["im"]) for v in e["leading_eigenvalues"]])


def test_analyze_loop_valence_five():
    # Loop's beta(5) = (5/8 - (3/8 + cos(72 deg)/4)^2) / 5; each neighbour's
    # limit weight is 1/(3/(8 beta) + 5), the subdominant eigenvalue
    # 3/8 + cos(72 deg)/4.
    a = subdiv.analyze("loop", k=5)["configurations"][0]
    beta = (5 / 8 - (3 / 8 + math.cos(2 * math.pi / 5) / 4) ** 2) / 5
    np.testing.assert_allclose(a["limit_mask"][1:], 1 / (3 / (8 * beta) + 5), atol=1e-14)
    assert a["leading_eigenvalues"].dtype == np.complex128
    np.testing.assert_allclose(a["leading_eigenvalues"][1].real, 3 / 8 + math.cos(2 * math.pi / 5) / 4, atol=1e-12)
    assert a["verdict"] == "C1"


def test_analyze_curve_scheme():
    a = subdiv.analyze("chaikin")
    assert a["curve"] is True
    np.testing.assert_allclose(a["eigenvalues"][:2].real, [1.0, 0.5], atol=1e-12)
    with pytest.raises(subdiv.InvalidInputError, match="curve scheme"):
        subdiv.analyze("chaikin", k=3)


def test_analyze_errors():
    with pytest.raises(subdiv.InvalidInputError, match="configuration='side'"):
        subdiv.analyze("loop", k=5, configuration="side")
    with pytest.raises(subdiv.InvalidInputError, match="k=2"):
        subdiv.analyze("loop", k=2)
    with pytest.raises(subdiv.InvalidInputError, match="quasi-4-8"):
        subdiv.analyze("quasi-4-8", k=5)


def test_depth_and_adaptive():
    mesh = subdiv.read(MESHES / "tetrahedron.obj")
    d = subdiv.depth(mesh, "loop", 1e-3, verify=True)
    assert d["bound"] <= 1e-3
    assert d["verified"]["measured"] <= d["bound"]
    assert d["measure"] == "vertex-to-limit"
    a = subdiv.adaptive(mesh, "loop", 1e-3)
    assert np.all(a.distances <= 1e-3)
    assert a.mesh.face_count <= a.uniform_faces
    assert len(a.source_levels) == a.mesh.vertex_count
    assert a.approximated == 0
    # An interpolating scheme's bound is on the level's linear surface.
    b = subdiv.depth(mesh, "butterfly", 1e-2, verify=True)
    assert b["measure"] == "surface-to-limit"
    assert 0 < b["verified"]["measured"] <= b["bound"]
    # On the sqrt3 split, in levels of two steps (after two the faces nest).
    c = subdiv.depth(mesh, "interpolatory-sqrt3", 1e-2, verify=True)
    assert c["measure"] == "surface-to-limit" and c["steps_per_level"] == 2
    assert 0 < c["verified"]["measured"] <= c["bound"]
    # four-eight walks its two-step quad split.
    e = subdiv.adaptive(subdiv.read(MESHES / "cube.obj"), "four-eight", 1e-2)
    assert e.steps_per_level == 2 and np.all(e.distances <= 1e-2)
    # Interpolating schemes: by their faces' next-level displacements.
    k = subdiv.adaptive(subdiv.read(MESHES / "cube.obj"), "kobbelt", 1e-2)
    assert k.measure == "surface-to-limit"
    assert 0 < k.largest_displacement <= k.displacement_threshold < 1e-2


def test_curves():
    square = [[1, 1], [-1, 1], [-1, -1], [1, -1]]
    # The four-point scheme keeps the corners and puts each edge's new point
    # at (1/2 + 1/16) 2 + 1/16 2 = 1.25 from the centre.
    fine = subdiv.refine_curve(square, "four-point", 1, closed=True)
    assert fine.shape == (8, 2)
    np.testing.assert_allclose(fine[0], [1, 1], atol=1e-15)
    np.testing.assert_allclose(fine[1], [0, 1.25], atol=1e-15)
    chaikin = subdiv.refine_curve(np.array(square, float), "chaikin", 1, closed=True)
    np.testing.assert_allclose(chaikin[0], [0.5, 1], atol=1e-15)
    with pytest.raises(subdiv.InvalidInputError, match="columns"):
        subdiv.refine_curve(np.zeros((4, 4)), "chaikin", 1)
    with pytest.raises(subdiv.InvalidInputError, match="non-finite"):
        subdiv.refine_curve([[0, 0], [np.inf, 1], [2, 2]], "chaikin", 1)
    names = [s["name"] for s in subdiv.curve_schemes()]
    assert {"cubic-bspline", "chaikin", "four-point"} <= set(names)


def test_schemes_describe_the_registry():
    names = [s["name"] for s in subdiv.schemes()]
    assert "catmull-clark" in names and "loop" in names and len(names) == len(set(names))
    loop = next(s for s in subdiv.schemes() if s["name"] == "loop")
    assert loop["needs_triangles"] and not loop["interpolating"] and loop["limit_masks"]
    assert subdiv.scheme("gcc", degree=5)["degree"] == 5
