"""stipple_numpy — an importable ctypes binding of libstipple that returns NumPy arrays.

    import stipple_numpy as sn
    lib = sn.Library("path/to/libstipple.so.1")         # or sn.Library() to search the default loader path
    s = lib.sampler("stratified", samples_per_pixel=64, seed=7)          # streams only (ABI 1.1)
    uv = s.stream_fill(x, y, first_sample=0, count=64, dimension=3, arity=2)   # ndarray (64, 2), float32
    s2 = lib.sampler("poisson", 16, 1, layout=[(2, 1, "pixel"), (1, 3, "light")])
    pix = s2.fill_pixel(x, y, s2.find_dimension("light"))              # ndarray (16, 3, 1)

Pixel coordinates may be negative (two's complement, as in the C ABI). Every failing call raises StippleError
with the library's status and message. Arrays are float32 in [0, 1), freshly allocated for each call.
"""
import ctypes

import numpy as np

STIPPLE_OK = 0
_status = ctypes.c_int32
_sampler = ctypes.c_void_p
_u32 = ctypes.c_uint32
_floats = ctypes.POINTER(ctypes.c_float)


class StippleError(RuntimeError):
    def __init__(self, status, message):
        super().__init__(f"libstipple status {status}: {message}")
        self.status = status


class _DimensionDesc(ctypes.Structure):
    _fields_ = [("struct_size", _u32), ("arity", _u32), ("count", _u32), ("reserved", _u32),
                ("name", ctypes.c_char_p)]


class _SamplerDesc(ctypes.Structure):
    _fields_ = [("struct_size", _u32), ("pattern", _u32), ("samples_per_pixel", _u32), ("dimension_count", _u32),
                ("seed", ctypes.c_uint64), ("dimensions", ctypes.POINTER(_DimensionDesc)), ("flags", _u32),
                ("reserved", _u32)]


class _DimensionInfo(ctypes.Structure):
    _fields_ = [("struct_size", _u32), ("arity", _u32), ("count", _u32), ("floats_per_pixel", _u32),
                ("name", ctypes.c_char_p), ("strata", _u32 * 3), ("reserved", _u32)]


def _coordinate(v):
    return ctypes.c_uint32(int(v) & 0xffffffff)


class Library:
    """libstipple.so.1 loaded through ctypes (needs ABI 1.1 for streams)."""

    def __init__(self, path="libstipple.so.1"):
        self._lib = ctypes.CDLL(path)
        lib = self._lib
        lib.stipple_last_error_message.restype = ctypes.c_char_p
        lib.stipple_get_version.argtypes = [ctypes.POINTER(_u32)] * 3
        lib.stipple_pattern_from_name.argtypes = [ctypes.c_char_p, ctypes.POINTER(_u32)]
        lib.stipple_sampler_create.argtypes = [ctypes.POINTER(_SamplerDesc), ctypes.POINTER(_sampler)]
        lib.stipple_sampler_release.argtypes = [_sampler]
        lib.stipple_sampler_get_dimension_info.argtypes = [_sampler, _u32, ctypes.POINTER(_DimensionInfo)]
        lib.stipple_sampler_find_dimension.argtypes = [_sampler, ctypes.c_char_p, ctypes.POINTER(_u32)]
        lib.stipple_sampler_fill_pixel.argtypes = [_sampler, _u32, _u32, _u32, _floats, ctypes.c_size_t]
        lib.stipple_sampler_sample.argtypes = [_sampler, _u32, _u32, _u32, _u32, _floats, ctypes.c_size_t]
        lib.stipple_sampler_stream.argtypes = [_sampler, _u32, _u32, _u32, _u32, _u32, _floats, ctypes.c_size_t]
        lib.stipple_sampler_stream_fill.argtypes = [_sampler, _u32, _u32, _u32, _u32, _u32, _u32, _floats,
                                                    ctypes.c_size_t]
        for name in ("stipple_get_version", "stipple_pattern_from_name", "stipple_sampler_create",
                     "stipple_sampler_release", "stipple_sampler_get_dimension_info", "stipple_sampler_find_dimension",
                     "stipple_sampler_fill_pixel", "stipple_sampler_sample", "stipple_sampler_stream",
                     "stipple_sampler_stream_fill"):
            getattr(lib, name).restype = _status
        major, minor, patch = _u32(), _u32(), _u32()
        self.check(lib.stipple_get_version(ctypes.byref(major), ctypes.byref(minor), ctypes.byref(patch)))
        self.version = (major.value, minor.value, patch.value)
        if self.version < (1, 1, 0):
            raise StippleError(5, f"stipple_numpy needs libstipple ABI 1.1, found {self.version}")

    def check(self, status):
        if status != STIPPLE_OK:
            raise StippleError(status, self._lib.stipple_last_error_message().decode())

    def sampler(self, pattern, samples_per_pixel, seed, layout=None):
        """layout: None (streams only) or a list of (arity, count[, name])."""
        return Sampler(self, pattern, samples_per_pixel, seed, layout or [])


