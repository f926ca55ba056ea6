"""Installs the mkbool package: builds the extension _mkbool with the project's own CMake
build (the repository one folder up) and puts it beside the Python files.

Offline, from Debian's python3-setuptools and python3-wheel:

    pip install --no-build-isolation ./python

MKBOOL_CMAKE_BUILD_DIR=DIR reuses an existing build of the repository (for example
``build``, after ``cmake --build build``; a relative path is taken from the repository
root, because pip runs this script in its own folder): only the target _mkbool is brought
up to date there. Otherwise the repository is configured in a build folder of its own (Release, no
tests), for the interpreter running this script.
"""

import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("MKBOOL_CMAKE_BUILD_DIR")
        if given:
            build_dir = pathlib.Path(given)
            build_dir = (build_dir if build_dir.is_absolute() else ROOT / build_dir).resolve()
            if not (build_dir / "CMakeCache.txt").exists():
                raise RuntimeError(f"MKBOOL_CMAKE_BUILD_DIR={given}: no CMake build there")
        else:
            build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
            build_dir.mkdir(parents=True, exist_ok=True)
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.run(
                ["cmake", "-S", str(ROOT), "-B", str(build_dir), *generator,
                 "-DCMAKE_BUILD_TYPE=Release", "-DMK_BUILD_TESTS=OFF", "-DMK_PYTHON=ON",
                 f"-DPython_EXECUTABLE={sys.executable}"],
                check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_mkbool", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build_dir / "python" / "mkbool" / f"_mkbool{suffix}"
        if not built.exists():
            raise RuntimeError(f"{built} was not built: was {build_dir} configured for another Python "
                               f"(this one is {sys.executable})?")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    name="mkbool",
    version="0.2.0",
    description="Exact Boolean operations on polygons (Margalit & Knott 1989) and a robustness harness",
    packages=["mkbool"],
    package_dir={"mkbool": "mkbool"},
    ext_modules=[Extension("mkbool._mkbool", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
)
