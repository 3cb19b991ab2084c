"""pip's entry to the Python module (see pyproject.toml): CMake configures
the project with the Python module alone, builds the extension, and the
package python/subdiv is installed around it."""

import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = re.search(r"project\(subdiv VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class CMakeBuild(build_ext):
    """Builds subdiv._subdiv with the project's CMake instead of setuptools' compiler."""

    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                        "-DSUBDIV_BUILD_PYTHON=ON", "-DSUBDIV_BUILD_TOOLS=OFF", "-DSUBDIV_BUILD_TESTS=OFF",
                        "-DSUBDIV_BUILD_BENCHMARKS=OFF", "-DSUBDIV_BUILD_EXAMPLES=OFF", "-DSUBDIV_INSTALL=OFF",
                        f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "subdiv_python", "--parallel",
                        str(os.cpu_count() or 1)], check=True)
        built = next((build / "python" / "subdiv").glob("_subdiv*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(
    version=VERSION,
    packages=["subdiv"],
    package_dir={"subdiv": "python/subdiv"},
    package_data={"subdiv": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("subdiv._subdiv", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Beside the project's own build/ (CMake's), not inside it.
    options={"build": {"build_base": "build-python"}},
)