class Sampler:
    def __init__(self, library, pattern, samples_per_pixel, seed, layout):
        self._library, lib = library, library._lib
        pattern_id = _u32()
        library.check(lib.stipple_pattern_from_name(pattern.encode(), ctypes.byref(pattern_id)))
        dims = (_DimensionDesc * max(1, len(layout)))()
        self._names = []
        for d, entry in enumerate(layout):
            arity, count = entry[0], entry[1]
            name = entry[2].encode() if len(entry) > 2 and entry[2] is not None else None
            self._names.append(name)
            dims[d] = _DimensionDesc(ctypes.sizeof(_DimensionDesc), arity, count, 0, name)
        desc = _SamplerDesc(ctypes.sizeof(_SamplerDesc), pattern_id.value, samples_per_pixel, len(layout),
                            seed & 0xffffffffffffffff, dims if layout else None, 0, 0)
        self._handle = _sampler()
        library.check(lib.stipple_sampler_create(ctypes.byref(desc), ctypes.byref(self._handle)))
        self.samples_per_pixel = samples_per_pixel

    def close(self):
        if self._handle:
            self._library._lib.stipple_sampler_release(self._handle)
            self._handle = _sampler()

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @staticmethod
    def _buffer(shape):
        out = np.empty(shape, dtype=np.float32)
        return out, out.ctypes.data_as(_floats), out.size

    def stream(self, x, y, sample_index, dimension, arity):
        """One value of stream (dimension, arity): ndarray (arity,)."""
        out, ptr, n = self._buffer((arity,))
        self._library.check(self._library._lib.stipple_sampler_stream(
            self._handle, _coordinate(x), _coordinate(y), sample_index, dimension, arity, ptr, n))
        return out

    def stream_fill(self, x, y, first_sample, count, dimension, arity):
        """Samples [first_sample, first_sample + count) of one stream: ndarray (count, arity)."""
        out, ptr, n = self._buffer((count, arity))
        self._library.check(self._library._lib.stipple_sampler_stream_fill(
            self._handle, _coordinate(x), _coordinate(y), first_sample, count, dimension, arity, ptr, n))
        return out

    def _info(self, dimension):
        info = _DimensionInfo()
        info.struct_size = ctypes.sizeof(_DimensionInfo)
        self._library.check(self._library._lib.stipple_sampler_get_dimension_info(
            self._handle, dimension, ctypes.byref(info)))
        return info

    def find_dimension(self, name):
        index = _u32()
        self._library.check(self._library._lib.stipple_sampler_find_dimension(
            self._handle, name.encode(), ctypes.byref(index)))
        return index.value

    def fill_pixel(self, x, y, dimension):
        """All N samples of a declared dimension: ndarray (N, k, arity)."""
        info = self._info(dimension)
        out, ptr, n = self._buffer((self.samples_per_pixel, info.count, info.arity))
        self._library.check(self._library._lib.stipple_sampler_fill_pixel(
            self._handle, _coordinate(x), _coordinate(y), dimension, ptr, n))
        return out

    def sample(self, x, y, sample_index, dimension):
        """One sample (any index) of a declared dimension: ndarray (k, arity)."""
        info = self._info(dimension)
        out, ptr, n = self._buffer((info.count, info.arity))
        self._library.check(self._library._lib.stipple_sampler_sample(
            self._handle, _coordinate(x), _coordinate(y), sample_index, dimension, ptr, n))
        return out
