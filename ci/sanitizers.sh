#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Sanitizer CI: build the asan preset (clang, ASan + UBSan, RelWithDebInfo at -O2; the test programs' own sources
# at -O0: STIPPLE_TEST_COMPILE_OPTIONS) and run the whole CTest suite but labels `slow` and `slurm` (the Slurm test
# checks job orchestration, which the release run covers; `slow`: the CI matrix and the intervals' coverage
# simulation, minutes under ASan); build the tsan preset (gcc at -O1: about a fifth less compile time than -O2)
# and run label `parallel` (tests that exercise several threads), STIPPLE_JOBS at a time (the one timing test
# among them, validation.timing_under_load, is RUN_SERIAL).
# The asan tree is also the fuzzing tree (ci/fuzz.sh runs its libFuzzer harnesses): one clang build instead of a
# gcc one for the tests and a clang one for the fuzzers, 345 CPU-seconds instead of 685. libFuzzer's coverage
# counters are limited to the fuzzed parsers (cmake/fuzz_coverage.txt), so the shim's kernels run at ASan speed.
# clang links its sanitizer runtimes into executables only, so every executable of the asan tree also links the C++
# half of UBSan's (-fsanitize-link-c++-runtime -lstdc++): a C host that dlopens libstipple needs it for the
# library's vptr checks.
# Each stage builds only the targets its tests run (ci/test-targets.sh), not the whole tree.
# Any sanitizer report fails the test it happens in (halt_on_error / abort_on_error), hence this script.
#
# Environment (all optional):
#   STIPPLE_ASAN_DIR, STIPPLE_TSAN_DIR  build directories (default: the presets' build/asan, build/tsan)
#   STIPPLE_JOBS                        parallel build and test jobs (default 2)
#   STIPPLE_SANITIZERS                  "asan tsan" (default), or one of them
#   STIPPLE_TSAN_EXCLUDE                ctest -E regex of parallel tests to leave out of the TSan run (default: none)
#
# TSan and TBB: Debian's libtbb is not instrumented, so TSan cannot see tbb::parallel_for's hand-overs. TSan builds
# of the renderer therefore render tiles on std::thread workers (integrators/src/renderer.cpp, under
# __SANITIZE_THREAD__), whose every edge TSan sees; ci/sanitizers.supp covers only what happens inside the
# uninstrumented TBB and Embree libraries. A deliberate race in the tile body is reported (checked by hand).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${STIPPLE_JOBS:-2}
which=${STIPPLE_SANITIZERS:-asan tsan}
export BOOST_TEST_COLOR_OUTPUT=no
supp="$PWD/ci/sanitizers.supp"

configure_and_build() { # preset, build dir, ctest selection...
    local preset=$1 dir=$2
    shift 2
    local args=(--preset "$preset" -B "$dir")
    # The city generator's scenes are not needed to find memory or thread errors; keep the build small.
    cmake "${args[@]}" -DSTIPPLE_BUILD_SCENES=OFF
    local targets
    targets=$(bash ci/test-targets.sh "$dir" "$@")
    echo "sanitizers.sh: $preset: building $(wc -w <<<"$targets") targets for ctest $*"
    # shellcheck disable=SC2086 # one word per target
    cmake --build "$dir" -j "$jobs" --target $targets
}

# A fresh tree has no test times, and ctest then starts the tests in their order, a long one maybe last. The release
# run's times (its CTestCostData.txt) order them longest first here too: a sanitizer scales them all alike.
seed_test_costs() { # build dir
    local costs=build/release/Testing/Temporary/CTestCostData.txt
    if [[ -f "$costs" && ! -f "$1/Testing/Temporary/CTestCostData.txt" ]]; then
        mkdir -p "$1/Testing/Temporary" && cp "$costs" "$1/Testing/Temporary/"
    fi
}

status=0
start=$SECONDS
if [[ " $which " == *" asan "* ]]; then
    dir=${STIPPLE_ASAN_DIR:-build/asan}
    configure_and_build asan "$dir" -LE 'slow|slurm'
    seed_test_costs "$dir"
    # Leak checking on, with no suppressions (ci/sanitizers.supp is TSan's: clang's LSan refuses its entries);
    # UBSan reports are fatal (-fno-sanitize-recover in the preset).
    export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    ctest --test-dir "$dir" -LE 'slow|slurm' -j "$jobs" --output-on-failure --timeout 900 || status=1
    unset ASAN_OPTIONS UBSAN_OPTIONS
    echo "sanitizers.sh: asan done after $((SECONDS - start)) s"
fi
if [[ " $which " == *" tsan "* ]]; then
    dir=${STIPPLE_TSAN_DIR:-build/tsan}
    exclude=${STIPPLE_TSAN_EXCLUDE:-}
    configure_and_build tsan "$dir" -L parallel ${exclude:+-E "$exclude"}
    seed_test_costs "$dir"
    export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$supp:print_suppressions=0"
    ctest --test-dir "$dir" -L parallel ${exclude:+-E "$exclude"} -j "$jobs" --output-on-failure --timeout 900 || status=1
    unset TSAN_OPTIONS
    echo "sanitizers.sh: tsan done after $((SECONDS - start)) s"
fi
echo "sanitizers.sh: $((SECONDS - start)) s, status $status"
exit $status
