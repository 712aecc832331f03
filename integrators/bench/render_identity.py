#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Whether two stipple-render builds make the same images, bit for bit, for a fixed seed.

    python3 integrators/bench/render_identity.py --baseline DIR --candidate DIR [--spp N (8)]
        [--scenes-dir DIR] [--scenes S,... (all four)] [--patterns P,... (stratified,sobol)] [--threads T (2)]

Each DIR is a build tree (or a copy of one, or its bin/stipple-render) holding bin/stipple-render and
lib/libstipple.so.1. Every scene is
rendered with every integrator (path, bdpt, direct, direct-light, direct-bsdf) and pattern by both builds with seed 7
at a small size, and the EXRs' pixels are compared exactly with OpenImageIO's idiff (-fail 0 -warn 0; the metadata,
which holds timings, is not compared). A change of the renderer that keeps its arithmetic must pass; one that
reorders it is checked by the statistical tests instead. Exit status 1 when some image differs.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

SCENES = ("cornell-box", "veach-mis", "veach-bidir", "italian-city")
INTEGRATORS = ("path", "bdpt", "direct", "direct-light", "direct-bsdf")


def render(build, scene_path, integrator, pattern, spp, threads, out):
    cmd = [os.path.join(build, "bin", "stipple-render"), scene_path, "--integrator", integrator, "--pattern", pattern,
           "--spp", str(spp), "--seed", "7", "--threads", str(threads), "--width", "96", "--height", "64", "-q",
           "-o", out]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"render_identity: {' '.join(cmd)} exited with {proc.returncode}: {proc.stderr.strip()}")


def build_tree(path):
    """A build tree, given as the tree or as its bin/stipple-render (what CMake's $<TARGET_FILE> names)."""
    if os.path.basename(path) == "stipple-render" and os.path.isfile(path):
        return os.path.dirname(os.path.dirname(os.path.abspath(path)))
    return path


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", required=True)
    parser.add_argument("--candidate", required=True)
    parser.add_argument("--spp", type=int, default=8)
    parser.add_argument("--scenes-dir", default=os.path.join(here, "..", "..", "scenes"))
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--patterns", default="stratified,sobol")
    parser.add_argument("--threads", type=int, default=2)
    o = parser.parse_args(argv)
    idiff = shutil.which("idiff")
    if not idiff:
        sys.exit("render_identity: OpenImageIO's idiff is not on PATH (Debian: openimageio-tools)")
    o.baseline, o.candidate = build_tree(o.baseline), build_tree(o.candidate)
    for d in (o.baseline, o.candidate):
        if not os.access(os.path.join(d, "bin", "stipple-render"), os.X_OK):
            sys.exit(f"render_identity: no bin/stipple-render in {d}")
    differing = 0
    total = 0
    with tempfile.TemporaryDirectory(prefix="render_identity.") as tmp:
        for scene in o.scenes.split(","):
            path = os.path.join(o.scenes_dir, scene + ".yaml")
            if not os.path.exists(path):
                sys.exit(f"render_identity: no {scene}.yaml in {o.scenes_dir}")
            for integrator in INTEGRATORS:
                for pattern in o.patterns.split(","):
                    a, b = os.path.join(tmp, "baseline.exr"), os.path.join(tmp, "candidate.exr")
                    render(o.baseline, path, integrator, pattern, o.spp, o.threads, a)
                    render(o.candidate, path, integrator, pattern, o.spp, o.threads, b)
                    compared = subprocess.run([idiff, "-fail", "0", "-warn", "0", a, b], capture_output=True)
                    same = compared.returncode == 0
                    total += 1
                    differing += not same
                    print(f"{scene:<14}{integrator:<14}{pattern:<24} {'identical' if same else 'DIFFERENT'}", flush=True)
    print(f"{total - differing} of {total} images identical")
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
