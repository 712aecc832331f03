# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Integer arguments checked against their C types before they reach ctypes, which would cut them silently
(2**32 + 16 as a uint32_t is 16)."""
import operator

from .errors import INVALID_ARGUMENT, OUT_OF_RANGE, ArgumentTypeError, StippleError

UINT32_MAX = 2**32 - 1
UINT64_MAX = 2**64 - 1


def integer(value, name):
    """value as a Python int; bool, float, str and other non-integers are refused (a pixel "1" is not 1)."""
    if not isinstance(value, (bool, str, bytes, float)):
        try:
            return operator.index(value)  # int and NumPy integer scalars
        except TypeError:
            pass
    raise ArgumentTypeError(INVALID_ARGUMENT, f"{name} is {value!r} ({type(value).__name__}); expected an integer")


def in_range(value, name, low, high, what=None):
    """value as an int in [low, high]; otherwise StippleError(OUT_OF_RANGE) naming the argument and the range."""
    v = integer(value, name)
    if not low <= v <= high:
        raise StippleError(OUT_OF_RANGE, f"{name} is {v}; expected {what or f'{low}..{high}'}")
    return v


def uint32(value, name):
    return in_range(value, name, 0, UINT32_MAX, "0..2^32-1 (a uint32_t)")


def uint64(value, name):
    return in_range(value, name, 0, UINT64_MAX, "0..2^64-1 (a uint64_t)")


def pixel(value, name):
    """A pixel coordinate: -2^31..2^32-1, passed as its uint32_t two's complement (as the C ABI reads it)."""
    return in_range(value, name, -(2**31), UINT32_MAX, "-2^31..2^32-1 (a pixel coordinate, int32 or uint32)") \
        & UINT32_MAX
