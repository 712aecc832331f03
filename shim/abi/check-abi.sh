#!/usr/bin/env bash
# Compares a built libstipple.so.1 against the committed baseline (shim/abi/libstipple.abi) and prints the
# report. abidiff's exit code is a bit field: 1 error, 2 usage, 4 ABI change, 8 incompatible change.
# Fails on the error/usage bits and on bit 8 (e.g. a removed function).
# Also fails on bit 4 when an existing function changed ("N Changed" with N > 0 in the summary): abidiff 2.2
# reports a field inserted into a struct of the header, which moves every later field, as bit 4 only (checked
# by building such a library). Only added functions/variables pass as a compatible change.
#   usage: shim/abi/check-abi.sh <path to libstipple.so.1>
set -uo pipefail
lib="$(realpath "${1:?usage: $0 <path to libstipple.so.1>}")"
# The library's debug info names sources relative to the project root (-ffile-prefix-map): compare from there.
cd "$(dirname "$0")/../.."
baseline=shim/abi/libstipple.abi
if [ ! -f "$baseline" ]; then
  echo "check-abi: no baseline at $baseline (make one with shim/abi/update-baseline.sh)"; exit 1
fi
report="$(abidiff --exported-interfaces-only "$baseline" "$lib")"
status=$?
echo "$report"
echo "check-abi: abidiff exit code $status"
if (( status & 8 )); then echo "check-abi: INCOMPATIBLE ABI change"; exit 1; fi
if (( status & 3 )); then echo "check-abi: abidiff failed to compare"; exit 1; fi
if (( status & 4 )); then
  if echo "$report" | grep -E -q 'changes summary: [0-9]+ Removed, [1-9][0-9]* Changed'; then
    echo "check-abi: an existing function's types changed: treated as incompatible"; exit 1
  fi
  echo "check-abi: compatible ABI change (additions only; update the baseline when releasing)"
fi
exit 0
