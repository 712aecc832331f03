#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Regenerates shim/abi/libstipple.abi, the committed ABI baseline, from a built libstipple.so.1 (built with -g,
# which shim/CMakeLists.txt adds in every configuration). Run it only when a release deliberately changes the ABI.
#   usage: shim/abi/update-baseline.sh <path to libstipple.so.1>
set -euo pipefail
lib="$(realpath "${1:?usage: $0 <path to libstipple.so.1>}")"
# The library's debug info names sources relative to the project root (-ffile-prefix-map), so abidw runs there.
cd "$(dirname "$0")/../.."
# Exported interfaces only (the sampler handle is opaque in the debug info too); no machine paths or locations.
abidw --exported-interfaces-only --no-corpus-path --no-comp-dir-path --no-show-locs \
      --out-file shim/abi/libstipple.abi "$lib"
echo "wrote shim/abi/libstipple.abi"
