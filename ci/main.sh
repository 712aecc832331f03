#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The README's main job: install what is missing, configure and build what it runs (preset main), run the quick
# validation matrix (all four scenes) and write its report to report/ at the repository root, then the
# study's Figure 3 in its quick form (generation time vs N, rho, spectrum) to report/figure3/.
# Exit status: stipple-validate's (0 all claims hold, 1 a claim failed, 2/3 it could not run), or 3 when
# the matrix passed but Figure 3 could not be made.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh main
# The release tree without tests and benchmarks, and of it only what runs below: libstipple, stipple-validate
# (the renderer is a library inside it), the Italian city's geometry and the Figure 3 program.
cmake --preset main
cmake --build --preset main -j 2
echo "main: installed and built in $SECONDS s"
status=0
build/release/bin/stipple-validate validation/quick.yaml -o report --threads 2 --cache build/stipple-cache || status=$?
# Figure 3 at 50 sets per N (about 20 s of CPU); the full 1000-set run (about 6 min) is in the README's other commands.
if ! build/release/bin/shim_pointsets_figure3 -o report/figure3 --quick > report/figure3.log 2>&1; then
  echo "main: Figure 3 failed (see report/figure3.log)" >&2
  [ "$status" -ne 0 ] || status=3
fi
if [ -f report/index.html ]; then
  echo "main: report written to $(pwd)/report/index.html; Figure 3 in $(pwd)/report/figure3/"
else
  echo "main: no report was written (stipple-validate exit status $status)" >&2
fi
exit "$status"
