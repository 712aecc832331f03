# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""stipple.qmc.Engine: a scipy.stats.qmc engine that serves exactly the sampler's streams, continues, resets and
fast-forwards as SciPy's engines do, and through which SciPy's measures see what the patterns promise.

Run: STIPPLE_LIBRARY=<libstipple.so.1> python3 -m unittest discover -s shim/python/tests -p test_qmc.py
"""
import unittest

import numpy as np
from scipy.stats import qmc

import stipple
from stipple.qmc import Engine


class EngineTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.lib = stipple.Library()

    def test_points_are_the_sampler_streams(self):
        engine = Engine(5, "pmj02", samples_per_pixel=64, seed=9, pixel=(3, 4), library=self.lib)
        self.assertEqual(engine.arities, (2, 2, 1))
        points = engine.random(64)
        self.assertEqual(points.shape, (64, 5))
        sampler = self.lib.sampler("pmj02", 64, 9)
        expected = np.hstack([sampler.stream_fill(3, 4, 0, 64, d, a) for d, a in enumerate((2, 2, 1))])
        np.testing.assert_array_equal(points, expected.astype(np.float64))
        self.assertTrue(((points >= 0) & (points < 1)).all())

    def test_continues_resets_and_fast_forwards(self):
        engine = Engine(2, "stratified", samples_per_pixel=16, seed=2, library=self.lib)
        whole = engine.random(48)  # three blocks of 16
        engine.reset()
        halves = np.vstack([engine.random(20), engine.random(28)])
        np.testing.assert_array_equal(whole, halves)
        engine.reset()
        engine.fast_forward(33)
        np.testing.assert_array_equal(engine.random(15), whole[33:])
        self.assertEqual(engine.num_generated, 48)

    def test_scipy_measures_see_the_patterns_promises(self):
        # Centred L2 discrepancy of 256 points in 2D: a jittered set's is about N^-1/2 of a random set's (~1/16
        # here), so over 16 fixed seeds every stratified or sobol set must lie below every independent one; a
        # reversal would need a many-sigma outlier (probability well below 1e-6 per pair).
        def discrepancies(pattern):
            return [qmc.discrepancy(Engine(2, pattern, samples_per_pixel=256, seed=s, library=self.lib).random(256))
                    for s in range(16)]
        independent = discrepancies("independent")
        for pattern in ("stratified", "sobol", "pmj02"):
            self.assertLess(max(discrepancies(pattern)), min(independent), pattern)

    def test_blue_noise_names_and_refusals(self):
        engine = Engine(2, "stratified+blue-noise", samples_per_pixel=16, library=self.lib)
        self.assertTrue(engine.sampler.blue_noise)
        with self.assertRaises(ValueError):
            Engine(3, "sobol", arities=(2, 2), library=self.lib)
        with self.assertRaises(ValueError):
            Engine(2, "no-such-pattern", library=self.lib)
        with self.assertRaises(TypeError):
            Engine(2, "sobol", samples_per_pixel="16", library=self.lib)
        with self.assertRaises(ValueError):
            Engine(2, "sobol", pixel=5, library=self.lib)


if __name__ == "__main__":
    unittest.main()
