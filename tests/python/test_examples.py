"""The Python examples run and print what they promise."""

import subprocess
import sys

from conftest import MESHES, SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run(name, *arguments):
    done = subprocess.run([sys.executable, str(EXAMPLES / name), *map(str, arguments)], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_compare_schemes(tmp_path):
    out = run("compare_schemes.py", MESHES / "cube.obj", tmp_path / "cube")
    assert "catmull-clark" in out and "    386 vertices     384 faces" in out  # 6 * 4^3 faces, V = F + 2
    assert "loop" in out and "refused" in out
    assert (tmp_path / "cube_catmull-clark.obj").exists()


def test_animate_with_stencils():
    out = run("animate_with_stencils.py", MESHES / "spot_control_mesh.obj")
    assert out.count("largest difference from refining again") == 3


def test_spectrum_table():
    out = run("spectrum_table.py", "loop")
    # Loop at valence 6: lambda_1 = 3/8 + cos(60 deg)/4 = 0.5.
    assert "   6   0.500000   0.500000" in out


def test_depth_for_accuracy():
    out = run("depth_for_accuracy.py", MESHES / "tetrahedron.obj", "loop", 1e-3)
    assert "a priori depth" in out and "adaptive:" in out


def test_refine_folder_with_dask(tmp_path):
    # Two worker processes: meshes go out and hierarchies come back pickled;
    # a scheme's refusal comes back as the library's exception.
    import numpy as np
    import subdiv

    out = run("refine_folder_with_dask.py", MESHES, "loop", 1, tmp_path)
    assert "cube.obj: refused: loop needs a triangle mesh" in out
    for name in ("tetrahedron", "elephant"):
        remote = subdiv.read(tmp_path / f"{name}_loop1.obj")
        local = subdiv.refine(subdiv.read(MESHES / f"{name}.obj"), "loop", 1).mesh
        np.testing.assert_array_equal(remote.points, local.points)
        np.testing.assert_array_equal(remote.face_indices, local.face_indices)
