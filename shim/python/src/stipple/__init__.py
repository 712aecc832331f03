# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""stipple — deterministic sample streams for Monte Carlo rendering, from libstipple.so.1, as NumPy arrays.

    import stipple
    lib = stipple.Library()                      # finds libstipple.so.1 (see stipple.Library)
    s = lib.sampler("stratified", samples_per_pixel=64, seed=7, blue_noise=True)   # or "stratified+blue-noise"
    uv = s.stream_fill(3, 5, first_sample=0, count=64, dimension=0, arity=2)    # (64, 2) float32
    sets = s.pixels([[x, y] for y in range(4) for x in range(4)], dimension=1, arity=2)   # (16, 64, 2)

Every failure raises a stipple.StippleError (the library's status and message, or an argument refused before
the call) that is also the built-in exception for its kind: ArgumentError (ValueError), ArgumentTypeError
(TypeError), LibraryError (OSError), StippleMemoryError (MemoryError), InternalError (RuntimeError).
stipple.qmc.Engine serves any pattern to scipy.stats.qmc.
"""
from .errors import (ArgumentError, ArgumentTypeError, InternalError, LibraryError, StippleError,
                     StippleMemoryError)
from .library import ENVIRONMENT_VARIABLE, LIBRARY_NAME, LIMITS, Library, Limits, search_path
from .sampler import CostWarning, Sampler

__all__ = ["ArgumentError", "ArgumentTypeError", "CostWarning", "ENVIRONMENT_VARIABLE", "InternalError",
           "LIBRARY_NAME", "LIMITS", "Library", "LibraryError", "Limits", "Sampler", "StippleError",
           "StippleMemoryError", "search_path"]
__version__ = "1.2.0"  # the project's version (CMakeLists.txt); shim.python_sampler checks they agree
