#!/usr/bin/env bash
# The README's main job: install what is missing, configure and build the release preset, run the quick
# validation matrix (all four scenes) and write its report to report/ at the repository root.
# Exit status: stipple-validate's (0 all claims hold, 1 a claim failed, 2/3 it could not run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh
cmake --preset release
cmake --build --preset release -j 2
status=0
build/release/bin/stipple-validate validation/quick.yaml -o report --threads 2 --cache build/stipple-cache || status=$?
if [ -f report/index.html ]; then
  echo "main: report written to $(pwd)/report/index.html"
else
  echo "main: no report was written (stipple-validate exit status $status)" >&2
fi
exit "$status"
