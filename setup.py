"""Builds the extension `raycast._raycast` with the project's CMake for `pip install .`.

The CMake tree is build/pip/cmake (configured once, Release, only the module's target), or the
already configured tree named by RAYCAST_CMAKE_BUILD_DIR (its `raycast_python` target is built,
a no-op when up to date). RAYCAST_PIP_BUILD_DIR moves setuptools' own scratch files."""
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
SCRATCH = os.environ.get("RAYCAST_PIP_BUILD_DIR", os.path.join(ROOT, "build", "pip"))


class CMakeBuild(build_ext):
    """build_ext that configures (once) and builds the CMake target raycast_python."""

    def build_extension(self, ext):
        tree = os.environ.get("RAYCAST_CMAKE_BUILD_DIR") or os.path.join(SCRATCH, "cmake")
        if not os.path.exists(os.path.join(tree, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(["cmake", "-S", ROOT, "-B", tree, *generator,
                                   "-DCMAKE_BUILD_TYPE=Release", "-DRAYCAST_TESTS=OFF",
                                   "-DRAYCAST_BENCH=OFF", "-DRAYCAST_PYTHON=ON", "-DRAYCAST_UNITY_BUILD=ON",
                                   f"-DPYTHON_EXECUTABLE={sys.executable}"])
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.check_call(["cmake", "--build", tree, "--target", "raycast_python",
                               "--parallel", jobs])
        package = os.path.join(tree, "python", "raycast")
        built = [f for f in os.listdir(package) if f.startswith("_raycast.") and
                 f.endswith((".so", ".pyd"))]
        if len(built) != 1:
            raise RuntimeError(f"expected one _raycast extension in {package}, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)


os.makedirs(SCRATCH, exist_ok=True)
setup(ext_modules=[Extension("raycast._raycast", sources=[])],
      cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": SCRATCH}, "egg_info": {"egg_base": SCRATCH}})
