#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Regions end to end: the equal-time and equal-spp claims are judged per region, the verdict headline and the
# region crop grid are in the report, every region crop is at least 256 px on its long side, and every pattern's
# crop has its error map beside it.
# usage: regions_report.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
validate=$1 matrix=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work/report"
bash "$here/expect_run.sh" 1 \
  "cornell @ 16 spp: stratified/independent [0-9.]+× \(95% [0-9.]+-[0-9.]+\) PASS" \
  "FAIL +equal_spp cornell region box-shadows @ 16 spp" \
  "cornell region box-shadows: independent/stratified [0-9.]+× .* FAIL" \
  "cornell +box-shadows +[a-z]+ 1 " \
  -- "$validate" "$matrix" -o "$work/report" --cache "$work/cache" --threads 2 || exit 1
ok=1
grep -q 'class="headline"' "$work/report/index.html" || { echo "FAILED: no headline in index.html"; ok=0; }
grep -q 'id="claims-total">4<' "$work/report/index.html" && grep -q 'id="claims-fail">1<' "$work/report/index.html" || { echo "FAILED: headline counts"; ok=0; }
for c in reference independent stratified poisson; do
  f="$work/report/crops/cornell-region-box-shadows-$c.png"
  [ -f "$f" ] || { echo "FAILED: missing $f"; ok=0; continue; }
  grep -q "crops/cornell-region-box-shadows-$c.png" "$work/report/index.html" || { echo "FAILED: $c crop not linked"; ok=0; }
  # PNG IHDR: width and height are the big-endian words at bytes 16 and 20.
  read -r w h < <(od -An -tu1 -j16 -N8 "$f" | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}')
  [ "$w" -ge 256 ] || [ "$h" -ge 256 ] || { echo "FAILED: $f is ${w}x${h}, under 256 px on its long side"; ok=0; }
  if [ "$c" != reference ]; then
    m="crops/cornell-region-box-shadows-error-$c.png"
    [ -f "$work/report/$m" ] && grep -q "$m" "$work/report/index.html" || { echo "FAILED: no error map $m"; ok=0; }
  fi
done
grep -q '"region_mse": \[' "$work/report/results.json" || { echo "FAILED: results.json lacks region_mse"; ok=0; }
[ $ok -eq 1 ] && echo "regions report: ok"
[ $ok -eq 1 ]
