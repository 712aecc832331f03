#!/usr/bin/env python3
"""Test of stipple_numpy: usage: test_stipple_numpy.py <path to libstipple.so.1>.

Checks shapes and dtypes, [0, 1), stream_fill == stream, stratification of a 2D block past N, signed pixels, the
declared-layout calls, errors raised as StippleError with the library's message, and an unbiased streamed estimate
of an edged integral (quarter disk): two-sided z-test over 2000 pixels, alpha = 0.01 (fixed seed).
"""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np  # noqa: E402

import stipple_numpy as sn  # noqa: E402

LIBRARY = None


class StippleNumpyTest(unittest.TestCase):
    def setUp(self):
        self.lib = sn.Library(LIBRARY)

    def test_streams_shapes_range_and_batch(self):
        s = self.lib.sampler("stratified", 16, 3)
        batch = s.stream_fill(1, 2, 5, 40, 7, 2)
        self.assertEqual(batch.shape, (40, 2))
        self.assertEqual(batch.dtype, np.float32)
        self.assertTrue(np.all((batch >= 0) & (batch < 1)))
        for i in range(40):
            np.testing.assert_array_equal(batch[i], s.stream(1, 2, 5 + i, 7, 2))

    def test_block_past_n_is_stratified(self):
        s = self.lib.sampler("stratified", 64, 9)
        block = s.stream_fill(-3, 4, 64 * 7, 64, 0, 2)  # block 7 of a negative pixel
        cells = set((int(u * 8), int(v * 8)) for u, v in block)
        self.assertEqual(len(cells), 64)
        self.assertFalse(np.array_equal(block, s.stream_fill(3, 4, 64 * 7, 64, 0, 2)))  # -3 is its own pixel

    def test_declared_layout(self):
        s = self.lib.sampler("poisson", 16, 1, layout=[(2, 1, "pixel"), (1, 3, "light")])
        light = s.find_dimension("light")
        pixel = s.fill_pixel(0, 0, light)
        self.assertEqual(pixel.shape, (16, 3, 1))
        np.testing.assert_array_equal(pixel[5], s.sample(0, 0, 5, light))
        self.assertEqual(s.sample(0, 0, 100, light).shape, (3, 1))

    def test_errors_raise_with_message(self):
        s = self.lib.sampler("independent", 4, 0)
        with self.assertRaises(sn.StippleError) as e:
            s.stream(0, 0, 0, 0, 4)
        self.assertIn("arity is 4", str(e.exception))
        with self.assertRaises(sn.StippleError):
            self.lib.sampler("no-such-pattern", 4, 0)
        with self.assertRaises(sn.StippleError):
            s.fill_pixel(0, 0, 0)  # no declared layout

    def test_streamed_quarter_disk_is_unbiased(self):
        s = self.lib.sampler("poisson", 32, 2026)
        estimates = np.array([np.mean(np.sum(s.stream_fill(p, 0, 32, 32, 4, 2).astype(np.float64) ** 2, axis=1) < 1)
                              for p in range(2000)])
        z = (estimates.mean() - math.pi / 4) / (estimates.std(ddof=1) / math.sqrt(len(estimates)))
        self.assertLess(abs(z), 2.576, f"mean {estimates.mean()} vs pi/4, z = {z}")


if __name__ == "__main__":
    LIBRARY = sys.argv.pop(1) if len(sys.argv) > 1 else "libstipple.so.1"
    unittest.main(verbosity=1)
