# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""The package's samplers: shapes and dtypes, [0, 1), batch calls equal single calls, every pattern listed and
served, the blue-noise flag, stratification of a block past N, signed pixels, declared layouts, errors carrying
the library's message, and an unbiased streamed estimate of an edged integral.

Run: STIPPLE_LIBRARY=<libstipple.so.1> python3 -m unittest discover -s shim/python/tests
"""
import math
import os
import unittest

import numpy as np

import stipple


class SamplerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.lib = stipple.Library()

    def test_package_version_is_the_projects(self):
        project = os.environ.get("STIPPLE_PROJECT_VERSION")
        if project is None:
            self.skipTest("STIPPLE_PROJECT_VERSION not set (CTest sets it)")
        self.assertEqual(stipple.__version__, project, "bump src/stipple/__init__.py with the project version")
        self.assertEqual(".".join(map(str, self.lib.version)), project)

    def test_every_pattern_is_listed_and_serves_streams(self):
        self.assertEqual(self.lib.patterns[:6],
                         ("independent", "stratified", "poisson", "poisson-seed", "sobol", "pmj02"))
        for pattern in self.lib.patterns:
            for blue_noise in (False, True):
                if blue_noise and pattern != "stratified":  # the flag serves stratified only
                    with self.assertRaises(stipple.StippleError) as refused:
                        self.lib.sampler(pattern, 16, 5, blue_noise=True)
                    self.assertIn("blue", refused.exception.message.lower())
                    continue
                with self.lib.sampler(pattern, 16, 5, blue_noise=blue_noise) as s:
                    values = s.stream_fill(2, 3, 0, 16, 1, 2)
                    self.assertEqual(values.shape, (16, 2))
                    self.assertTrue(np.all((values >= 0) & (values < 1)), pattern)

    def test_streams_shapes_range_and_batch(self):
        s = self.lib.sampler("stratified", 16, 3)
        batch = s.stream_fill(1, 2, 5, 40, 7, 2)
        self.assertEqual(batch.shape, (40, 2))
        self.assertEqual(batch.dtype, np.float32)
        self.assertTrue(np.all((batch >= 0) & (batch < 1)))
        for i in range(40):
            np.testing.assert_array_equal(batch[i], s.stream(1, 2, 5 + i, 7, 2))

    def test_many_pixels_in_one_call_equal_one_pixel_calls(self):
        s = self.lib.sampler("stratified", 32, 11, blue_noise=True)
        xy = np.array([[x, y] for y in range(-2, 3) for x in range(70, 75)], dtype=np.int64)
        sets = s.pixels(xy, dimension=4, arity=3)
        self.assertEqual(sets.shape, (len(xy), 32, 3))
        for p, (x, y) in enumerate(xy):
            np.testing.assert_array_equal(sets[p], s.stream_fill(x, y, 0, 32, 4, 3))
        np.testing.assert_array_equal(s.pixels([3, 4], 0, 1, first_sample=40, count=5)[0],
                                      s.stream_fill(3, 4, 40, 5, 0, 1))
        self.assertEqual(s.pixels(np.zeros((0, 2), dtype=np.uint32)).shape, (0, 32, 2))

    def test_blue_noise_flag_changes_the_sets(self):
        plain = self.lib.sampler("stratified", 16, 1).stream_fill(5, 5, 0, 16, 0, 2)
        blue = self.lib.sampler("stratified", 16, 1, blue_noise=True).stream_fill(5, 5, 0, 16, 0, 2)
        self.assertFalse(np.array_equal(plain, blue))
        self.assertEqual(len({(int(u * 4), int(v * 4)) for u, v in blue}), 16)  # still one point per stratum

    def test_block_past_n_is_stratified(self):
        s = self.lib.sampler("stratified", 64, 9)
        block = s.stream_fill(-3, 4, 64 * 7, 64, 0, 2)  # block 7 of a negative pixel
        cells = set((int(u * 8), int(v * 8)) for u, v in block)
        self.assertEqual(len(cells), 64)
        self.assertFalse(np.array_equal(block, s.stream_fill(3, 4, 64 * 7, 64, 0, 2)))  # -3 is its own pixel
        np.testing.assert_array_equal(block, s.stream_fill(2**32 - 3, 4, 64 * 7, 64, 0, 2))  # two's complement

    def test_declared_layout(self):
        s = self.lib.sampler("poisson", 16, 1, layout=[(2, 1, "pixel"), (1, 3, "light")])
        light = s.find_dimension("light")
        self.assertEqual(s.dimension_info(light)["name"], "light")
        pixel = s.fill_pixel(0, 0, light)
        self.assertEqual(pixel.shape, (16, 3, 1))
        np.testing.assert_array_equal(pixel[5], s.sample(0, 0, 5, light))
        self.assertEqual(s.sample(0, 0, 100, light).shape, (3, 1))
        self.assertEqual(s.sample_independent(0, 0, 3, 9, 5).shape, (5,))

    def test_errors_raise_with_the_library_message(self):
        s = self.lib.sampler("independent", 4, 0)
        with self.assertRaises(stipple.StippleError) as e:
            s.fill_pixel(0, 0, 0)  # no declared layout
        self.assertEqual(e.exception.status, 3)
        self.assertIn("dimension", e.exception.message)
        with self.assertRaises(stipple.StippleError) as e:
            self.lib.sampler("no-such-pattern", 4, 0)
        self.assertIn("no-such-pattern", str(e.exception))
        s.close()
        with self.assertRaises(stipple.StippleError):
            s.stream(0, 0, 0, 0, 2)

    def test_large_poisson_sets_are_announced(self):
        with self.assertWarns(stipple.CostWarning):
            self.lib.sampler("poisson", 1 << 18, 1).close()  # creating costs nothing; the first call would

    def test_streamed_quarter_disk_is_unbiased(self):
        # Two-sided z-test over 2000 pixels, alpha = 0.01, fixed seed: the blocks past N stay unbiased.
        s = self.lib.sampler("poisson", 32, 2026)
        inside = np.sum(s.pixels([[p, 0] for p in range(2000)], 4, 2, first_sample=32, count=32)
                        .astype(np.float64) ** 2, axis=2) < 1
        estimates = inside.mean(axis=1)
        z = (estimates.mean() - math.pi / 4) / (estimates.std(ddof=1) / math.sqrt(len(estimates)))
        self.assertLess(abs(z), 2.576, f"mean {estimates.mean()} vs pi/4, z = {z}")


if __name__ == "__main__":
    unittest.main()
