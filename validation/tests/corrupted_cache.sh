#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# A cached reference is used only when it verifies. Each corruption (a valid EXR of the right size with the wrong
# content, flipped bytes, edited provenance, a truncated EXR, a missing provenance) must be noticed, re-rendered
# (never a reason to skip the scene), give the same RMS as the clean run, and leave an entry that verifies.
# Then two processes writing the same fresh entry at once must leave one that verifies, and no temporaries.
# usage: corrupted_cache.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
bin=$1 matrix=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAILED: $*"; exit 1; }
run() { "$bin" "$matrix" -o "$work/report" --cache "$work/cache" --threads 2 > "$work/log" 2>&1; echo $? > "$work/status"; }
rms() { cut -d, -f1-13 "$work/report/results.csv"; }

run; [ "$(cat "$work/status")" = 0 ] || { cat "$work/log"; fail "clean run"; }
clean=$(rms)
img=$(ls "$work"/cache/*.exr | grep -v variance) var=$(ls "$work"/cache/*.variance.exr) json=$(ls "$work"/cache/*.json)
[ -f "$img" ] && [ -f "$var" ] && [ -f "$json" ] || fail "no cache entry: $(ls "$work/cache")"
grep -q '"image_checksum": "[0-9a-f]\{16\}"' "$json" || fail "provenance has no image checksum"
grep -q '"key_material": ' "$json" || fail "provenance has no full key"
pristine="$work/pristine" && mkdir -p "$pristine" && cp "$img" "$var" "$json" "$pristine/"
restore() { cp "$pristine"/* "$work/cache/"; }

corrupt() {  # LABEL: damage the entry, rerun, demand a re-render with the clean RMS, then a clean cached run
  local label=$1
  run
  [ "$(cat "$work/status")" = 0 ] || { cat "$work/log"; fail "$label: exit $(cat "$work/status")"; }
  grep -q "did not verify" "$work/log" || { cat "$work/log"; fail "$label: the damaged entry was used"; }
  grep -q "rendered" "$work/log" || fail "$label: not re-rendered"
  [ "$(rms)" = "$clean" ] || fail "$label: RMS differs from the clean run"
  run
  grep -q "did not verify" "$work/log" && fail "$label: the replaced entry does not verify"
  grep -q "cached" "$work/log" || fail "$label: the replaced entry is not used"
  echo "ok: $label: noticed, re-rendered, same RMS, replaced"
  restore
}

cp "$var" "$img"; corrupt "valid EXR of the right size, wrong content"
python3 - "$img" <<'PY'
import sys
p = sys.argv[1]; b = bytearray(open(p, 'rb').read()); i = len(b) * 2 // 3
b[i] ^= 0xff; b[i + 1] ^= 0x55; open(p, 'wb').write(b)
PY
corrupt "flipped bytes in the EXR"
sed -i 's/|seed 777|/|seed 778|/' "$json"; corrupt "edited provenance (key material)"
sed -i 's/"image_checksum": "[0-9a-f]/"image_checksum": "z/' "$json"; corrupt "edited provenance (checksum)"
truncate -s $(( $(stat -c %s "$img") / 2 )) "$img"; corrupt "truncated EXR"
rm "$json"; corrupt "missing provenance"

# Concurrent writers: two processes make the same fresh entry at once.
rm -rf "$work/cache2"
"$bin" "$matrix" --cache "$work/cache2" --threads 1 --references-only > "$work/w1.log" 2>&1 & p1=$!
"$bin" "$matrix" --cache "$work/cache2" --threads 1 --references-only > "$work/w2.log" 2>&1 & p2=$!
wait $p1 || { cat "$work/w1.log"; fail "writer 1"; }
wait $p2 || { cat "$work/w2.log"; fail "writer 2"; }
[ -z "$(find "$work/cache2" -name '*.stipple-tmp-*')" ] || fail "concurrent writers left temporaries: $(ls -a "$work/cache2")"
"$bin" "$matrix" -o "$work/report" --cache "$work/cache2" --threads 2 > "$work/log" 2>&1 || fail "run on the shared entry"
grep -q "did not verify" "$work/log" && fail "the concurrently written entry does not verify"
grep -q "cached" "$work/log" || fail "the concurrently written entry is not used"
[ "$(rms)" = "$clean" ] || fail "the concurrently written entry gives other RMS"
echo "ok: two concurrent writers leave one entry that verifies and no temporaries"

# Kill and rerun: SIGTERM during reference renders leaves no temporary in the cache; a SIGKILLed writer's
# temporaries (planted: SIGKILL cannot be timed to the write reliably) are swept by the next run, whose entry verifies.
for delay in 0.3 0.7 1.2; do
  rm -rf "$work/cache3"
  "$bin" "$matrix" --cache "$work/cache3" --threads 1 --references-only > "$work/k.log" 2>&1 & pid=$!
  sleep $delay; kill -TERM $pid 2> /dev/null; wait $pid; rc=$?
  [ -z "$(find "$work/cache3" -name '*.stipple-tmp-*' 2> /dev/null)" ] || fail "SIGTERM after ${delay}s (rc $rc) left temporaries in the cache"
  echo "ok: SIGTERM after ${delay}s: rc $rc, no temporary in the cache"
done
true & dead=$!; wait $dead
host=$(hostname | tr -- '-/' '__')
base=$(basename "$img" .exr)
touch "$work/cache3/.$base.exr.stipple-tmp-$host-$dead-0.exr" "$work/cache3/.$base.json.stipple-tmp-$host-$dead-2.json"
"$bin" "$matrix" -o "$work/report" --cache "$work/cache3" --threads 2 > "$work/log" 2>&1 || { cat "$work/log"; fail "rerun after kills"; }
[ -z "$(find "$work/cache3" -name '*.stipple-tmp-*')" ] || fail "the rerun did not sweep a dead writer's temporaries"
grep -q "did not verify" "$work/log" && fail "an interrupted write left an entry that was used"
[ "$(rms)" = "$clean" ] || fail "the entry after kills gives other RMS"
echo "ok: after kills the rerun sweeps the cache and its entry verifies"
echo PASSED
