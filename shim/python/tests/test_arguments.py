# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Arguments are checked against their C types and the library's limits before any call: nothing is cut to 32
bits, nothing huge is allocated for a refused count, non-integers are refused, and every refusal is a
StippleError naming the argument and also the built-in exception a Python user catches (ValueError, TypeError,
OSError). A failed constructor leaves nothing for __del__ to trip over; a library that cannot be found is a
LibraryError (a StippleError and an OSError); a path given is loaded exactly, never searched for; close() waits
for the calls other threads have in flight.

Run: STIPPLE_LIBRARY=<libstipple.so.1> python3 -m unittest discover -s shim/python/tests
"""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import stipple
from stipple import errors

TWO_32 = 2**32


class ArgumentTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.lib = stipple.Library()
        cls.s = cls.lib.sampler("stratified", 16, 1, layout=[(2, 1, "pixel")])

    def refused(self, status, words, call, *args, **kwargs):
        with self.assertRaises(stipple.StippleError) as e:
            call(*args, **kwargs)
        self.assertEqual(e.exception.status, status, e.exception)
        for word in words:
            self.assertIn(word, e.exception.message)
        return e.exception

    def test_sample_index_2_32_is_refused_not_sample_0(self):
        self.refused(errors.OUT_OF_RANGE, ["sample_index", str(TWO_32)], self.s.stream, 0, 0, TWO_32, 0, 2)
        self.refused(errors.OUT_OF_RANGE, ["sample_index"], self.s.sample, 0, 0, TWO_32, 0)
        self.refused(errors.OUT_OF_RANGE, ["first_sample"], self.s.stream_fill, 0, 0, TWO_32, 1, 0, 2)
        self.refused(errors.OUT_OF_RANGE, ["sample_index"], self.s.stream, 0, 0, -1, 0, 2)
        last = self.s.stream_fill(0, 0, TWO_32 - 1, 1, 0, 2)  # the last index is served
        np.testing.assert_array_equal(last[0], self.s.stream(0, 0, TWO_32 - 1, 0, 2))

    def test_samples_per_pixel_2_32_plus_16_is_refused_not_16(self):
        self.refused(errors.OUT_OF_RANGE, ["samples_per_pixel", str(TWO_32 + 16)], self.lib.sampler,
                     "stratified", TWO_32 + 16, 1)
        self.refused(errors.OUT_OF_RANGE, ["samples_per_pixel"], self.lib.sampler, "stratified",
                     self.lib.limits.max_samples_per_pixel + 1, 1)
        self.refused(errors.OUT_OF_RANGE, ["samples_per_pixel"], self.lib.sampler, "stratified", 0, 1)
        self.refused(errors.OUT_OF_RANGE, ["count"], self.lib.sampler, "stratified", 4, 1,
                     layout=[(2, TWO_32 + 1)])

    def test_count_2_32_plus_16_is_refused_before_allocating(self):
        # Under an address-space limit of 1 GiB above what the process uses, a 16 GiB np.empty would fail with
        # MemoryError; the refusal must come first, as the package's error.
        code = ("import resource, stipple\n"
                "from stipple import errors\n"
                "s = stipple.Library().sampler('independent', 4, 0)\n"
                "soft, hard = resource.getrlimit(resource.RLIMIT_AS)\n"
                "used = int(open('/proc/self/statm').read().split()[0]) * resource.getpagesize()\n"
                "resource.setrlimit(resource.RLIMIT_AS, (used + (1 << 30), hard))\n"
                "for call in (lambda: s.stream_fill(0, 0, 0, 2**32 + 16, 0, 2),\n"
                "             lambda: s.pixels([[0, 0]], 0, 2, count=2**32 + 16),\n"
                "             lambda: s.stream_fill(0, 0, 16, 2**32 - 15, 0, 2),\n"
                "             lambda: s.sample_independent(0, 0, 0, 0, 2**32 + 16)):\n"
                "    try:\n"
                "        call()\n"
                "        raise SystemExit('not refused')\n"
                "    except stipple.StippleError as e:\n"
                "        assert e.status == errors.OUT_OF_RANGE and 'count' in e.message, e\n"
                "print('refused')\n")
        result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.strip(), "refused")

    def test_dimension_2_32_plus_3_is_refused_not_3(self):
        self.refused(errors.OUT_OF_RANGE, ["dimension", str(TWO_32 + 3)], self.s.stream, 0, 0, 0, TWO_32 + 3, 2)
        self.refused(errors.OUT_OF_RANGE, ["dimension"], self.s.stream_fill, 0, 0, 0, 4, TWO_32 + 3, 2)
        self.refused(errors.OUT_OF_RANGE, ["dimension"], self.s.pixels, [[0, 0]], TWO_32 + 3)
        self.refused(errors.OUT_OF_RANGE, ["dimension"], self.s.fill_pixel, 0, 0, TWO_32)
        self.refused(errors.OUT_OF_RANGE, ["arity"], self.s.stream, 0, 0, 0, 0, TWO_32 + 2)

    def test_non_integers_are_refused(self):
        self.refused(errors.INVALID_ARGUMENT, ["x", "'1'", "str"], self.s.stream, "1", 0, 0, 0, 2)
        self.refused(errors.INVALID_ARGUMENT, ["y", "float"], self.s.stream_fill, 0, 1.0, 0, 4, 0, 2)
        self.refused(errors.INVALID_ARGUMENT, ["sample_index", "bool"], self.s.stream, 0, 0, True, 0, 2)
        self.refused(errors.INVALID_ARGUMENT, ["pixels", "dtype"], self.s.pixels, [["1", "2"]])
        self.refused(errors.INVALID_ARGUMENT, ["pixels", "dtype"], self.s.pixels, np.zeros((3, 2)))
        self.refused(errors.INVALID_ARGUMENT, ["pixels", "shape"], self.s.pixels, np.zeros((3, 3), dtype=int))
        self.refused(errors.INVALID_ARGUMENT, ["pattern"], self.lib.sampler, 1, 4, 0)
        self.refused(errors.INVALID_ARGUMENT, ["blue_noise"], self.lib.sampler, "sobol", 4, 0, blue_noise=1)
        np.testing.assert_array_equal(self.s.stream(np.int64(3), np.uint32(4), np.int16(5), 0, 2),
                                      self.s.stream(3, 4, 5, 0, 2))  # NumPy integers are integers

    def test_pixels_and_seeds_out_of_their_types_are_refused(self):
        self.refused(errors.OUT_OF_RANGE, ["x", str(TWO_32)], self.s.stream, TWO_32, 0, 0, 0, 2)
        self.refused(errors.OUT_OF_RANGE, ["y"], self.s.stream, 0, -(2**31) - 1, 0, 0, 2)
        self.refused(errors.OUT_OF_RANGE, ["pixels", str(TWO_32)], self.s.pixels, np.array([[TWO_32, 0]]))
        self.refused(errors.OUT_OF_RANGE, ["seed"], self.lib.sampler, "sobol", 4, 2**64)
        self.refused(errors.OUT_OF_RANGE, ["seed"], self.lib.sampler, "sobol", 4, -1)
        self.assertEqual(self.lib.sampler("sobol", 4, 2**64 - 1).seed, 2**64 - 1)

    def test_failed_constructor_leaves_nothing_for_del(self):
        code = ("import gc, stipple\n"
                "lib = stipple.Library()\n"
                "for bad in (dict(pattern='nope'), dict(samples_per_pixel=2**32 + 16), dict(seed='1')):\n"
                "    args = dict(pattern='sobol', samples_per_pixel=4, seed=0)\n"
                "    args.update(bad)\n"
                "    try:\n"
                "        lib.sampler(**args)\n"
                "    except stipple.StippleError:\n"
                "        pass\n"
                "    gc.collect()\n")
        result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stderr, "")  # an exception in __del__ is printed as "Exception ignored in ..."

    def test_a_library_that_cannot_load_is_a_library_error(self):
        e = self.refused(None, ["no-such-folder", "STIPPLE_LIBRARY"], stipple.Library, "no-such-folder/libx.so")
        self.assertIsInstance(e, stipple.LibraryError)
        self.assertIsInstance(e, OSError)
        env = dict(os.environ, STIPPLE_LIBRARY=os.devnull)
        result = subprocess.run([sys.executable, "-c", "import stipple\ntry:\n    stipple.Library()\n"
                                 "except stipple.StippleError as e:\n    print(e)\n"], env=env,
                                capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("$STIPPLE_LIBRARY", result.stdout)

    def test_errors_are_the_builtin_exceptions_python_users_catch(self):
        with self.assertRaises(ValueError):
            self.s.stream(0, 0, TWO_32, 0, 2)  # out of range
        with self.assertRaises(ValueError):
            self.lib.sampler("no-such-pattern", 4)  # refused by the library
        with self.assertRaises(TypeError):
            self.s.stream("0", 0, 0, 0, 2)
        with self.assertRaises(TypeError):
            self.lib.sampler(7, 4)
        with self.assertRaises(OSError):
            stipple.Library("no-such-folder")
        for status, kind in [(errors.INVALID_ARGUMENT, ValueError), (errors.OUT_OF_RANGE, ValueError),
                             (errors.OUT_OF_MEMORY, MemoryError), (errors.ABI_VERSION, OSError),
                             (errors.INTERNAL, RuntimeError)]:
            e = stipple.StippleError(status, "m")
            self.assertIsInstance(e, kind)
            self.assertIsInstance(e, stipple.StippleError)
            self.assertEqual((e.status, e.message), (status, "m"))

    def test_a_given_path_is_loaded_exactly(self):
        # Each of these once made the system loader search its own places (and load whatever it found there).
        package_parent = os.path.dirname(os.path.dirname(os.path.abspath(stipple.__file__)))
        base_env = dict(os.environ, PYTHONPATH=package_parent)
        with tempfile.TemporaryDirectory() as empty:
            for given in ("./" + stipple.LIBRARY_NAME, stipple.LIBRARY_NAME, "."):
                code = f"import stipple\ntry:\n    print(stipple.Library({given!r}).path)\n" \
                       "except OSError as e:\n    print('refused', e)\n"
                env = dict(base_env, LD_LIBRARY_PATH=os.path.dirname(self.lib.path))
                result = subprocess.run([sys.executable, "-c", code], cwd=empty, env=env, capture_output=True,
                                        text=True, timeout=60)
                self.assertEqual(result.returncode, 0, result.stderr)
                self.assertTrue(result.stdout.startswith("refused"), (given, result.stdout))
                self.assertIn(empty, result.stdout)
            code = "import stipple\ntry:\n    stipple.Library()\nexcept OSError as e:\n    print('refused', e)\n"
            result = subprocess.run([sys.executable, "-c", code], cwd=empty, capture_output=True, text=True,
                                    timeout=60, env=dict(base_env, STIPPLE_LIBRARY="."))
            self.assertTrue(result.stdout.startswith("refused"), result.stdout + result.stderr)
        self.refused(errors.INVALID_ARGUMENT, ["empty"], stipple.Library, "")

    def test_close_waits_for_calls_in_flight(self):
        # Closing a sampler while another thread is inside a call once freed it under that call (a segfault, 5 of 5
        # runs); run in a child so a crash is a failure, not the end of the suite.
        code = ("import threading, numpy as np, stipple\n"
                "lib = stipple.Library()\n"
                "pixels = np.array([[x, y] for y in range(64) for x in range(64)])\n"
                "for trial in range(20):\n"
                "    s = lib.sampler('stratified', 256, trial)\n"
                "    outcome = []\n"
                "    def work():\n"
                "        try:\n"
                "            while True:\n"
                "                s.pixels(pixels, dimension=0, arity=2)\n"
                "        except stipple.ArgumentError as e:\n"
                "            outcome.append(str(e))\n"
                "    t = threading.Thread(target=work)\n"
                "    t.start()\n"
                "    s.close()\n"
                "    t.join()\n"
                "    assert outcome and 'closed' in outcome[0], outcome\n"
                "print('ok')\n")
        result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stdout.strip(), "ok")

    def test_blue_noise_spelt_as_the_other_front_ends_do(self):
        plain = self.lib.sampler("stratified", 16, 3, blue_noise=True)
        spelt = self.lib.sampler("stratified+blue-noise", 16, 3)
        self.assertTrue(spelt.blue_noise)
        np.testing.assert_array_equal(plain.stream_fill(5, 9, 0, 16, 0, 2), spelt.stream_fill(5, 9, 0, 16, 0, 2))
        self.refused(errors.INVALID_ARGUMENT, ["sobol"], self.lib.sampler, "sobol+blue-noise", 16)

if __name__ == "__main__":
    unittest.main()
