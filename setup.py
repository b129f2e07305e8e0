"""The Python package's build (pyproject.toml): the native module wrenchkit._core by the project's own CMake
build (python/CMakeLists.txt, target wrenchkit_python), the pure-Python files from python/wrenchkit/."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = Path(self.build_temp).resolve() / "cmake"
        config = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                  "-DWRENCHKIT_BUILD_TESTS=OFF", "-DWRENCHKIT_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja"):
            config += ["-G", "Ninja"]
        subprocess.run(config, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "wrenchkit_python", "-j", jobs], check=True)
        built = next((build / "python" / "wrenchkit").glob("_core*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(package_dir={"": "python"}, packages=["wrenchkit"],
      ext_modules=[Extension("wrenchkit._core", sources=[])], cmdclass={"build_ext": CMakeBuild})
