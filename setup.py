"""Builds the Python module `capsubot` with the project's CMake build (python/CMakeLists.txt).

pip install --no-build-isolation .   configures and builds in a temporary folder (Release, only
                                     the library and the module), installs the module and its
                                     type stubs (the package capsubot-stubs), and removes the
                                     folder: the source folder is left as it was (setuptools'
                                     own build and egg-info folders go to temporary folders too).
CAPSUBOT_CMAKE_BUILD_DIR=DIR         uses an existing configured build folder instead (only the
                                     targets asked for are built, and the folder is kept).
CAPSUBOT_PIP_CLI=1                   also builds the command-line program and installs it as the
                                     environment's `capsubot` command.
CMake's configure and build output goes to the terminal (/dev/tty) when there is one, so that
a build of a few minutes shows its progress although pip hides a backend's output; without a
terminal it goes to pip's log (shown with `pip install -v`).
"""
import contextlib
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from distutils.command.build_scripts import build_scripts  # setuptools provides distutils

SOURCE = pathlib.Path(__file__).parent.resolve()
# setuptools' build and egg-info folders: outside the source folder.
SCRATCH = pathlib.Path(tempfile.mkdtemp(prefix="capsubot-setuptools-"))


@contextlib.contextmanager
def progress_stream():
    """The terminal if there is one, else the standard error pip logs."""
    try:
        tty = open("/dev/tty", "w")
    except OSError:
        yield sys.stderr
        return
    with tty:
        yield tty


class CMakeModule(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("CAPSUBOT_CMAKE_BUILD_DIR")
        build = pathlib.Path(given).resolve() if given else SCRATCH / "cmake"
        cli = os.environ.get("CAPSUBOT_PIP_CLI", "") not in ("", "0")
        targets = ["capsubot_python"] + (["capsubot_cli"] if cli else [])
        with progress_stream() as out:
            def run(args, what):
                print(f"capsubot: {what}", file=out, flush=True)
                subprocess.check_call(args, stdout=out, stderr=subprocess.STDOUT)

            if not given:
                run(["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DCAPSUBOT_BUILD_TESTS=OFF", "-DCAPSUBOT_BUILD_BENCHMARKS=OFF",
                     "-DCAPSUBOT_PYTHON=ON", f"-DCAPSUBOT_BUILD_CLI={'ON' if cli else 'OFF'}",
                     f"-DPython_EXECUTABLE={sys.executable}"],
                    f"configuring the CMake build in {build}")
            run(["cmake", "--build", str(build), "--target", *targets, "-j",
                 str(os.cpu_count() or 1)], f"building {' and '.join(targets)} (a few minutes)")
        built = sorted((build / "python").glob("capsubot*.so"))
        if not built:
            raise RuntimeError(f"the CMake build in {build} made no python/capsubot*.so")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)
        # The stubs the CMake build put beside the module (python/CMakeLists.txt).
        shutil.copytree(build / "python" / "capsubot-stubs", target.parent / "capsubot-stubs",
                        dirs_exist_ok=True)
        if cli:
            # build_scripts runs after build_ext and copies the scripts listed by then: the
            # program, installed into the environment's bin/.
            program = SCRATCH / "scripts" / "capsubot"
            program.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(build / "capsubot", program)
            self.distribution.scripts = [str(program)]


class CopyPrograms(build_scripts):
    """Copies the scripts as they are: the program is a compiled file, not Python text."""

    def run(self):
        os.makedirs(self.build_dir, exist_ok=True)
        for script in self.scripts or []:
            shutil.copy2(script, os.path.join(self.build_dir, os.path.basename(script)))


try:
    setup(ext_modules=[CMakeModule("capsubot")],
          cmdclass={"build_ext": CMakeBuild, "build_scripts": CopyPrograms},
          scripts=[],
          options={"build": {"build_base": str(SCRATCH / "build")},
                   "egg_info": {"egg_base": str(SCRATCH)}})
finally:
    shutil.rmtree(SCRATCH, ignore_errors=True)
