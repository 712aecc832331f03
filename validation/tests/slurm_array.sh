#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# On a one-node Slurm started here (validation/slurm/local-slurm.sh): a small matrix as a 4-task array job with
# one shared, initially empty reference cache, then the dependent merge job. The merged results.json must equal a
# single run's in every deterministic field (RMS and the other floats bitwise; times left out), and each
# reference must have been rendered by exactly one task. When Slurm cannot start, the test FAILS: CI machines
# (Debian 12, root) must run it. The daemons are stopped on every exit.
# usage: slurm_array.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -eu
bin=$1 matrix=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
slurm=$here/../slurm
state=$work/slurm-state
t0=$SECONDS

# Daemons an interrupted earlier run left behind (their pid files are in the old state folder) go first.
[ -d "$state" ] && bash "$slurm/local-slurm.sh" stop "$state" > /dev/null 2>&1 || true
rm -rf "$work"
mkdir -p "$work"
# Its own ports unless told otherwise, so a local Slurm someone left on the default ports does not clash.
export STIPPLE_SLURM_PORT=${STIPPLE_SLURM_PORT:-6917}
trap 'bash "$slurm/local-slurm.sh" stop "$state" || true' EXIT
trap 'exit 130' INT TERM HUP  # so that the EXIT trap stops the daemons when the test is interrupted
if ! bash "$slurm/local-slurm.sh" start "$state" > "$work/slurm-env" 2> "$work/slurm-start.log"; then
    cat "$work/slurm-start.log"
    echo "FAILED: Slurm could not start on this machine (see above); this test needs a one-node Slurm (root, Debian's slurm-wlm and munge)"
    exit 1
fi
cat "$work/slurm-start.log"
source "$work/slurm-env"  # SLURM_CONF

# The single run the array must reproduce (its own cache: the array starts from an empty one).
"$bin" "$matrix" -o "$work/single" --cache "$work/cache-single" --threads 2 > "$work/single.log" 2>&1 \
    || { cat "$work/single.log"; echo "FAILED: the single run exited $?"; exit 1; }

read -r array merge < <(bash "$slurm/submit-matrix.sh" "$matrix" "$work/array" --tasks 4 --threads 1 --mem 500 \
    --time 00:10:00 --bin "$bin" --parsable)
echo "array job $array, merge job $merge (after $((SECONDS - t0)) s)"

# Wait for the merge job to end (completed jobs stay known to slurmctld for MinJobAge seconds).
state_of() { scontrol show job "$1" 2> /dev/null | sed -nE 's/.*JobState=([A-Z_]+).*/\1/p' | head -n 1; }
deadline=$((SECONDS + 240))
while :; do
    s=$(state_of "$merge")
    case "$s" in
        COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE) break ;;
    esac
    if scontrol show job "$merge" 2> /dev/null | grep -q DependencyNeverSatisfied; then s=DependencyNeverSatisfied; break; fi
    [ $SECONDS -lt $deadline ] || { s="still ${s:-unknown} after 240 s"; break; }
    sleep 1
done
echo "merge job: $s (after $((SECONDS - t0)) s)"
if [ "$s" != COMPLETED ]; then
    scontrol show job "$array" | grep -E "JobId|JobState|ExitCode" || true
    tail -n 20 "$work"/array/logs/*.out || true
    echo "FAILED: the merge job did not complete ($s)"
    exit 1
fi
cat "$work"/array/logs/merge-*.out | grep -E '^(PASS|FAIL|[0-9]+ checks)' || true

python3 - "$work/single/results.json" "$work/array/report/results.json" "$work"/array/shards/*/results.json <<'PY'
import json, math, struct, sys
single, merged, shards = sys.argv[1], sys.argv[2], sys.argv[3:]
a, b = json.load(open(single)), json.load(open(merged))
TIMES = {"render_seconds", "sampler_seconds", "cpu_seconds", "median_render_seconds", "median_sampler_seconds",
         "median_cpu_seconds", "efficiency",
         "load_seconds", "build_seconds", "warmup_seconds", "reference_seconds"}

def bits(x):  # floats compared bit for bit
    return struct.pack("<d", x) if isinstance(x, float) else x

def same(x, y, where):
    if isinstance(x, dict) and isinstance(y, dict):
        if set(x) - TIMES != set(y) - TIMES:
            return f"{where}: keys {sorted(set(x) ^ set(y))} differ"
        for k in x:
            if k in TIMES: continue
            d = same(x[k], y[k], f"{where}.{k}")
            if d: return d
        return None
    if isinstance(x, list) and isinstance(y, list):
        if len(x) != len(y): return f"{where}: {len(x)} vs {len(y)} entries"
        for i, (u, v) in enumerate(zip(x, y)):
            d = same(u, v, f"{where}[{i}]")
            if d: return d
        return None
    if type(x) != type(y) or bits(x) != bits(y):
        return f"{where}: {x!r} (single) vs {y!r} (merged)"
    return None

fails = []
for key in ("matrix", "renderer_version", "fingerprint", "scenes", "skipped_scenes", "rows", "cells", "slopes"):
    d = same(a.get(key), b.get(key), key)
    if d: fails.append(d)
# Check outcomes: the same verdicts (their figures may quote times).
verdict = lambda r: [(c["type"], c["where"], c["status"], c["fails_run"], c["claim"]) for c in r["checks"]]
if not verdict(a) or verdict(a) != verdict(b): fails.append(f"checks: {verdict(a)} vs {verdict(b)}")
rows = len(a["rows"])
if rows == 0 or any(r.get("rms") is None for r in b["rows"]): fails.append("no rows, or a row without RMS")
# The shared cache: each scene's reference rendered by exactly one task (the others waited on its lock and read it).
renders = {}
for p in shards:
    for s in json.load(open(p))["scenes"]:
        renders[s["name"]] = renders.get(s["name"], 0) + (s["reference_seconds"] > 0)
for name, n in renders.items():
    if n != 1: fails.append(f"reference of {name} rendered by {n} tasks, expected 1")
if len(shards) != 4: fails.append(f"{len(shards)} shard folders, expected 4")
if fails:
    print("FAILED: merged array results differ from the single run:\n  " + "\n  ".join(fails))
    sys.exit(1)
print(f"merged == single run: {rows} rows, {len(a['cells'])} cells, {len(a['slopes'])} slopes, fingerprint of "
      f"{len(a['fingerprint'])} fields; references rendered once each: {renders}")
PY
echo "PASSED: 4-task Slurm array + merge equals the single run ($((SECONDS - t0)) s)"
