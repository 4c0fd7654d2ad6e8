"""Builds the extension drillflex._core with the project's CMake build (pyproject.toml has the rest).

The extension is the CMake target drillflex_python, built in the repository's build/ (the directory
scripts/build uses: Release, no tests), so a tree already built by scripts/build only links it again.
CMAKE_BUILD_PARALLEL_LEVEL sets the build's jobs (default: every core); ccache is used when present.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build = ROOT / "build"
        # The interpreter the module is for: in a venv, the one it was made from (the same ABI), so
        # build/ keeps a Python that outlives the venv.
        python = getattr(sys, "_base_executable", sys.executable)
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DDRILLFLEX_BUILD_TESTS=OFF", f"-DPython_EXECUTABLE={python}"]
        if not (build / "CMakeCache.txt").exists() and shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "drillflex_python", "-j", jobs], check=True)
        built = build / "python" / "drillflex" / Path(self.get_ext_filename(ext.name)).name
        if not built.exists():
            raise RuntimeError(f"the CMake build left no {built}: is pybind11-dev installed (scripts/install-deps)?")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(ext_modules=[CMakeExtension("drillflex._core")], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": "build/setuptools"}})
