# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
"""The package carries the libstipple.so.1 it is built against, so an installed package needs no environment
variable: the library named by $STIPPLE_LIBRARY at build time (a file or a folder holding it or its lib/), else the
source checkout's build tree (build/release/lib first, then the other build folders, e.g. the quick start's
build/lib/lib). With none found the package is built without a copy and searches at run time (stipple.Library).
Metadata is in pyproject.toml."""
import os
import pathlib
import shutil

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

LIBRARY_NAME = "libstipple.so.1"
HERE = pathlib.Path(__file__).resolve().parent


def library_to_carry():
    value = os.environ.get("STIPPLE_LIBRARY")
    if value:
        path = pathlib.Path(os.path.abspath(value))
        for candidate in (path, path / LIBRARY_NAME, path / "lib" / LIBRARY_NAME):
            if candidate.is_file():
                return candidate
        raise SystemExit(f"setup.py: $STIPPLE_LIBRARY is {value!r}, which is not {LIBRARY_NAME} or a folder "
                         "holding it")
    build = HERE.parent.parent / "build"
    if HERE.parent.name == "shim" and build.is_dir():
        found = sorted(build.glob("*/lib/" + LIBRARY_NAME), key=lambda p: (p.parts[-3] != "release", str(p)))
        if found:
            return found[0]
    return None


class BuildWithLibrary(build_py):
    def run(self):
        super().run()
        library = library_to_carry()
        if library is None:
            print(f"setup.py: no {LIBRARY_NAME} found (set STIPPLE_LIBRARY or build the library first); the "
                  "package will search for one at run time")
            return
        target = pathlib.Path(self.build_lib) / "stipple" / "_lib"
        target.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(library.resolve(), target / LIBRARY_NAME)  # the file itself, not its symlink
        print(f"setup.py: the package carries {library}")


class PlatformDistribution(Distribution):
    """A wheel with a shared library in it is specific to its platform."""

    def has_ext_modules(self):
        return library_to_carry() is not None


setup(cmdclass={"build_py": BuildWithLibrary}, distclass=PlatformDistribution)
