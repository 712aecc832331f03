#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Installs the Debian 12 packages a job needs. Idempotent: when everything is present it only checks.
# Non-interactive (CI has no standard input); never installs recommended extras.
#
#   bash ci/install-deps.sh [SET...]         SET: main or tests (default: both)
#   bash ci/install-deps.sh --list [SET...]  print the packages of the sets, one a line, and install nothing
#                                            (ci/check_package_sets.py compares them with what configure uses)
#     main   what ci/main.sh builds and runs: the shim, the renderer, stipple-validate and the Figure 3 program
#     tests  what ci/test.sh adds: Boost.Test, Google Benchmark, the tests' tools (python3, abidiff, Chromium,
#            a one-node Slurm) and clang for the fuzz harnesses
set -euo pipefail

main_packages=(
  build-essential cmake ninja-build git
  libembree-dev libtbb-dev
  libopenimageio-dev libopencolorio-dev
  libyaml-cpp-dev nlohmann-json3-dev
  libboost-dev            # Boost.Math (common/: stipple::statistics)
  gnuplot-nox             # the report's and Figure 3's plots
  openimageio-tools       # OpenImageIO's CMake config names its tools (/usr/bin/iconvert ...): configure fails without them
  libcpp-httplib-dev pkg-config  # stipple-validate --serve-study (the perceptual experiment's votes)
  python3-imath           # not used, but Imath's CMake config (through OpenImageIO) names its Python module: without
                          # it every configure prints a "file does not exist" warning
)
test_packages=(
  libboost-test-dev
  libbenchmark-dev
  pkg-config              # shim.install's pkg-config consumer
  python3 python3-numpy   # the Python example hosts (shim.quarter_disk_py, shim.stipple_numpy) and test scripts
  python3-yaml            # validation/slurm/estimate-cost.py
  abigail-tools           # shim.abi, shim.abi_since_1_0
  chromium                # headless: the report's browser test (validation.report_browser)
  clang libclang-rt-14-dev                     # ci/fuzz.sh: libFuzzer harnesses
  slurm-wlm slurmctld slurmd slurm-client munge # validation.slurm_array_equals_single_run
  python3-venv python3-pip python3-setuptools python3-wheel   # the Python package: its tests and the offline pip install
  python3-scipy           # the Python package's scipy.stats.qmc adapter and its test
  python3-selenium chromium-driver              # validation.perceptual_browser: simulated observers
)

list_only=0
if [ "${1:-}" = --list ]; then list_only=1; shift; fi
sets=("$@")
[ ${#sets[@]} -gt 0 ] || sets=(main tests)
packages=()
for set in "${sets[@]}"; do
  case "$set" in
    main) packages+=("${main_packages[@]}") ;;
    tests) packages+=("${main_packages[@]}" "${test_packages[@]}") ;;
    *) echo "install-deps: unknown set '$set' (known: main, tests)" >&2; exit 2 ;;
  esac
done

if [ "$list_only" -eq 1 ]; then
  printf '%s\n' "${packages[@]}" | sort -u
  exit 0
fi

missing=()
for p in $(printf '%s\n' "${packages[@]}" | sort -u); do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  if [ "$status" != "install ok installed" ]; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all $(printf '%s\n' "${packages[@]}" | sort -u | wc -l) packages of '${sets[*]}' present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq < /dev/null
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" < /dev/null
