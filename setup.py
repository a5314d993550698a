"""pip install . : setuptools builds the native module skipnc._skipnc with
CMake (only that target, Release, without the tests) and places it in the
package; the metadata is in pyproject.toml. The version is the CMake
project's, read from CMakeLists.txt: the one place it is written.

Environment:
  SKIPNC_CMAKE_BUILD_DIR  the CMake build folder (default build-pip/ here, kept,
                          so a second install only rebuilds what changed). A
                          folder CMake has already configured (a build tree of
                          scripts/build.sh, say) is used as it is configured:
                          only its _skipnc target is built, its libraries reused.
  SKIPNC_CMAKE_ARGS       more arguments for CMake's configure step.
"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def cmake_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(skipnc VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """build_ext that runs CMake for the `_skipnc` target."""

    def build_extension(self, ext):
        given = os.environ.get("SKIPNC_CMAKE_BUILD_DIR")
        build = pathlib.Path(given or ROOT / "build-pip").resolve()
        configured = (build / "CMakeCache.txt").exists()
        if not (given and configured):
            configure = ["cmake", "-S", str(ROOT), "-B", str(build),
                         "-DCMAKE_BUILD_TYPE=Release", "-DSKIPNC_TESTS=OFF",
                         "-DSKIPNC_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"]
            if shutil.which("ninja") and not configured:
                configure += ["-G", "Ninja"]
            configure += shlex.split(os.environ.get("SKIPNC_CMAKE_ARGS", ""))
            subprocess.check_call(configure)
        subprocess.check_call(["cmake", "--build", str(build), "--target", "_skipnc",
                               "-j", str(os.cpu_count() or 1)])
        built = sorted((build / "python" / "skipnc").glob("_skipnc*.so"))
        if not built:
            raise RuntimeError(f"CMake built no _skipnc module in {build}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    version=cmake_version(),
    ext_modules=[Extension("skipnc._skipnc", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build folders beside CMake's build/, not in it.
    options={"build": {"build_base": "build-pip/setuptools"}},
)
