# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""A sampler: pattern, N samples per pixel, seed, optional blue noise and declared layout; NumPy arrays out."""
import contextlib
import ctypes
import threading
import warnings

import numpy as np

from . import _abi
from ._integers import UINT32_MAX, in_range, pixel, uint32, uint64
from .errors import INVALID_ARGUMENT, OUT_OF_MEMORY, OUT_OF_RANGE, ArgumentTypeError, StippleError

# Poisson-disk sets are generated once per (k*N, arity) and cached in the process; the first call at a large
# set size pays for it (poisson, CPU seconds of the first 2D call: 0.6 at 2^16 points, 2.4 at 2^18, about 12 at
# 2^20).
EXPENSIVE_POISSON_SET = 1 << 18
_POISSON_PATTERNS = ("poisson", "poisson-seed")


class CostWarning(UserWarning):
    """Issued when a sampler's first call will take seconds (a large Poisson-disk set to generate)."""


def _float_array(shape):
    try:
        return np.empty(shape, dtype=np.float32)
    except MemoryError:
        raise StippleError(OUT_OF_MEMORY, f"cannot allocate a float32 array of shape {shape}") from None


def _address(array, offset_floats=0):
    return array.ctypes.data + 4 * offset_floats


def _pixel_array(pixels):
    """pixels (array-like of shape (P, 2) or (2,)) as two uint32 columns, or StippleError."""
    try:
        p = np.asarray(pixels)
    except (ValueError, TypeError) as e:
        raise StippleError(INVALID_ARGUMENT, f"pixels cannot be read as an array ({e})") from None
    if p.ndim == 1:
        p = p.reshape(1, -1)
    if p.ndim != 2 or p.shape[1] != 2:
        raise StippleError(INVALID_ARGUMENT, f"pixels has shape {p.shape}; expected (P, 2): one (x, y) per row")
    if p.dtype.kind not in "iu":
        raise ArgumentTypeError(INVALID_ARGUMENT, f"pixels has dtype {p.dtype}; expected integers")
    if p.size:
        low, high = int(p.min()), int(p.max())
        if low < -(2**31) or high > UINT32_MAX:
            raise StippleError(OUT_OF_RANGE, f"pixels hold {low if low < -(2**31) else high}; expected "
                                                    "-2^31..2^32-1 (a pixel coordinate, int32 or uint32)")
    return (p.astype(np.int64) & UINT32_MAX).astype(np.uint32)


