#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Compares a built libstipple.so.1 against the committed baseline (shim/abi/libstipple.abi) and prints the
# report. abidiff's exit code is a bit field: 1 error, 2 usage, 4 ABI change, 8 incompatible change.
# Fails on the error/usage bits and on bit 8 (e.g. a removed function).
# Also fails on bit 4 when an existing function changed ("N Changed" with N > 0 in the summary): abidiff 2.2
# reports a field inserted into a struct of the header, which moves every later field, as bit 4 only (checked
# by building such a library). Only added functions/variables pass as a compatible change.
# One change to an existing function is compatible and allowed: the dlopen table struct stipple_api growing at its
# end (new function pointers appended after every old member; hosts read its struct_size). Any other change to
# it (a member moved, removed or retyped) still fails.
#   usage: shim/abi/check-abi.sh <path to libstipple.so.1> [baseline, default shim/abi/libstipple.abi]
set -uo pipefail
lib="$(realpath "${1:?usage: $0 <path to libstipple.so.1> [baseline]}")"
# The library's debug info names sources relative to the project root (-ffile-prefix-map): compare from there.
cd "$(dirname "$0")/../.."
baseline="${2:-shim/abi/libstipple.abi}"
if [ ! -f "$baseline" ]; then
  echo "check-abi: no baseline at $baseline (make one with shim/abi/update-baseline.sh)"; exit 1
fi
# True when the only changed function is stipple_get_api and the only change under it is struct stipple_api
# growing by members inserted at offsets >= its old size.
appended_to_api_table() {
  local changes old offsets
  changes="$(echo "$1" | sed -n '/function with some indirect sub-type change/,$p')"
  [ "$(echo "$changes" | grep -c "^  \[C\]")" = 1 ] || return 1
  grep -q "^  \[C\] 'function stipple_status stipple_get_api" <<< "$changes" || return 1
  grep -q "underlying type 'struct stipple_api' changed" <<< "$changes" || return 1
  if echo "$changes" | grep -E -q "deletion|offset changed|changed offset|type of '|name of '|removed|underlying type 'struct [a-z_]+' changed" \
     && echo "$changes" | grep -E "deletion|offset changed|changed offset|type of '|name of '|removed|underlying type 'struct [a-z_]+' changed" \
        | grep -v -q "underlying type 'struct stipple_api' changed"; then
    return 1
  fi
  old="$(echo "$changes" | sed -n 's/.*type size changed from \([0-9]*\) to [0-9]* (in bits).*/\1/p' | head -1)"
  [ -n "$old" ] || return 1
  offsets="$(echo "$changes" | sed -n "s/.*', at offset \([0-9]*\) (in bits).*/\1/p")"
  [ -n "$offsets" ] || return 1
  for o in $offsets; do (( o >= old )) || return 1; done
  return 0
}

report="$(abidiff --exported-interfaces-only "$baseline" "$lib")"
status=$?
echo "$report"
echo "check-abi: abidiff exit code $status"
if (( status & 8 )); then echo "check-abi: INCOMPATIBLE ABI change"; exit 1; fi
if (( status & 3 )); then echo "check-abi: abidiff failed to compare"; exit 1; fi
if (( status & 4 )); then
  if echo "$report" | grep -E -q 'changes summary: [0-9]+ Removed, [1-9][0-9]* Changed'; then
    if ! appended_to_api_table "$report"; then
      echo "check-abi: an existing function's types changed: treated as incompatible"; exit 1
    fi
    echo "check-abi: struct stipple_api grew at its end only (members appended)"
  fi
  echo "check-abi: compatible ABI change (additions only; update the baseline when releasing)"
fi
exit 0
