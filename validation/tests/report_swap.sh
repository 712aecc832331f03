#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The report folder is all-or-nothing and holds only the current matrix's files:
#  1. a folder reused for another matrix keeps none of the previous matrix's crops or plots;
#  2. SIGTERM at any moment of a run leaves the previous report exactly as it was and no temporary folder;
#  3. a SIGKILLed run's temporary folder is swept by the next run, which publishes a complete report.
# usage: report_swap.sh STIPPLE_VALIDATE BIG_MATRIX SMALL_MATRIX WORKDIR
set -u
bin=$1 big=$2 small=$3 work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAILED: $*"; exit 1; }
temps() { find "$work" -maxdepth 1 -name '*.stipple-tmp-*' | wc -l; }

t0=$(date +%s.%N)
"$bin" "$big" -o "$work/report" --cache "$work/cache" --threads 2 > "$work/log" 2>&1 || { cat "$work/log"; fail "big run"; }
full=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')  # a whole run with references to render, as below
ls "$work/report/crops" | grep -q poisson || fail "the big matrix made no poisson crop"
files() { (cd "$work/report" && find . -type f | sort); }
bigfiles=$(files)  # what a complete report of the big matrix holds
"$bin" "$small" -o "$work/report" --cache "$work/cache" --threads 2 > "$work/log" 2>&1 || { cat "$work/log"; fail "small run"; }
ls "$work/report/crops" "$work/report/plots" | grep -qE "poisson|veach" && fail "the previous matrix's files remain: $(ls -R "$work/report")"
grep -q '"matrix": "cache"' "$work/report/results.json" || grep -q 'cache' "$work/report/results.json" || fail "results.json is not the new matrix's"
echo "ok: a reused folder holds only the current matrix's files"

snapshot() { (cd "$work/report" && find . -type f | sort | xargs md5sum); }
before=$(snapshot)
# SIGTERM at fixed moments and at fractions of a whole run, so some land mid-run however fast the machine is.
for delay in 0.2 $(awk -v t="$full" 'BEGIN { for (f = 0.1; f < 1; f += 0.2) printf "%.3f ", t * f }') 1.5; do
  rm -rf "$work/fresh-cache"  # a reference to render: the run takes a while
  "$bin" "$big" -o "$work/report" --cache "$work/fresh-cache" --threads 2 > "$work/log" 2>&1 & pid=$!
  sleep $delay; kill -TERM $pid 2> /dev/null; wait $pid; rc=$?
  [ "$(temps)" -eq 0 ] || fail "SIGTERM after ${delay}s (rc $rc) left a temporary folder: $(ls -a "$work")"
  after=$(snapshot)
  if [ $rc -eq 0 ] || [ $rc -eq 1 ]; then before=$after; echo "run finished before SIGTERM at ${delay}s"; continue; fi
  if [ "$after" != "$before" ]; then
    # SIGTERM after the swap (the run was cleaning up): the folder must then be the new report, whole.
    [ "$(files)" = "$bigfiles" ] || fail "SIGTERM after ${delay}s (rc $rc) left a report that is neither the old nor a whole new one: $(files)"
    before=$after; echo "ok: SIGTERM after ${delay}s came after the swap: rc $rc, the new report whole"; continue
  fi
  echo "ok: SIGTERM after ${delay}s: rc $rc, previous report intact, no temporary folder"
done

rm -rf "$work/fresh-cache"
"$bin" "$big" -o "$work/report" --cache "$work/fresh-cache" --threads 2 > "$work/log" 2>&1 & pid=$!
# Killed as soon as its temporary folder exists (the references still have to render then); on a busy machine
# that can take seconds, so wait while the run lives (up to 2 minutes), not a fixed few.
for _ in $(seq 24000); do
  [ "$(temps)" -gt 0 ] && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.005
done
kill -KILL $pid 2> /dev/null || fail "the run finished before SIGKILL"
wait $pid 2> /dev/null
[ "$(temps)" -gt 0 ] || fail "SIGKILL left no temporary folder (nothing for the sweep to do)"
[ "$(snapshot)" = "$before" ] || fail "SIGKILL changed the previous report"
"$bin" "$small" -o "$work/report" --cache "$work/cache" --threads 2 > "$work/log" 2>&1 || { cat "$work/log"; fail "rerun"; }
[ "$(temps)" -eq 0 ] || fail "the rerun did not sweep the killed run's temporary folder: $(ls -a "$work")"
[ -f "$work/report/index.html" ] && [ -f "$work/report/results.json" ] || fail "the rerun's report is incomplete"
echo "ok: SIGKILL leaves the previous report; the rerun sweeps and publishes"
echo PASSED
