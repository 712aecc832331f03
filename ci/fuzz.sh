#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Fuzzing CI: build the libFuzzer harnesses in the asan preset's tree (clang, ASan + UBSan; the tests' tree too, so
# after ci/sanitizers.sh only the harnesses' own sources compile) and run each for a bounded time over its seed
# corpus and its regressions, STIPPLE_JOBS harnesses at a time. Exit status 1 when any harness
# finds a crash, a leak, a sanitizer report or a timeout; the reproducer is left in <build>/fuzz-out/<harness>/
# and the command to replay it is printed. Fix the bug, then add the file to the harness's regressions folder below (replayed by
# CTest).
#
# Environment (all optional):
#   STIPPLE_FUZZ_DIR      build directory (default: the asan preset's build/asan, shared with ci/sanitizers.sh)
#   STIPPLE_FUZZ_SECONDS  seconds per harness (default 20; a longer local run: 600 or more)
#   STIPPLE_JOBS          parallel build jobs and harnesses run at once (default 2)
#   STIPPLE_FUZZ_ONLY     space-separated harness names to run (default: all)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
seconds=${STIPPLE_FUZZ_SECONDS:-20}
jobs=${STIPPLE_JOBS:-2}
dir=${STIPPLE_FUZZ_DIR:-${STIPPLE_ASAN_DIR:-build/asan}}
start=$SECONDS

# The scenes part (city generator) has nothing to fuzz here (and ci/sanitizers.sh configures the tree the same way).
cmake --preset asan -B "$dir" -DSTIPPLE_BUILD_SCENES=OFF
cmake --build "$dir" -j "$jobs" --target stipple stipple_api_fuzzer scene_fuzzer matrix_fuzzer render_args_fuzzer \
    validate_args_fuzzer provenance_fuzzer pfm_fuzzer command_template_fuzzer

# harness name, part folder, seed corpus and regressions folders (in <part>/fuzz/)
harnesses=("stipple_api_fuzzer shim corpus regressions" "scene_fuzzer integrators corpus regressions"
           "matrix_fuzzer validation corpus regressions"
           "render_args_fuzzer integrators args-corpus args-regressions"
           "validate_args_fuzzer validation args-corpus args-regressions"
           "provenance_fuzzer validation provenance-corpus provenance-regressions"
           "pfm_fuzzer validation pfm-corpus pfm-regressions"
           "command_template_fuzzer validation command-corpus command-regressions")
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# One harness for $seconds; its lines go to $out/summary.txt and its verdict (0 or 1) to $out/status.
fuzz_one() { # name part seeds regressions
    local name=$1 part=$2 seeds=$3 regressions=$4
    local out="$dir/fuzz-out/$name"
    rm -rf "$out"
    mkdir -p "$out/corpus"  # new inputs go here, never into the repository
    local log="$out/log.txt"
    if "$dir/bin/$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
        -print_final_stats=1 -artifact_prefix="$out/" \
        "$out/corpus" "$root/$part/fuzz/$seeds" "$root/$part/fuzz/$regressions" >"$log" 2>&1; then
        local execs
        execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
        echo "fuzz.sh: $name ok: ${execs:-?} executions, $(ls "$out/corpus" | wc -l) new corpus inputs" >"$out/summary.txt"
        echo 0 >"$out/status"
    else
        {
            echo "fuzz.sh: $name FAILED; last lines of $log:"
            tail -40 "$log"
            for artifact in "$out"/crash-* "$out"/leak-* "$out"/timeout-* "$out"/oom-*; do
                [[ -e "$artifact" ]] && echo "fuzz.sh: reproduce with: $dir/bin/$name $artifact"
            done
        } >"$out/summary.txt"
        echo 1 >"$out/status"
    fi
}

# The harnesses are single-threaded: $jobs of them at a time, each for its full $seconds.
names=()
for entry in "${harnesses[@]}"; do
    read -r name part seeds regressions <<<"$entry"
    [[ -n "${STIPPLE_FUZZ_ONLY:-}" && " $STIPPLE_FUZZ_ONLY " != *" $name "* ]] && continue
    while (( $(jobs -rp | wc -l) >= jobs )); do wait -n || true; done
    echo "fuzz.sh: $name for ${seconds}s"
    fuzz_one "$name" "$part" "$seeds" "$regressions" &
    names+=("$name")
done
wait
status=0
for name in "${names[@]}"; do
    cat "$dir/fuzz-out/$name/summary.txt"
    [[ "$(cat "$dir/fuzz-out/$name/status")" == 0 ]] || status=1
done
echo "fuzz.sh: $((SECONDS - start)) s, status $status"
exit $status
