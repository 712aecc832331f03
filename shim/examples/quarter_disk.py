#!/usr/bin/env python3
"""quarter_disk.py — a python3 ctypes host of libstipple: estimates the quarter disk area pi/4 with every pattern.

Loads libstipple.so.1 (path from argv[1], else <this file's directory>/../../build/release/lib/libstipple.so.1),
uses only the function table returned by stipple_get_api, and for N = 16..4096 estimates
pi/4 = P(x^2 + y^2 < 1) in each of 256 pixels, printing the RMS error per pattern and N.

Exit status 0 only if stratified beats independent at every N >= 64 by a one-sided F-test on the mean squared
errors (F = MSE_independent / MSE_stratified, (256, 256) degrees of freedom), alpha = 0.01 Sidak-corrected over
the 4 tested N, with ln F ~ Normal(0, 2/256 + 2/256) giving the critical value (about 1.42).
Standard library only (ctypes, math, sys).
"""
import ctypes
import math
import os
import sys

STIPPLE_ABI_MAJOR = 1
STIPPLE_OK = 0
PATTERN_COUNT = 4
PIXELS_X, PIXELS_Y = 16, 16
PIXELS = PIXELS_X * PIXELS_Y
COUNTS = [16, 64, 256, 1024, 4096]

status_t = ctypes.c_int32
sampler_t = ctypes.c_void_p


class DimensionDesc(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_uint32), ("arity", ctypes.c_uint32), ("count", ctypes.c_uint32),
                ("reserved", ctypes.c_uint32), ("name", ctypes.c_char_p)]


class SamplerDesc(ctypes.Structure):
    _fields_ = [("struct_size", ctypes.c_uint32), ("pattern", ctypes.c_uint32),
                ("samples_per_pixel", ctypes.c_uint32), ("dimension_count", ctypes.c_uint32),
                ("seed", ctypes.c_uint64), ("dimensions", ctypes.POINTER(DimensionDesc)),
                ("flags", ctypes.c_uint32), ("reserved", ctypes.c_uint32)]


class Api(ctypes.Structure):
    _fields_ = [
        ("struct_size", ctypes.c_uint32), ("abi_major", ctypes.c_uint32), ("abi_minor", ctypes.c_uint32),
        ("reserved", ctypes.c_uint32),
        ("last_error_message", ctypes.CFUNCTYPE(ctypes.c_char_p)),
        ("get_version", ctypes.CFUNCTYPE(status_t, ctypes.POINTER(ctypes.c_uint32), ctypes.POINTER(ctypes.c_uint32),
                                         ctypes.POINTER(ctypes.c_uint32))),
        ("pattern_from_name", ctypes.CFUNCTYPE(status_t, ctypes.c_char_p, ctypes.POINTER(ctypes.c_uint32))),
        ("pattern_name", ctypes.CFUNCTYPE(status_t, ctypes.c_uint32, ctypes.POINTER(ctypes.c_char_p))),
        ("sampler_create", ctypes.CFUNCTYPE(status_t, ctypes.POINTER(SamplerDesc), ctypes.POINTER(sampler_t))),
        ("sampler_release", ctypes.CFUNCTYPE(status_t, sampler_t)),
        ("sampler_get_info", ctypes.c_void_p),
        ("sampler_get_dimension_info", ctypes.c_void_p),
        ("sampler_find_dimension", ctypes.c_void_p),
        ("sampler_fill_pixel", ctypes.CFUNCTYPE(status_t, sampler_t, ctypes.c_uint32, ctypes.c_uint32,
                                                ctypes.c_uint32, ctypes.POINTER(ctypes.c_float), ctypes.c_size_t)),
        ("sampler_sample", ctypes.c_void_p),
        ("sampler_sample_independent", ctypes.c_void_p),
    ]


class StippleError(RuntimeError):
    pass


def load_api(path):
    library = ctypes.CDLL(path, mode=ctypes.RTLD_LOCAL)
    get_api = library.stipple_get_api
    get_api.argtypes = [ctypes.c_uint32, ctypes.POINTER(ctypes.POINTER(Api))]
    get_api.restype = status_t
    table = ctypes.POINTER(Api)()
    if get_api(STIPPLE_ABI_MAJOR, ctypes.byref(table)) != STIPPLE_OK:
        raise StippleError("the library does not provide ABI %d" % STIPPLE_ABI_MAJOR)
    if table.contents.struct_size < ctypes.sizeof(Api):
        raise StippleError("the library's function table is smaller than this host's")
    return library, table.contents


def check(api, status, what):
    if status != STIPPLE_OK:
        raise StippleError("%s failed with status %d: %s" % (what, status, api.last_error_message().decode()))


def mean_squared_error(api, pattern, n, buffer):
    exact = math.pi / 4
    dimension = DimensionDesc(ctypes.sizeof(DimensionDesc), 2, 1, 0, b"point")
    desc = SamplerDesc(ctypes.sizeof(SamplerDesc), pattern, n, 1, 20261121, ctypes.pointer(dimension), 0, 0)
    sampler = sampler_t()
    check(api, api.sampler_create(ctypes.byref(desc), ctypes.byref(sampler)), "sampler_create")
    try:
        total = 0.0
        for py in range(PIXELS_Y):
            for px in range(PIXELS_X):
                check(api, api.sampler_fill_pixel(sampler, px, py, 0, buffer, 2 * n), "sampler_fill_pixel")
                values = buffer[:2 * n]
                inside = sum(1 for x, y in zip(values[0::2], values[1::2]) if x * x + y * y < 1.0)
                error = inside / n - exact
                total += error * error
        return total / PIXELS
    finally:
        api.sampler_release(sampler)


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    path = argv[1] if len(argv) > 1 else os.path.join(here, "..", "..", "build", "release", "lib", "libstipple.so.1")
    try:
        _library, api = load_api(path)
    except OSError as e:
        print("quarter_disk.py: cannot load libstipple: %s" % e, file=sys.stderr)
        return 2
    buffer = (ctypes.c_float * (2 * max(COUNTS)))()
    critical_f = math.exp(2.807 * math.sqrt(2.0 / PIXELS + 2.0 / PIXELS))  # Sidak: 1 - 0.99^(1/4) -> z = 2.807

    print("RMS error of the pi/4 estimate over %d pixels (seed 20261121), python3 ctypes host" % PIXELS)
    print("%-14s" % "pattern" + "".join(" %16s" % ("N=%d" % n) for n in COUNTS))
    mse = {}
    try:
        for pattern in range(PATTERN_COUNT):
            name = ctypes.c_char_p()
            check(api, api.pattern_name(pattern, ctypes.byref(name)), "pattern_name")
            row = [mean_squared_error(api, pattern, n, buffer) for n in COUNTS]
            mse[pattern] = row
            print("%-14s" % name.value.decode() + "".join(" %16.3e" % math.sqrt(m) for m in row), flush=True)
    except StippleError as e:
        print("quarter_disk.py: %s" % e, file=sys.stderr)
        return 2

    print("F-test stratified < independent (critical F = %.3f, alpha 0.01 Sidak over 4 N):" % critical_f)
    passed = True
    for c, n in enumerate(COUNTS):
        if n < 64:
            continue
        f = mse[0][c] / mse[1][c]
        ok = f > critical_f
        passed = passed and ok
        print("  N=%-5d F = MSE_independent / MSE_stratified = %8.2f  %s" % (n, f, "pass" if ok else "FAIL"))
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
