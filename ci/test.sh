#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The README's test command: install what is missing, then
#   1. configure, build and run the whole CTest suite in Release (preset `release`);
#   2. the suite under ASan + UBSan and the multi-threaded tests under TSan (ci/sanitizers.sh);
#   3. each libFuzzer harness for a short bounded time over its corpus (ci/fuzz.sh).
# Any failure stops the run with a non-zero status. Set STIPPLE_QUICK_TESTS=1 to run step 1 only.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh tests
export BOOST_TEST_COLOR_OUTPUT=no
start=$SECONDS

cmake --preset release
cmake --build --preset release -j 2
mkdir -p build
ctest --preset release 2>&1 | tee build/ctest-release.log
summary=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' build/ctest-release.log | tail -1)
[[ -n "$summary" ]] || { echo "test.sh: ctest printed no summary" >&2; exit 1; }
echo "test.sh: release suite done after $((SECONDS - start)) s"

if [[ "${STIPPLE_QUICK_TESTS:-0}" != 1 ]]; then
    bash ci/sanitizers.sh
    echo "test.sh: sanitizers done after $((SECONDS - start)) s"
    bash ci/fuzz.sh
    echo "test.sh: fuzzing done after $((SECONDS - start)) s"
fi

# One closing line any reader understands: the release suite's counts (the stages above passed, or we stopped).
total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$summary")
failed=$(sed -E 's/.*, ([0-9]+) tests failed.*/\1/' <<<"$summary")
echo "test.sh: all stages passed in $((SECONDS - start)) s"
echo "$((total - failed)) passed, $failed failed"
