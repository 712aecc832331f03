#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Things planted in a reference cache are never followed and never block a run:
#  - a FIFO in place of a cached EXR is reported as not a regular file and the entry is rendered again (the run
#    ends; before, it waited forever on the FIFO);
#  - a symlink in place of an entry's lock file is not followed: nothing is created where it points, and the run
#    fails with a message naming the lock file.
# usage: cache_planted.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
bin=$1 matrix=$2 work=$3
rm -rf "$work" && mkdir -p "$work/elsewhere" || exit 1
failed=0
fail() { echo "FAILED: $*"; failed=1; }
run() { timeout 60 "$bin" "$matrix" --cache "$work/cache" --threads 2 -o "$work/report" > "$work/log" 2>&1; }
run || { cat "$work/log"; echo "FAILED: first run"; exit 1; }
json=$(ls "$work/cache"/*.json | head -1)
stem=${json%.json}

rm "$stem.exr" && mkfifo "$stem.exr"
run; rc=$?
[ $rc -ne 124 ] || fail "the run hung on a FIFO in place of the cached EXR"
[ $rc -eq 0 ] || { cat "$work/log"; fail "FIFO in place of the EXR: exit $rc"; }
grep -q "not a regular file" "$work/log" || { cat "$work/log"; fail "the FIFO is not named"; }
[ -f "$stem.exr" ] && [ ! -p "$stem.exr" ] || fail "the entry was not rendered again as a regular file"
echo "ok: a FIFO in place of a cached EXR: exit $rc, $(grep -o '[^(]*not a regular file' "$work/log" | head -1)"

rm -f "$stem".*
ln -s "$work/elsewhere/created" "$stem.lock"
run; rc=$?
[ ! -e "$work/elsewhere/created" ] || fail "the lock's symlink was followed: $work/elsewhere/created exists"
[ $rc -ne 0 ] && grep -q "lock file .*symlink" "$work/log" || { cat "$work/log"; fail "no error naming the symlinked lock (exit $rc)"; }
echo "ok: a symlinked lock file is not followed: $(grep -o 'cannot open lock file.*' "$work/log" | head -1)"
[ $failed -eq 0 ] || exit 1
echo PASSED
