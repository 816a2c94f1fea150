"""Builds the package `pagor` (python/pagor/: pure-Python modules, the stubs of its extension and
py.typed) with its extension `pagor._pagor` built by the project's CMake; setuptools only drives
it.

pip runs this through pyproject.toml's setuptools backend. The extension is configured and built in
the CMake build directory `build-python/` (kept, so a second `pip install` is incremental), with
only the core and the module enabled. Environment:
  PAGOR_BUILD_DIR   a CMake build directory to use instead; when it is already configured (the
                    README's `build/`, say) only its target pagor_python is built, nothing else
  CMAKE_ARGS        more arguments for CMake's configure step
                    (e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
"""
import os
import re
import shlex
import shutil
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
BUILD_DIR = Path(os.environ.get("PAGOR_BUILD_DIR") or ROOT / "build-python").resolve()
SETUPTOOLS_DIR = BUILD_DIR / "setuptools"
SETUPTOOLS_DIR.mkdir(parents=True, exist_ok=True)


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(\s*\w+\s+VERSION\s+([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """Configures (once), builds the target pagor_python and copies the extension into place."""

    def build_extension(self, ext):
        build_dir = BUILD_DIR
        if not (build_dir / "CMakeCache.txt").exists():
            self.spawn(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                        "-DCMAKE_BUILD_TYPE=Release", "-DPAGOR_BUILD_PYTHON=ON",
                        "-DPAGOR_BUILD_APP=OFF", "-DPAGOR_BUILD_STUDIO=OFF",
                        "-DPAGOR_BUILD_TESTS=OFF", "-DPAGOR_BUILD_BENCH=OFF",
                        f"-DPython3_EXECUTABLE={sys.executable}"]
                       + shlex.split(os.environ.get("CMAKE_ARGS", "")))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        self.spawn(["cmake", "--build", str(build_dir), "--target", "pagor_python", "-j", jobs])
        built = build_dir / "python" / "pagor" / ("_pagor" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():
            sys.exit(f"setup.py: {built} was not built: the build directory {build_dir} is "
                     f"configured for another Python than {sys.executable}, or without the "
                     "Python module (see CMake's 'Python module' message)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(
    version=project_version(),
    # The package's Python files and stubs; its C++ sources (python/pagor/pybind/) stay out.
    packages=["pagor"],
    package_dir={"": "python"},
    package_data={"pagor": ["py.typed", "_pagor.pyi"]},
    py_modules=[],
    ext_modules=[Extension("pagor._pagor", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own files go beside CMake's, not into the source tree.
    options={"build": {"build_base": str(SETUPTOOLS_DIR)},
             "egg_info": {"egg_base": str(SETUPTOOLS_DIR)}},
    zip_safe=False,
)
