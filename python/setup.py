"""Builds swarmdesign._core with the repository's CMake (target swarmdesign_python) and puts it
into the package. Environment: SWARMDESIGN_BUILD_DIR reuses a configured build tree (default: a
build folder of its own under this one), CMAKE_BUILD_PARALLEL_LEVEL the jobs."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = Path(os.environ.get("SWARMDESIGN_BUILD_DIR", HERE / "build-cmake")).resolve()
        if not (build / "CMakeCache.txt").exists():
            subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                                   "-DSWARMDESIGN_PYTHON=ON", "-DSWARMDESIGN_TESTS=OFF", "-DSWARMDESIGN_BENCH=OFF",
                                   f"-DPYTHON_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", str(build), "--target", "swarmdesign_python"])
        built = next((build / "python" / "swarmdesign").glob("_core*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(ext_modules=[Extension("swarmdesign._core", sources=[])], cmdclass={"build_ext": CMakeBuild})
