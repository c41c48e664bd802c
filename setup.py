"""Builds the Python module `capsubot` with the project's CMake build (python/CMakeLists.txt).

pip install --no-build-isolation .   configures and builds in build-pip/ (Release, only the
                                     library and the module), then installs the module and its
                                     type stubs (the package capsubot-stubs).
CAPSUBOT_CMAKE_BUILD_DIR=DIR         uses an existing configured build folder instead (only its
                                     capsubot_python target is built).
"""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = pathlib.Path(__file__).parent.resolve()


class CMakeModule(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("CAPSUBOT_CMAKE_BUILD_DIR")
        build = pathlib.Path(given).resolve() if given else SOURCE / "build-pip"
        if not given:
            subprocess.check_call([
                "cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                "-DCAPSUBOT_BUILD_TESTS=OFF", "-DCAPSUBOT_BUILD_BENCHMARKS=OFF",
                "-DCAPSUBOT_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", str(build), "--target", "capsubot_python",
                               "-j", str(os.cpu_count() or 1)])
        built = sorted((build / "python").glob("capsubot*.so"))
        if not built:
            raise RuntimeError(f"the CMake build in {build} made no python/capsubot*.so")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)
        # The stubs the CMake build put beside the module (python/CMakeLists.txt).
        shutil.copytree(build / "python" / "capsubot-stubs", target.parent / "capsubot-stubs",
                        dirs_exist_ok=True)


setup(ext_modules=[CMakeModule("capsubot")], cmdclass={"build_ext": CMakeBuild})