class Sampler:
    """Deterministic sample streams of one pattern (see stipple.h for the semantics).

    Sampler(library, pattern, samples_per_pixel, seed=0, *, blue_noise=False, layout=None)
        library (Library); pattern (str): one of library.patterns, optionally spelt "<pattern>+blue-noise" as the
        other front ends do; samples_per_pixel (int): N, 1..library.limits.max_samples_per_pixel; seed (int):
        0..2^64-1; blue_noise (bool): screen-space blue noise over 64 x 64 pixel tiles; layout (None | list of
        (arity, count[, name])): declared dimensions for fill_pixel / sample; streams need none.

    Every value is a float32 in [0, 1) and a pure function of (seed, pixel, sample index, dimension, value
    index). Pixel coordinates are -2^31..2^32-1 (negative ones as the C ABI's two's complement). Every integer
    is checked against its C type and the library's limits before the call; every failure raises StippleError.
    Poisson patterns generate each set size once per process: the first call at k*N >= 2^18 takes seconds
    (2.4 s of CPU at 2^18, about 12 s at 2^20), and creating such a sampler issues a CostWarning. Close with
    close() or a with-block (or let it go).
    """

    def __init__(self, library, pattern, samples_per_pixel, seed=0, *, blue_noise=False, layout=None):
        self._handle = None  # first: __del__ after a failed constructor has nothing to release
        self._lease_changed = threading.Condition()  # guards _handle and _in_flight: close() waits for calls
        self._in_flight = 0
        self._library = library
        cdll = library._cdll
        if not isinstance(pattern, str):
            raise ArgumentTypeError(INVALID_ARGUMENT, f"pattern is {pattern!r}; expected one of {library.patterns}")
        if not isinstance(blue_noise, (bool, np.bool_)):
            raise ArgumentTypeError(INVALID_ARGUMENT, f"blue_noise is {blue_noise!r}; expected True or False")
        n = in_range(samples_per_pixel, "samples_per_pixel", 1, library.limits.max_samples_per_pixel)
        seed = uint64(seed, "seed")
        layout = [] if layout is None else list(layout)
        if len(layout) > library.limits.max_dimensions:
            raise StippleError(OUT_OF_RANGE, f"layout has {len(layout)} dimensions; expected at most "
                                                    f"{library.limits.max_dimensions}")
        # "<pattern>+blue-noise" is the tools' spelling of blue_noise=True (stipple_pattern_parse, ABI 1.2).
        pattern_id, name_flags = _abi.u32(), _abi.u32(0)
        if hasattr(cdll, "stipple_pattern_parse"):
            library.check(cdll.stipple_pattern_parse(pattern.encode(), ctypes.byref(pattern_id),
                                                     ctypes.byref(name_flags)))
        else:
            library.check(cdll.stipple_pattern_from_name(pattern.encode(), ctypes.byref(pattern_id)))
        dims = (_abi.DimensionDesc * max(1, len(layout)))()
        largest_set = n
        for d, entry in enumerate(layout):
            if isinstance(entry, (str, bytes)) or not 2 <= len(entry) <= 3:
                raise StippleError(INVALID_ARGUMENT, f"layout[{d}] is {entry!r}; expected (arity, count[, name])")
            arity = uint32(entry[0], f"layout[{d}] arity")
            count = uint32(entry[1], f"layout[{d}] count")
            name = entry[2] if len(entry) > 2 else None
            if name is not None and not isinstance(name, str):
                raise ArgumentTypeError(INVALID_ARGUMENT, f"layout[{d}] name is {name!r}; expected a str or None")
            dims[d] = _abi.DimensionDesc(ctypes.sizeof(_abi.DimensionDesc), arity, count, 0,
                                         None if name is None else name.encode())
            largest_set = max(largest_set, n * count)
        flags = name_flags.value | (_abi.PATTERN_FLAG_BLUE_NOISE if blue_noise else 0)
        desc = _abi.SamplerDesc(ctypes.sizeof(_abi.SamplerDesc), pattern_id.value, n, len(layout), seed,
                                dims if layout else None, flags, 0)
        handle = _abi.sampler()
        library.check(cdll.stipple_sampler_create(ctypes.byref(desc), ctypes.byref(handle)))
        self._handle = handle
        self._dims = dims  # the library copies the layout; kept only for symmetry of lifetime
        self.pattern, self.samples_per_pixel, self.seed = pattern, n, seed
        self.blue_noise, self.dimension_count = bool(flags & _abi.PATTERN_FLAG_BLUE_NOISE), len(layout)
        if pattern in _POISSON_PATTERNS and largest_set >= EXPENSIVE_POISSON_SET:
            warnings.warn(f"{pattern} with a set of {largest_set} points: the first call generates it "
                          "(seconds; about 12 s of CPU at 2^20 points), later calls reuse it", CostWarning,
                          stacklevel=3)

    # ---- lifetime ----------------------------------------------------------------------------------------------
    def close(self):
        """Releases the library's sampler once every call in flight on other threads has returned; later calls
        raise ArgumentError ("the sampler is closed")."""
        lease_changed = getattr(self, "_lease_changed", None)
        if lease_changed is None:
            return
        with lease_changed:
            handle, self._handle = self._handle, None
            while self._in_flight:
                lease_changed.wait()
        if handle:
            self._library._cdll.stipple_sampler_release(handle)

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @contextlib.contextmanager
    def _lease(self):
        """The handle, kept alive until the block ends: close() on another thread waits for it."""
        with self._lease_changed:
            if not self._handle:
                raise StippleError(INVALID_ARGUMENT, "the sampler is closed")
            self._in_flight += 1
            handle = self._handle
        try:
            yield handle
        finally:
            with self._lease_changed:
                self._in_flight -= 1
                if not self._in_flight:
                    self._lease_changed.notify_all()

    def _call(self, function, *args):
        """function(handle, *args) of the C ABI under a lease; a failed status raises."""
        with self._lease() as handle:
            status = getattr(self._library._cdll, function)(handle, *args)
        self._library.check(status)

    def __repr__(self):
        return (f"stipple.Sampler({self.pattern!r}, samples_per_pixel={self.samples_per_pixel}, seed={self.seed}, "
                f"blue_noise={self.blue_noise}, dimensions={self.dimension_count})")

    # ---- streams (no layout needed) ----------------------------------------------------------------------------
    def _stream_range(self, first_sample, count, arity):
        first = uint32(first_sample, "first_sample")
        count = in_range(count, "count", 1, _abi.MAX_SAMPLE_INDEX_END - first,
                         f"1..2^32 - first_sample = {_abi.MAX_SAMPLE_INDEX_END - first} (first_sample + count <= 2^32)")
        arity = in_range(arity, "arity", 1, 3)
        return first, count, arity

    def stream(self, x, y, sample_index, dimension, arity):
        """One sample of stream (dimension, arity) of pixel (x, y) -> ndarray float32 (arity,).

        x, y (int): pixel; sample_index (int): 0..2^32-1 (index i is position i mod N of block i // N);
        dimension (int): the host's dimension counter, 0..2^32-1; arity (int): 1, 2 or 3."""
        arity = in_range(arity, "arity", 1, 3)
        out = _float_array((arity,))
        self._call("stipple_sampler_stream",
            pixel(x, "x"), pixel(y, "y"), uint32(sample_index, "sample_index"),
            uint32(dimension, "dimension"), arity, _address(out), out.size)
        return out

    def stream_fill(self, x, y, first_sample, count, dimension, arity):
        """Samples first_sample .. first_sample + count - 1 of one stream -> ndarray float32 (count, arity).

        Bitwise equal to count stream() calls. first_sample + count <= 2^32."""
        first, count, arity = self._stream_range(first_sample, count, arity)
        dimension = uint32(dimension, "dimension")
        x, y = pixel(x, "x"), pixel(y, "y")
        out = _float_array((count, arity))
        self._call("stipple_sampler_stream_fill",
            x, y, first, count, dimension, arity, _address(out), out.size)
        return out

    def pixels(self, pixels, dimension=0, arity=2, first_sample=0, count=None):
        """One stream's samples for many pixels in one call -> ndarray float32 (P, count, arity).

        pixels (array-like of int, shape (P, 2) or (2,)): one (x, y) per row; dimension (int): the stream's
        index; arity (int): 1, 2 or 3; first_sample (int), count (int | None: N): the samples, as stream_fill.
        Row p equals stream_fill(*pixels[p], first_sample, count, dimension, arity)."""
        xy = _pixel_array(pixels)
        first, count, arity = self._stream_range(first_sample, self.samples_per_pixel if count is None else count,
                                                 arity)
        dimension = uint32(dimension, "dimension")
        out = _float_array((len(xy), count, arity))
        # One C call per pixel into the one output array (a many-pixel call in the ABI would remove the loop).
        fill, check = self._library._cdll.stipple_sampler_stream_fill, self._library.check
        per_pixel, base, status = count * arity, out.ctypes.data, 0
        with self._lease() as handle:
            for p, (x, y) in enumerate(xy.tolist()):
                status = fill(handle, x, y, first, count, dimension, arity, base + 4 * p * per_pixel, per_pixel)
                if status:
                    break
        if status:
            check(status)
        return out

    # ---- declared layout ---------------------------------------------------------------------------------------
    def dimension_info(self, dimension):
        """A declared dimension -> dict(arity=int, count=int (k), floats_per_pixel=int, name=str,
        strata=tuple[int, int, int])."""
        info = _abi.DimensionInfo()
        info.struct_size = ctypes.sizeof(_abi.DimensionInfo)
        self._call("stipple_sampler_get_dimension_info",
            uint32(dimension, "dimension"), ctypes.byref(info))
        return {"arity": info.arity, "count": info.count, "floats_per_pixel": info.floats_per_pixel,
                "name": (info.name or b"").decode(), "strata": tuple(info.strata)}

    def find_dimension(self, name):
        """The index (int) of the first declared dimension called name (str)."""
        if not isinstance(name, str):
            raise ArgumentTypeError(INVALID_ARGUMENT, f"name is {name!r}; expected a str")
        index = _abi.u32()
        self._call("stipple_sampler_find_dimension",
            name.encode(), ctypes.byref(index))
        return index.value

    def fill_pixel(self, x, y, dimension):
        """All N samples of a declared dimension for pixel (x, y) -> ndarray float32 (N, k, arity)."""
        info = self.dimension_info(dimension)
        out = _float_array((self.samples_per_pixel, info["count"], info["arity"]))
        self._call("stipple_sampler_fill_pixel",
            pixel(x, "x"), pixel(y, "y"), uint32(dimension, "dimension"), _address(out), out.size)
        return out

    def sample(self, x, y, sample_index, dimension):
        """One sample (any index, 0..2^32-1) of a declared dimension -> ndarray float32 (k, arity)."""
        info = self.dimension_info(dimension)
        out = _float_array((info["count"], info["arity"]))
        self._call("stipple_sampler_sample",
            pixel(x, "x"), pixel(y, "y"), uint32(sample_index, "sample_index"),
            uint32(dimension, "dimension"), _address(out), out.size)
        return out

    def sample_independent(self, x, y, sample_index, stream, count):
        """count independent uniform values for (pixel, sample index, stream) -> ndarray float32 (count,): values
        past the declared layout (never stratified). count is 1..2^32-1."""
        count = in_range(count, "count", 1, UINT32_MAX)
        out = _float_array((count,))
        self._call("stipple_sampler_sample_independent",
            pixel(x, "x"), pixel(y, "y"), uint32(sample_index, "sample_index"),
            uint32(stream, "stream"), _address(out), out.size)
        return out
