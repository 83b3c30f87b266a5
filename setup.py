# SPDX-License-Identifier: GPL-3.0-or-later
# Copyright (C) 2026 the pcl_wrap authors
"""Builds the Python package's engine with the project's CMake build, for pip and wheels.

The extension pcl_wrap._core and the library it links (libpcl_wrap) are built in
$PCL_WRAP_PYTHON_BUILD_DIR (default build-python/ beside this file, kept between builds so that a
second install only relinks) and placed in the package, the module finding the library beside
itself. PCL, CGAL and TBB stay the system's.
"""
import glob
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        return re.search(r"project\(pcl_wrap VERSION ([0-9.]+)", f.read()).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.abspath(os.environ.get("PCL_WRAP_PYTHON_BUILD_DIR", os.path.join(ROOT, "build-python")))
        stage = os.path.join(build, "stage")
        configure = ["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                     "-DPCL_WRAP_BUILD_PYTHON=ON", "-DPCL_WRAP_BUILD_APPS=OFF", "-DPCL_WRAP_BUILD_TESTS=OFF",
                     "-DPCL_WRAP_BUILD_BENCH=OFF", "-DPCL_WRAP_BUILD_ROS=OFF",
                     "-DPython3_EXECUTABLE=" + sys.executable, "-DCMAKE_INSTALL_PREFIX=" + stage,
                     "-DPCL_WRAP_PYTHON_INSTALL_DIR=.", "-DCMAKE_INSTALL_LIBDIR=pcl_wrap"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        subprocess.run(configure, check=True, stdout=subprocess.DEVNULL)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", build, "--target", "pcl_wrap_python", "-j", jobs], check=True)
        subprocess.run(["cmake", "--install", build], check=True, stdout=subprocess.DEVNULL)
        target = self.get_ext_fullpath(ext.name)
        package = os.path.dirname(target)
        os.makedirs(package, exist_ok=True)
        modules = glob.glob(os.path.join(stage, "pcl_wrap", "_core*.so"))
        if len(modules) != 1:
            raise RuntimeError("the CMake build made %d modules, not one: %s" % (len(modules), modules))
        shutil.copy2(modules[0], target)
        # The library under its soname (libpcl_wrap.so.MAJOR.MINOR), which the module asks for.
        major_minor = ".".join(project_version().split(".")[:2])
        shutil.copy2(os.path.join(stage, "pcl_wrap", "libpcl_wrap.so." + major_minor), package)


BUILD = os.path.join("build-python", "setuptools")  # setuptools' own files, beside CMake's
os.makedirs(os.path.join(ROOT, BUILD), exist_ok=True)

setup(
    version=project_version(),
    options={"build": {"build_base": BUILD}, "egg_info": {"egg_base": BUILD}},
    packages=["pcl_wrap"],
    package_dir={"": "python"},
    package_data={"pcl_wrap": ["_core.pyi", "py.typed"]},
    ext_modules=[Extension("pcl_wrap._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
