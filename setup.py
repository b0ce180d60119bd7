# SPDX-License-Identifier: MIT
"""Builds the compiled module cgogn._cgogn with CMake (the metadata is in
pyproject.toml). pybind11, NumPy, Eigen and oneTBB come from the system:
build with `pip install --no-build-isolation .` (see python/README.md)."""
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
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
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
        subprocess.run(["cmake", "--build", str(build), "--target", "_cgogn", "-j", jobs], check=True)
        built = next((build / "python" / "cgogn").glob("_cgogn*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(ext_modules=[Extension("cgogn._cgogn", sources=[])], cmdclass={"build_ext": CMakeBuild})
