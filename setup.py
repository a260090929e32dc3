"""Builds gsp._gsp with CMake for `pip install --no-build-isolation .` (metadata: pyproject.toml).

The module is the CMake target gsp_python. By default it is built in build/pip (configured
once, for the interpreter running pip); GSP_BUILD_DIR=build reuses the tree scripts/setup.sh
built, so installing after setup compiles nothing new.
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.abspath(os.environ.get("GSP_BUILD_DIR") or os.path.join(ROOT, "build", "pip"))
        if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(["cmake", "-S", ROOT, "-B", build, *generator, "-DCMAKE_BUILD_TYPE=Release",
                                   f"-DPython_EXECUTABLE={sys.executable}", "-DGSP_BUILD_PYTHON=ON",
                                   "-DGSP_BUILD_TESTS=OFF", "-DGSP_WITH_CGAL=OFF"])
        jobs = os.environ.get("GSP_JOBS") or str(os.cpu_count() or 1)
        subprocess.check_call(["cmake", "--build", build, "--target", "gsp_python", "-j", jobs])
        built = glob.glob(os.path.join(build, "python", "gsp", "_gsp*.so"))
        if not built:
            raise RuntimeError(f"the CMake build in {build} made no gsp/_gsp*.so")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[Extension("gsp._gsp", sources=[])], cmdclass={"build_ext": CMakeBuild})
