#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# A scene that cannot be loaded is skipped, not fatal: the single run and the merge of its shards both finish
# the other scene, name the skipped one (output and results.json) and exit with status 3.
# usage: skipped_scene.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
bin=$1 matrix=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
ok=1
expect() {  # expect LABEL STATUS LOG RESULTS_JSON
  local label=$1 want=$2 log=$3 json=$4 status
  status=$(tail -1 "$log")
  [ "$status" = "exit $want" ] || { echo "FAILED: $label: $status, expected exit $want"; ok=0; }
  grep -qE "scene skipped: .*unknown-key\.yaml" "$log" || { echo "FAILED: $label: output does not name the skipped scene"; ok=0; }
  grep -q '"name": "broken"' "$json" || { echo "FAILED: $label: results.json lacks skipped scene 'broken'"; ok=0; }
  grep -q '"scene": "cornell"' "$json" || { echo "FAILED: $label: results.json lacks the rows of 'cornell'"; ok=0; }
}
run() { local log=$1; shift; "$bin" "$@" > "$log" 2>&1; echo "exit $?" >> "$log"; }
run "$work/single.log" "$matrix" -o "$work/single" --cache "$work/cache" --threads 2
expect single 3 "$work/single.log" "$work/single/results.json"
run "$work/s1.log" "$matrix" -o "$work/s1" --cache "$work/cache" --threads 2 --shard 1/2
run "$work/s2.log" "$matrix" -o "$work/s2" --cache "$work/cache" --threads 2 --shard 2/2
run "$work/merged.log" "$matrix" -o "$work/merged" --merge "$work/s1" "$work/s2"
expect merged 3 "$work/merged.log" "$work/merged/results.json"
if grep -q "did every shard finish" "$work/merged.log"; then echo "FAILED: merge blamed the shards"; ok=0; fi
cat "$work/single.log" "$work/merged.log"
[ $ok -eq 1 ] && echo "PASSED: the broken scene is skipped and reported, single and merged"
[ $ok -eq 1 ]
