#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The README's test command: install what is missing, then
#   1. configure, build and run the whole CTest suite in Release (preset `release`);
#   2. the suite under ASan + UBSan and the multi-threaded tests under TSan (ci/sanitizers.sh);
#   3. each libFuzzer harness for a short bounded time over its corpus (ci/fuzz.sh).
# The TSan and fuzz trees are built in the background (nice 19) from the end of step 1's build on.
# Any failure stops the run with a non-zero status. Set STIPPLE_QUICK_TESTS=1 to run step 1 only.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh tests
export BOOST_TEST_COLOR_OUTPUT=no
start=$SECONDS

cmake --preset release
cmake --build --preset release -j 2
mkdir -p build

# The TSan and fuzz trees build in the background at the lowest priority while the release and ASan suites run: a
# suite leaves part of the two cores idle (tests wait on child processes, files and renders' threads), and a nice-19
# build takes little more than what is idle. Their stages wait for it.
background=
if [[ "${STIPPLE_QUICK_TESTS:-0}" != 1 ]]; then
    # Its own process group (setsid), so that a failing run stops the whole build with it.
    setsid bash -c 'export STIPPLE_BUILD_ONLY=1
        STIPPLE_SANITIZERS=tsan nice -n 19 bash ci/sanitizers.sh && nice -n 19 bash ci/fuzz.sh' \
        >build/background-build.log 2>&1 &
    background=$!
    trap '[[ -n "$background" ]] && kill -- -"$background" 2>/dev/null || true' EXIT
fi
wait_background() {
    if ! wait "$background"; then
        background=
        echo "test.sh: the background build of the TSan and fuzz trees failed; its log (build/background-build.log):"
        cat build/background-build.log
        exit 1
    fi
    background=
    echo "test.sh: the TSan and fuzz trees were built in the background (build/background-build.log)"
}

ctest --preset release 2>&1 | tee build/ctest-release.log
summary=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' build/ctest-release.log | tail -1)
[[ -n "$summary" ]] || { echo "test.sh: ctest printed no summary" >&2; exit 1; }
echo "test.sh: release suite done after $((SECONDS - start)) s"

if [[ "${STIPPLE_QUICK_TESTS:-0}" != 1 ]]; then
    STIPPLE_SANITIZERS=asan bash ci/sanitizers.sh
    wait_background
    echo "test.sh: ASan + UBSan done after $((SECONDS - start)) s"
    STIPPLE_SANITIZERS=tsan bash ci/sanitizers.sh
    echo "test.sh: sanitizers done after $((SECONDS - start)) s"
    bash ci/fuzz.sh
    echo "test.sh: fuzzing done after $((SECONDS - start)) s"
fi

# One closing line any reader understands: the release suite's counts (the stages above passed, or we stopped).
total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$summary")
failed=$(sed -E 's/.*, ([0-9]+) tests failed.*/\1/' <<<"$summary")
echo "test.sh: all stages passed in $((SECONDS - start)) s"
echo "$((total - failed)) passed, $failed failed"
