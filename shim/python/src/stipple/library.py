# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Loading libstipple.so.1: where the package looks for it, and what the loaded library offers."""
import collections
import ctypes
import os
import pathlib

from . import _abi
from .errors import ABI_VERSION, INVALID_ARGUMENT, OK, ArgumentError, ArgumentTypeError, StippleError

LIBRARY_NAME = "libstipple.so.1"
ENVIRONMENT_VARIABLE = "STIPPLE_LIBRARY"

Limits = collections.namedtuple("Limits", "max_samples_per_pixel max_values_per_sample max_set_size "
                                          "max_dimensions max_name_length max_sample_index_end")
Limits.__doc__ = """The library's limits (stipple.h): N, k of one dimension, k*N of one dimension, the number of
declared dimensions, a dimension name's length, and first_sample + count of one stream call."""

LIMITS = Limits(_abi.MAX_SAMPLES_PER_PIXEL, _abi.MAX_VALUES_PER_SAMPLE, _abi.MAX_SET_SIZE, _abi.MAX_DIMENSIONS,
                _abi.MAX_NAME_LENGTH, _abi.MAX_SAMPLE_INDEX_END)


def _as_library_file(path, what):
    """An absolute path, so that exactly this file is loaded (a bare or ./-relative name would make the system
    loader search its own places): a file is used as given; a folder is searched for libstipple.so.1 (directly
    or in its lib/)."""
    text = os.fspath(path)
    if isinstance(text, bytes):
        text = os.fsdecode(text)
    if not text:
        raise ArgumentError(INVALID_ARGUMENT, f"{what} is an empty path; expected the library file or its folder")
    path = pathlib.Path(os.path.abspath(text))
    if path.is_dir():
        for candidate in (path / LIBRARY_NAME, path / "lib" / LIBRARY_NAME):
            if candidate.is_file():
                return candidate
        return path / LIBRARY_NAME
    return path


def _bundled_candidates():
    """The copy of the library a pip install carries (shim/python/setup.py puts the one it was built against
    into stipple/_lib/)."""
    bundled = pathlib.Path(__file__).resolve().parent / "_lib" / LIBRARY_NAME
    return [bundled] if bundled.is_file() else []


def _installed_candidates():
    """Beside an installed package: `cmake --install` writes _install_location.py with the library's folder
    relative to the package's."""
    try:
        from . import _install_location
    except ImportError:
        return []
    return [pathlib.Path(os.path.normpath(pathlib.Path(__file__).resolve().parent / _install_location.LIBRARY_DIR /
                                          LIBRARY_NAME))]


def _build_tree_candidates():
    """Imported from a source checkout (shim/python/src/stipple): the checkout's build/<preset>/lib, release
    first."""
    package = pathlib.Path(__file__).resolve().parent
    if package.parent.name != "src" or package.parents[2].name != "shim":
        return []
    build = package.parents[3] / "build"
    presets = sorted(build.glob("*/lib/" + LIBRARY_NAME), key=lambda p: (p.parts[-3] != "release", str(p)))
    return presets


def search_path():
    """The places Library() tries, in order, as (what, path) pairs: the STIPPLE_LIBRARY environment variable
    (when set, even to an empty string, nothing else), the copy a pip install carries, the installed prefix, the source checkout's build tree, and the system loader's own search (LD_LIBRARY_PATH,
    the ldconfig cache) by name."""
    places = []
    if ENVIRONMENT_VARIABLE in os.environ:
        return [(f"${ENVIRONMENT_VARIABLE}", _as_library_file(os.environ[ENVIRONMENT_VARIABLE],
                                                              f"${ENVIRONMENT_VARIABLE}"))]
    places += [("bundled with the package", p) for p in _bundled_candidates()]
    places += [("installed prefix", p) for p in _installed_candidates()]
    places += [("build tree", p) for p in _build_tree_candidates()]
    places.append(("system loader", pathlib.Path(LIBRARY_NAME)))
    return places


