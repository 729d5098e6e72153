"""Builds the sgtllc Python module for `pip install .` by driving the project's CMake build (README "Python").

Only the module's target (sgtllc_python) and the libraries it links are built, for the interpreter that runs
pip, in BUILD (default: build-pip/ beside this file, or $SGTLLC_PIP_BUILD_DIR). A build folder one level below
the source, like make's build/, lets ccache (CCACHE_BASEDIR above the source) reuse the objects of `make build`:
it compiles with the same relative paths.
$SGTLLC_CMAKE_ARGS adds CMake options (e.g. -DSGTLLC_WERROR=ON, to match that build's flags);
$CMAKE_BUILD_PARALLEL_LEVEL sets the jobs (default 2). The wheel holds the module, its type stub sgtllc.pyi beside
it, and the PEP 561 stub package sgtllc-stubs (the same stub, with py.typed) for type checkers that want one.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import setuptools
from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

# pip builds a wheel; setuptools before 70.1 does that with the `wheel` package, which --no-build-isolation does
# not fetch. Say so instead of setuptools' "invalid command 'bdist_wheel'".
try:
    import wheel  # noqa: F401
except ImportError:
    if tuple(int(p) for p in re.findall(r"\d+", setuptools.__version__)[:2]) < (70, 1):
        sys.exit(f"sgtllc: {sys.executable} has setuptools {setuptools.__version__} without the 'wheel' package, "
                 "which pip needs to build the module: install it (Debian: apt-get install python3-wheel, or "
                 "scripts/install-deps.sh) or use an interpreter that has it (Debian's /usr/bin/python3)")

ROOT = Path(__file__).resolve().parent
BUILD = Path(os.environ.get("SGTLLC_PIP_BUILD_DIR") or ROOT / "build-pip").resolve()
BUILD.mkdir(parents=True, exist_ok=True)


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(sgtllc VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if cmake is None:
            sys.exit("sgtllc: cmake not found; run scripts/install-deps.sh (Debian: apt-get install cmake)")
        cmake_dir = BUILD  # one level below the source, as make's build/ (setuptools' folders sit inside it)
        args = [
            cmake, "-S", str(ROOT), "-B", str(cmake_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython_EXECUTABLE={sys.executable}",
            "-DSGTLLC_BUILD_PYTHON=ON", "-DSGTLLC_BUILD_APPS=OFF", "-DSGTLLC_BUILD_TESTS=OFF",
            "-DSGTLLC_BUILD_BENCH=OFF", "-DSGTLLC_BUILD_EXAMPLES=OFF",
        ]
        if shutil.which("ninja") and not (cmake_dir / "CMakeCache.txt").exists():
            args += ["-G", "Ninja"]
        if shutil.which("ccache"):
            args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        args += shlex.split(os.environ.get("SGTLLC_CMAKE_ARGS", ""))
        subprocess.run(args, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run([cmake, "--build", str(cmake_dir), "--target", "sgtllc_python", "-j", jobs], check=True)

        # The module as CMake named it (sgtllc.cpython-311-x86_64-linux-gnu.so), where setuptools wants it.
        built = [p for p in (cmake_dir / "python").glob("sgtllc*" + (".pyd" if os.name == "nt" else ".so"))]
        if len(built) != 1:
            sys.exit(f"sgtllc: expected one built module in {cmake_dir / 'python'}, found {built}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)
        stub = ROOT / "python" / "sgtllc.pyi"
        shutil.copyfile(stub, target.parent / "sgtllc.pyi")
        stubs = target.parent / "sgtllc-stubs"
        stubs.mkdir(exist_ok=True)
        shutil.copyfile(stub, stubs / "__init__.pyi")
        (stubs / "py.typed").write_text("")


setup(
    version=project_version(),
    ext_modules=[Extension("sgtllc", sources=[])],
    packages=[],  # no package discovery: the module is the extension alone (and its stubs, copied in by CMakeBuild)
    py_modules=[],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build folders beside CMake's, not in make's build/.
    options={"build": {"build_base": str(BUILD / "setuptools")}, "egg_info": {"egg_base": str(BUILD)}},
    zip_safe=False,
)
