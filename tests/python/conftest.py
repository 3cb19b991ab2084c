"""Shared fixtures of the Python tests: where the sources, the bundled meshes
and the subdiv program are (ctest sets SUBDIV_SOURCE_DIR and SUBDIV_CLI)."""

import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("SUBDIV_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
MESHES = SOURCE_DIR / "data" / "meshes"
TEST_DATA = SOURCE_DIR / "tests" / "data"


@pytest.fixture
def cli():
    """The subdiv program, or a skip where it is not built."""
    path = os.environ.get("SUBDIV_CLI")
    if not path or not os.path.exists(path):
        pytest.skip("the subdiv program is not built (SUBDIV_CLI unset)")
    return path
