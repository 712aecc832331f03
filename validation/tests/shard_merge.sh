#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Shard 1/2 + shard 2/2, merged, must give the same results rows as a single run (times excluded: the
# last three CSV columns) and the same check outcomes.
# usage: shard_merge.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -eu
bin=$1 matrix=$2 work=$3
rm -rf "$work/single" "$work/s1" "$work/s2" "$work/merged"
mkdir -p "$work"
cache="$work/cache"
"$bin" "$matrix" -o "$work/single" --cache "$cache" --threads 2 > "$work/single.log" 2>&1 || true
"$bin" "$matrix" -o "$work/s1" --cache "$cache" --threads 2 --shard 1/2 > /dev/null 2>&1
"$bin" "$matrix" -o "$work/s2" --cache "$cache" --threads 2 --shard 2/2 > /dev/null 2>&1
"$bin" "$matrix" -o "$work/merged" --merge "$work/s1" "$work/s2" > "$work/merged.log" 2>&1 || true
for f in single s1 s2 merged; do [ -s "$work/$f/results.csv" ] || { echo "FAILED: no $f/results.csv"; exit 1; }; done
rows_single=$(($(wc -l < "$work/single/results.csv") - 1))
rows_s1=$(($(wc -l < "$work/s1/results.csv") - 1))
rows_s2=$(($(wc -l < "$work/s2/results.csv") - 1))
echo "rows: single $rows_single, shard 1 $rows_s1, shard 2 $rows_s2"
[ "$rows_s1" -gt 0 ] && [ "$rows_s2" -gt 0 ] || { echo "FAILED: a shard is empty"; exit 1; }
[ $((rows_s1 + rows_s2)) -eq "$rows_single" ] || { echo "FAILED: shards do not add up"; exit 1; }
cols=$(head -1 "$work/single/results.csv" | tr ',' '\n' | wc -l)
keep=$((cols - 3))  # render, sampler and CPU seconds
if ! diff <(cut -d, -f1-$keep "$work/single/results.csv") <(cut -d, -f1-$keep "$work/merged/results.csv"); then
  echo "FAILED: merged rows differ from the single run"; exit 1
fi
diff <(grep -E '^(PASS|FAIL|NOT SEPARATED) ' "$work/single.log") <(grep -E '^(PASS|FAIL|NOT SEPARATED) ' "$work/merged.log") \
  || { echo "FAILED: check outcomes differ"; exit 1; }
[ -s "$work/merged/index.html" ] || { echo "FAILED: merged report has no index.html"; exit 1; }
echo "PASSED: shard 1/2 + 2/2 merged equals the single run ($rows_single rows)"
