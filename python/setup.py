# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Builds the extension mdcs._mdcs with CMake (the repository's own CMakeLists.txt, target mdcs_python_module)
for pip; the metadata is in pyproject.toml. Environment: MDCS_BUILD_JOBS (parallel compile jobs, default 2),
MDCS_CMAKE_ARGS (more arguments for the configure step)."""

import os
import re
import shlex
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)  # the repository: CMakeLists.txt, include/, cmake/


def version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        match = re.search(r"project\(MDCS VERSION ([0-9.]+)", f.read())
    return match.group(1) if match else "0.0.0"


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if not os.path.exists(os.path.join(ROOT, "include", "CGAL", "Polyhedral_geodesics_3.h")):
            raise RuntimeError("mdcs: build from the MDCS source tree (pip install ./python from the repository root)")
        output = os.path.dirname(os.path.abspath(self.get_ext_fullpath(ext.name)))
        build = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        args = ["-DCMAKE_BUILD_TYPE=Release", "-DMDCS_BUILD_TESTS=OFF", "-DMDCS_BUILD_EXAMPLES=OFF",
                "-DMDCS_BUILD_CLI=OFF", "-DMDCS_BUILD_BENCHMARKS=OFF", "-DMDCS_BUILD_DOC=OFF",
                "-DMDCS_BUILD_PYTHON=ON", f"-DPYTHON_EXECUTABLE={sys.executable}",
                f"-DMDCS_PYTHON_OUTPUT_DIR={output}"]
        try:
            import pybind11

            args.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except (ImportError, AttributeError):
            pass  # Debian's pybind11-dev provides the CMake package
        args += shlex.split(os.environ.get("MDCS_CMAKE_ARGS", ""))
        jobs = os.environ.get("MDCS_BUILD_JOBS", "2")
        subprocess.check_call(["cmake", "-S", ROOT, "-B", build] + args)
        subprocess.check_call(["cmake", "--build", build, "--target", "mdcs_python_module", "-j", jobs])


setup(version=version(), ext_modules=[CMakeExtension("mdcs._mdcs")], cmdclass={"build_ext": CMakeBuild},
      zip_safe=False)
