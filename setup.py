# SPDX-License-Identifier: MIT
"""Builds the compiled module cgogn._cgogn with CMake (the metadata is in
pyproject.toml). pybind11, NumPy, Eigen and oneTBB come from the system:
build with `pip install --no-build-isolation .` (see python/README.md).

With CGOGN_CMAKE_BUILD_DIR set to a configured build folder of the project
(e.g. build/release, with the Python module on), its _cgogn target is built
and packaged instead of configuring and compiling the library once more."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).parent.resolve()


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        reused = os.environ.get("CGOGN_CMAKE_BUILD_DIR")
        if reused:
            build = pathlib.Path(reused)
            if not build.is_absolute():
                build = ROOT / build
            if not (build / "CMakeCache.txt").is_file():
                raise RuntimeError(f"CGOGN_CMAKE_BUILD_DIR={reused} is not a configured CMake build folder")
        else:
            build = pathlib.Path(self.build_temp).resolve() / "cmake"
            self.configure(build)
        subprocess.run(["cmake", "--build", str(build), "--target", "_cgogn", "-j", jobs], check=True)
        built = next((build / "python" / "cgogn").glob("_cgogn*.so"), None)
        if built is None:
            raise RuntimeError(f"{build} built no _cgogn module (is CGOGN_BUILD_PYTHON on there?)")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)

    @staticmethod
    def configure(build):
        subprocess.run(
            [
                "cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja",
                "-DCMAKE_BUILD_TYPE=Release",
                "-DCGOGN_BUILD_TESTS=OFF", "-DCGOGN_BUILD_EXAMPLES=OFF", "-DCGOGN_BUILD_BENCHMARKS=OFF",
                "-DCGOGN_BUILD_TOOLS=OFF", "-DCGOGN_BUILD_PYTHON=ON",
                f"-DPython_EXECUTABLE={sys.executable}",
            ],
            check=True,
        )


setup(ext_modules=[Extension("cgogn._cgogn", sources=[])], cmdclass={"build_ext": CMakeBuild})
