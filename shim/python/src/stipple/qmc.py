# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Any stipple pattern as a scipy.stats.qmc engine, so SciPy's measures (qmc.discrepancy, qmc.geometric_discrepancy,
qmc.scale, ...) run on the sets a renderer gets.

    from scipy.stats import qmc
    from stipple.qmc import Engine
    points = Engine(2, "poisson", samples_per_pixel=256, seed=1).random(256)      # (256, 2)
    print(qmc.discrepancy(points))

Point i of the engine is sample i of one pixel's streams: the d coordinates are dimensions 0, 1, ... of the
sampler, each of the arity given by `arities` (default: 2D dimensions, and a 1D one last when d is odd, as a
path tracer asks for them). So Engine(2, "stratified", samples_per_pixel=N).random(N) is one jittered set of N
points; points past N read the pattern's next block (stipple.h: index i is position i mod N of block i // N).
Needs SciPy (Debian: python3-scipy).
"""
import numpy as np
from scipy.stats import qmc as _scipy_qmc

from ._integers import in_range, pixel, uint64
from .errors import INVALID_ARGUMENT, ArgumentError
from .library import Library


class Engine(_scipy_qmc.QMCEngine):
    """A stipple pattern as a scipy.stats.qmc.QMCEngine.

    Engine(d, pattern="sobol", *, samples_per_pixel=256, seed=0, pixel=(0, 0), arities=None, library=None)
        d (int): the points' dimension, >= 1; pattern (str): any name the library accepts, "+blue-noise"
        included; samples_per_pixel (int): the pattern's N; seed (int): the sampler's seed, 0..2^64-1;
        pixel ((int, int)): the pixel whose streams are served; arities (None | sequence of 1, 2 or 3 summing
        to d): how the coordinates group into the sampler's dimensions; library (None | Library).

    random(n) continues where the last call stopped; reset() starts again at sample 0; fast_forward(n) skips.
    """

    def __init__(self, d, pattern="sobol", *, samples_per_pixel=256, seed=0, pixel=(0, 0), arities=None,
                 library=None):
        d = in_range(d, "d", 1, 3 * 4096)
        if arities is None:
            arities = [2] * (d // 2) + [1] * (d % 2)
        arities = [in_range(a, f"arities[{i}]", 1, 3) for i, a in enumerate(arities)]
        if sum(arities) != d:
            raise ArgumentError(INVALID_ARGUMENT, f"arities {arities} sum to {sum(arities)}; expected d = {d}")
        self.pattern, self.arities = pattern, tuple(arities)
        self.pixel = (_pixel_coordinate(pixel, 0), _pixel_coordinate(pixel, 1))
        self.stipple_seed = uint64(seed, "seed")
        self.sampler = (library or Library()).sampler(pattern, samples_per_pixel, self.stipple_seed)
        super().__init__(d=d, seed=self.stipple_seed)

    def _random(self, n=1, *, workers=1):
        n = int(n)
        out = np.empty((n, self.d), dtype=np.float64)
        if n == 0:
            return out
        first, column = self.num_generated, 0
        for dimension, arity in enumerate(self.arities):
            values = self.sampler.stream_fill(self.pixel[0], self.pixel[1], first, n, dimension, arity)
            out[:, column:column + arity] = values
            column += arity
        return out

    def __repr__(self):
        return (f"stipple.qmc.Engine(d={self.d}, pattern={self.pattern!r}, samples_per_pixel="
                f"{self.sampler.samples_per_pixel}, seed={self.stipple_seed}, pixel={self.pixel}, "
                f"arities={self.arities})")


def _pixel_coordinate(value, index):
    try:
        coordinate = value[index]
    except (TypeError, IndexError):
        raise ArgumentError(INVALID_ARGUMENT, f"pixel is {value!r}; expected (x, y)") from None
    return pixel(coordinate, f"pixel[{index}]")
