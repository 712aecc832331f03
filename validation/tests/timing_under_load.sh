#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# A time claim judged while CPU hogs (one per core) compete for the cores: the true claim must not FAIL
# (poisson / stratified ≤ 1.15: PASS, or NOT SEPARATED when the load blurs it), the false one (poisson-seed / stratified ≤ 1.05) must still FAIL.
# usage: timing_under_load.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
validate=$1 matrix=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
hogs=()
stop_hogs() { for p in "${hogs[@]}"; do kill "$p" 2>/dev/null; done; }
trap stop_hogs EXIT
for _ in 1 2; do
  ( while :; do :; done ) &
  hogs+=($!)
done
bash "$here/expect_run.sh" 1 \
  "(PASS|NOT SEPARATED) +time_ratio all @ 16 spp: poisson / stratified" \
  "FAIL +time_ratio all @ 16 spp: poisson-seed / stratified" \
  "cornell: CPU ratio [0-9.]+ .*<-- FAIL" \
  "2 checks, 1 failed" \
  -- "$validate" "$matrix" -o "$work/report" --cache "$work/cache" --threads 2
