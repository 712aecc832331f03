# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""The C ABI as ctypes sees it: structs, limits and the functions' signatures (stipple.h, ABI 1.1)."""
import ctypes

ABI_MAJOR = 1
ABI_MINOR = 1

PATTERN_FLAG_BLUE_NOISE = 1

# stipple.h's limits. (A limits query in the ABI would let a newer library raise them; until then they are the
# header's, and the library checks them again.)
MAX_SAMPLES_PER_PIXEL = 1 << 20
MAX_VALUES_PER_SAMPLE = 1024
MAX_SET_SIZE = 1 << 22
MAX_DIMENSIONS = 4096
MAX_NAME_LENGTH = 63
MAX_SAMPLE_INDEX_END = 1 << 32  # first_sample + count <= 2^32

status = ctypes.c_int32
sampler = ctypes.c_void_p
u32 = ctypes.c_uint32
floats = ctypes.POINTER(ctypes.c_float)


class DimensionDesc(ctypes.Structure):
    _fields_ = [("struct_size", u32), ("arity", u32), ("count", u32), ("reserved", u32),
                ("name", ctypes.c_char_p)]


class SamplerDesc(ctypes.Structure):
    _fields_ = [("struct_size", u32), ("pattern", u32), ("samples_per_pixel", u32), ("dimension_count", u32),
                ("seed", ctypes.c_uint64), ("dimensions", ctypes.POINTER(DimensionDesc)), ("flags", u32),
                ("reserved", u32)]


class DimensionInfo(ctypes.Structure):
    _fields_ = [("struct_size", u32), ("arity", u32), ("count", u32), ("floats_per_pixel", u32),
                ("name", ctypes.c_char_p), ("strata", u32 * 3), ("reserved", u32)]


# name: (argument types); every function returns a stipple_status except stipple_last_error_message.
SIGNATURES = {
    "stipple_get_version": [ctypes.POINTER(u32)] * 3,
    "stipple_pattern_from_name": [ctypes.c_char_p, ctypes.POINTER(u32)],
    "stipple_pattern_name": [u32, ctypes.POINTER(ctypes.c_char_p)],
    "stipple_sampler_create": [ctypes.POINTER(SamplerDesc), ctypes.POINTER(sampler)],
    "stipple_sampler_release": [sampler],
    "stipple_sampler_get_dimension_info": [sampler, u32, ctypes.POINTER(DimensionInfo)],
    "stipple_sampler_find_dimension": [sampler, ctypes.c_char_p, ctypes.POINTER(u32)],
    "stipple_sampler_fill_pixel": [sampler, u32, u32, u32, ctypes.c_void_p, ctypes.c_size_t],
    "stipple_sampler_sample": [sampler, u32, u32, u32, u32, ctypes.c_void_p, ctypes.c_size_t],
    "stipple_sampler_sample_independent": [sampler, u32, u32, u32, u32, ctypes.c_void_p, ctypes.c_size_t],
    "stipple_sampler_stream": [sampler, u32, u32, u32, u32, u32, ctypes.c_void_p, ctypes.c_size_t],
    "stipple_sampler_stream_fill": [sampler, u32, u32, u32, u32, u32, u32, ctypes.c_void_p, ctypes.c_size_t],
}

# Functions of later ABI minors, bound when the library has them.
OPTIONAL_SIGNATURES = {
    "stipple_pattern_parse": [ctypes.c_char_p, ctypes.POINTER(u32), ctypes.POINTER(u32)],  # ABI 1.2
}


def bind(cdll):
    """Sets argtypes/restype of every function this package calls; AttributeError names a missing one."""
    cdll.stipple_last_error_message.argtypes = []
    cdll.stipple_last_error_message.restype = ctypes.c_char_p
    for name, argtypes in SIGNATURES.items():
        function = getattr(cdll, name)
        function.argtypes = argtypes
        function.restype = status
    for name, argtypes in OPTIONAL_SIGNATURES.items():
        function = getattr(cdll, name, None)
        if function is not None:
            function.argtypes = argtypes
            function.restype = status
