"""Builds robowire._robowire from the C++ headers in ../include (pybind11).

The extension has no per-message code: python/src walks the protocols'
std::variant lists and tables at compile time. After the build, the stubs
(robowire/*.pyi) are generated from the built module's schema (stubgen.py).

Environment: ROBOWIRE_PY_WERROR=1 adds -Werror to the strict warning set;
ROBOWIRE_PY_JOBS sets the parallel compile jobs (default 2).
"""
import importlib
import os
import sys
import sysconfig
from pathlib import Path

import pybind11
from pybind11.setup_helpers import ParallelCompile, Pybind11Extension
from setuptools import setup
from setuptools.command.build_ext import build_ext

here = Path(__file__).resolve().parent
root = here.parent
include = root / "include"
if not (include / "robowire").is_dir():
    sys.exit(f"robowire: the C++ headers are not at {include}: build from a checkout of the repository")

flags = ["-Wall", "-Wextra", "-Wpedantic", "-Wconversion", "-Wsign-conversion", "-Wshadow", "-g0", "-O2",
         # pybind11's and Python's headers are not ours: no warnings from them
         "-isystem", pybind11.get_include(), "-isystem", sysconfig.get_paths()["include"]]
if "clang" not in (os.environ.get("CC") or sysconfig.get_config_var("CC") or ""):
    flags.append("-Wno-restrict")  # as tools/CMakeLists.txt: g++ 12's false positive (GCC bug 105329) in the tools library
if os.environ.get("ROBOWIRE_PY_WERROR") == "1":
    flags.append("-Werror")

ParallelCompile("ROBOWIRE_PY_JOBS", default=2).install()

# The tools library (tools/lib, namespace robowire::tools: log reader, output formats, schema, one driver per
# protocol; nlohmann/json, header-only), shared with the command-line tool. ROBOWIRE_TOOLS_LIB: a
# librobowire_tools.a already built by CMake (position independent), linked instead of compiling its sources.
tools = root / "tools" / "lib"
tools_lib = os.environ.get("ROBOWIRE_TOOLS_LIB")
tool_sources = [] if tools_lib else [str(p) for p in sorted(tools.glob("*.cpp"))]

extension = Pybind11Extension(
    "robowire._robowire",
    sorted(str(p.relative_to(here)) for p in (here / "src").glob("*.cpp")) + tool_sources,
    include_dirs=[str(include), str(tools)],
    cxx_std=20,
    extra_compile_args=flags,
    extra_objects=[tools_lib] if tools_lib else [],
    extra_link_args=["-s"],
    # any header changed: rebuild (setuptools compares these with the built module)
    depends=[str(p) for p in sorted((here / "src").glob("*.hpp"))] + [str(p) for p in sorted(tools.glob("*.hpp"))]
    + [str(p) for p in sorted(include.rglob("*.hpp"))],
)


class build_ext_and_stubs(build_ext):
    """build_ext, then robowire/*.pyi from the built module's schema."""

    def run(self):
        super().run()
        package_dir = Path(self.get_ext_fullpath("robowire._robowire")).parent
        sys.path.insert(0, str(here))  # stubgen.py
        sys.path.insert(0, str(package_dir.parent))  # the built package, ahead of the sources here
        try:
            for name in [n for n in sys.modules if n == "robowire" or n.startswith("robowire.")]:
                del sys.modules[name]
            robowire = importlib.import_module("robowire")
            import stubgen
            for path, text in stubgen.stubs(robowire).items():
                (package_dir / path).write_text(text)
                print(f"robowire: wrote {package_dir / path}")
        finally:
            sys.path.remove(str(package_dir.parent))
            sys.path.remove(str(here))


setup(packages=["robowire"], package_data={"robowire": ["py.typed", "*.pyi"]}, include_package_data=False,
      ext_modules=[extension], cmdclass={"build_ext": build_ext_and_stubs})
