"""The build step of `pip install .` (pyproject.toml): the project's CMake builds the compiled module
eccd._eccd (target eccd_python) and the program eccd, which go into the package (eccd/bin/eccd, run by the
console script `eccd`).

Where: the CMake build folder is build-pip/ in the source tree (ECCD_PIP_BUILD_DIR to choose another), one
level below the root like build/, so that ccache (base_dir above the tree) reuses the objects of a CMake
build of the same sources; ccache is used when it is installed. Only the two targets are built: no tests,
no benchmarks. Environment: ECCD_PIP_PROGRAM=0 leaves the program out; CMAKE_BUILD_PARALLEL_LEVEL the jobs
(default: the machine's cores); ECCD_CMAKE_ARGS more configure arguments (split on spaces), e.g.
-DECCD_WERROR=ON (warnings as errors: scripts/run-tests.sh; the default is OFF at every configure, so the
setting does not stay in build-pip/'s cache).
"""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        m = re.search(r"project\(\s*eccd\s+VERSION\s+([0-9][0-9.]*)", f.read())
    if not m:
        raise RuntimeError("CMakeLists.txt: no `project(eccd VERSION x.y.z ...)`: the package has no version")
    return m.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.abspath(os.environ.get("ECCD_PIP_BUILD_DIR") or os.path.join(ROOT, "build-pip"))
        configure = ["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                     "-DECCD_INSTALL=OFF", "-DECCD_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}",
                     "-DECCD_WERROR=OFF"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        configure += os.environ.get("ECCD_CMAKE_ARGS", "").split()
        with_program = os.environ.get("ECCD_PIP_PROGRAM", "1") != "0"
        configure.append(f"-DECCD_BUILD_PROGRAM={'ON' if with_program else 'OFF'}")
        subprocess.check_call(configure)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 2)
        targets = ["eccd_python"] + (["eccd"] if with_program else [])
        subprocess.check_call(["cmake", "--build", build, "--target", *targets, "-j", jobs])

        package = os.path.join(build, "python", "eccd")
        built = [f for f in os.listdir(package) if f.startswith("_eccd") and f.endswith(".so")]
        if len(built) != 1:
            raise RuntimeError(f"{package}: expected one compiled module _eccd*.so, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)
        if with_program:
            bindir = os.path.join(os.path.dirname(target), "bin")
            os.makedirs(bindir, exist_ok=True)
            shutil.copy2(os.path.join(build, "eccd"), os.path.join(bindir, "eccd"))


setup(
    version=project_version(),
    ext_modules=[Extension("eccd._eccd", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-python"}},
    zip_safe=False,
)
