"""`pip install ./bindings/python` (offline: --no-build-isolation --no-index):
builds libeg2d with CMake from this repository and carries it inside the
package, so `import eg2d` needs neither EG2D_LIBRARY nor an installed library.
The metadata is in pyproject.toml."""
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

HERE = Path(__file__).resolve().parent
SOURCE = HERE.parent.parent  # the repository: bindings/python/../..


class BuildWithLibrary(build_py):
    """The Python files, then libeg2d.so.1 built by CMake next to them."""

    def run(self):
        super().run()
        if not (SOURCE / "include" / "eg2d.h").exists():
            raise SystemExit(f"eg2d: {SOURCE} is not the eg2d repository: install from a checkout")
        with tempfile.TemporaryDirectory() as build:
            flags = ["-DCMAKE_BUILD_TYPE=Release", "-DEG2D_BUILD_EXAMPLES=OFF", "-DEG2D_BUILD_BENCH=OFF",
                     "-DEG2D_BUILD_TOOLS=OFF", "-DEG2D_BUILD_FORTRAN=OFF", "-DBUILD_TESTING=OFF"]
            subprocess.check_call(["cmake", "-S", str(SOURCE), "-B", build, *flags])
            subprocess.check_call(["cmake", "--build", build, "--target", "eg2d", "-j", str(os.cpu_count() or 1)])
            target = Path(self.build_lib) / "eg2d"
            shutil.copy2(Path(build) / "src" / "libeg2d.so.1", target / "libeg2d.so.1")
            # The library sits beside the package's files.
            (target / "_location.py").write_text('LIBDIR_RELATIVE = "."\n')


class BinaryDistribution(Distribution):
    def has_ext_modules(self):  # a platform wheel: it carries a shared library
        return True


setup(cmdclass={"build_py": BuildWithLibrary}, distclass=BinaryDistribution)