class Library:
    """libstipple.so.1 loaded through ctypes.

    Library(path=None): path (str | os.PathLike | None) is the library file or a folder holding it (or its lib/).
    A given path is loaded exactly (never looked up by the system loader). Without a path the package tries, in
    order: $STIPPLE_LIBRARY (a file or folder; when set, nothing else), the copy of the library a pip install
    carries, the prefix it was installed into by `cmake --install`, the build tree of the source checkout it is
    imported from (build/release/lib first), and the system loader's search for libstipple.so.1. Raises LibraryError (an
    OSError; status None) naming every place tried when none loads, and LibraryError(ABI_VERSION) for a library
    older than 1.1.

    Attributes:
        path (str): the file loaded (or the bare name, when the system loader found it).
        version (tuple[int, int, int]): the library's major, minor, patch.
        patterns (tuple[str, ...]): every pattern the library offers, in the order of its numbers.
        limits (Limits): N, k, k*N, dimension and stream limits.
    """

    def __init__(self, path=None):
        self._cdll = None
        if path is not None:
            if not isinstance(path, (str, bytes, os.PathLike)):
                raise ArgumentTypeError(INVALID_ARGUMENT, f"path is {path!r} ({type(path).__name__}); expected a "
                                                          "str or os.PathLike naming the library or its folder")
            places = [("argument", _as_library_file(path, "path"))]
        else:
            places = search_path()
        failures = []
        for what, candidate in places:
            name = str(candidate)
            if candidate.parent != pathlib.Path(".") and not candidate.is_file():
                failures.append(f"{what}: {name} (no such file)")
                continue
            try:
                self._cdll = ctypes.CDLL(name, mode=ctypes.RTLD_LOCAL)
                self.path = name
                break
            except OSError as e:
                failures.append(f"{what}: {e}")
        if self._cdll is None:
            raise StippleError(None, f"cannot load {LIBRARY_NAME}; tried " + "; ".join(failures) +
                               f". Pass Library(path) or set {ENVIRONMENT_VARIABLE} to the library file or its folder")
        try:
            _abi.bind(self._cdll)
        except AttributeError as e:
            raise StippleError(ABI_VERSION, f"{self.path} is not a libstipple of ABI 1.1 or later ({e})") from None
        major, minor, patch = _abi.u32(), _abi.u32(), _abi.u32()
        self.check(self._cdll.stipple_get_version(ctypes.byref(major), ctypes.byref(minor), ctypes.byref(patch)))
        self.version = (major.value, minor.value, patch.value)
        if major.value != _abi.ABI_MAJOR or minor.value < _abi.ABI_MINOR:
            raise StippleError(ABI_VERSION, f"{self.path} is libstipple {'.'.join(map(str, self.version))}; "
                                            f"this package needs ABI {_abi.ABI_MAJOR}.{_abi.ABI_MINOR} or later "
                                            f"within major version {_abi.ABI_MAJOR}")
        self.patterns = self._pattern_names()
        self.limits = LIMITS

    def _pattern_names(self):
        # Pattern numbers are dense from 0: probe until the library refuses one. (A pattern-count query in a
        # later ABI minor would replace the probe.)
        names = []
        name = ctypes.c_char_p()
        while self._cdll.stipple_pattern_name(len(names), ctypes.byref(name)) == OK:
            names.append(name.value.decode())
        return tuple(names)

    def check(self, status):
        """Raises StippleError with the calling thread's library message when status is not OK."""
        if status != OK:
            raise StippleError(status, self._cdll.stipple_last_error_message().decode(errors="replace"))

    def sampler(self, pattern, samples_per_pixel, seed=0, *, blue_noise=False, layout=None):
        """A Sampler (see stipple.Sampler for the arguments)."""
        from .sampler import Sampler
        return Sampler(self, pattern, samples_per_pixel, seed, blue_noise=blue_noise, layout=layout)

    def __repr__(self):
        return f"stipple.Library({self.path!r}, version {'.'.join(map(str, self.version))})"
