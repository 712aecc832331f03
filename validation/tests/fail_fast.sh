#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# What can be checked before rendering is checked first: a missing or malformed --baseline, a cache folder that
# cannot be written and an -o that is not a report folder each fail with exit status 2 before any reference or
# cell is rendered: nothing rendered is logged, the cache stays empty, the report folder is not created. Those are
# the proof; the time is printed (about 0.6 s on 2 loaded cores, nearly all of it loading the shared libraries) and
# bounded only by a 60 s ceiling against a hang, so a busy machine or a sanitizer build cannot flip the verdict.
# usage: fail_fast.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
bin=$1 matrix=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAILED: $*"; exit 1; }
check() {  # LABEL REGEX ARGS...
  local label=$1 regex=$2; shift 2
  local t0 t1 rc
  t0=$(date +%s%N)
  "$bin" "$matrix" --threads 2 "$@" > "$work/log" 2>&1; rc=$?
  t1=$(date +%s%N)
  local ms=$(( (t1 - t0) / 1000000 ))
  [ $rc -eq 2 ] || { cat "$work/log"; fail "$label: exit $rc, expected 2"; }
  grep -qE -- "$regex" "$work/log" || { cat "$work/log"; fail "$label: message lacks /$regex/"; }
  grep -q "reference for\|RMS" "$work/log" && fail "$label: rendered before failing"
  [ -z "$(find "$work/cache" -name '*.exr' 2> /dev/null)" ] || fail "$label: a reference was rendered"
  [ ! -e "$work/report" ] || fail "$label: the report folder was created"
  [ $ms -lt 60000 ] || fail "$label: took ${ms} ms (a hang?)"
  echo "ok: $label: exit 2 after ${ms} ms: $(grep stipple-validate "$work/log" | head -1)"
}
check "missing --baseline" "--baseline: .*no-such-results.json.*cannot open" \
  -o "$work/report" --cache "$work/cache" --baseline "$work/no-such-results.json"
printf 'name: x\nrows: [\n' > "$work/bad-results.json"
check "malformed --baseline" "--baseline: .*bad-results.json:[0-9]+:[0-9]+" \
  -o "$work/report" --cache "$work/cache" --baseline "$work/bad-results.json"
check "--baseline is a folder" "--baseline: .*not a regular file" \
  -o "$work/report" --cache "$work/cache" --baseline "$work"
touch "$work/file"
check "cache folder under a file" "cache folder .*file/cache: cannot create" -o "$work/report" --cache "$work/file/cache"
mkdir -p "$work/not-a-report" && touch "$work/not-a-report/precious.txt"
check "-o is not a report folder" "not a report folder" -o "$work/not-a-report" --cache "$work/cache"
[ -f "$work/not-a-report/precious.txt" ] || fail "the non-report folder was touched"
mkdir -p "$work/sub/deeper" && cd "$work/sub/deeper" || exit 1  # the cache stays outside these folders
check "-o is the working folder" "must name a report folder" -o . --cache "$work/cache"
check "-o is a parent" "must name a report folder" -o .. --cache "$work/cache"
cd "$work" || exit 1
check "cache inside the report" "inside the report folder" -o "$work/report" --cache "$work/report/cache"
echo PASSED
