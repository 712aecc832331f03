#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# stipple-validate owns the external renderers it starts (each in a process group of its own):
#  1. a renderer that hangs (with a child of its own) is killed at the per-image timeout, named by its cell, and
#     its child dies with it (exit 3);
#  2. SIGTERM, SIGINT and SIGHUP of stipple-validate kill and reap the renderer and its child and remove the work
#     folder;
#  3. after a SIGKILL the work folder is left, and the next run sweeps it;
#  4. a run refused for want of permission makes no work folder.
# usage: external_children.sh STIPPLE_VALIDATE ANALYTIC_HOST MATRIX_DIR WORKDIR
set -u
bin=$1 host=$2 dir=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
ok=1
fail() { echo "FAILED: $*"; ok=0; }
alive() { [ -n "$1" ] && kill -0 "$1" 2> /dev/null && ! grep -q '^State:.*Z' "/proc/$1/status" 2> /dev/null; }
commands="$dir/analytic-host.command"
# A renderer that starts a child of its own, writes both pids and waits forever.
cat > "$work/hang.sh" << EOF
#!/bin/sh
sleep 1000 &
echo "\$\$ \$!" > "$work/pids"
wait
EOF
chmod +x "$work/hang.sh"
pids() { cat "$work/pids" 2> /dev/null; }

# 1. The timeout.
start=$(date +%s)
"$bin" "$dir/external-renderer.yaml" -o "$work/timeout" --cache "$work/cache" --renderer "$work/hang.sh" \
  --renderer-command "$commands" --renderer-timeout 1 > "$work/timeout.log" 2>&1
rc=$?
[ $rc -eq 3 ] || fail "a hung renderer with --renderer-timeout 1: exit $rc, expected 3"
[ $(( $(date +%s) - start )) -lt 60 ] || fail "the timeout did not end the run in time"
grep -qE "scene lights, independent, 512 spp, seed [0-9]+ .*ran longer than the per-image timeout of 1.0 s" "$work/timeout.log" ||
  fail "the timeout does not name the cell: $(grep -i timeout "$work/timeout.log")"
read -r child grandchild <<< "$(pids)"
alive "$child" && fail "the timed-out renderer ($child) is alive"
alive "$grandchild" && fail "the timed-out renderer's child ($grandchild) is alive"

# 2. Signals while a renderer runs.
for sig in TERM INT HUP; do
  rm -f "$work/pids"
  "$bin" "$dir/external-renderer.yaml" -o "$work/sig" --cache "$work/cache-$sig" --renderer "$work/hang.sh" \
    --renderer-command "$commands" > "$work/sig-$sig.log" 2>&1 &
  validate=$!
  for _ in $(seq 200); do [ -s "$work/pids" ] && break; sleep 0.1; done
  read -r child grandchild <<< "$(pids)"
  [ -n "$child" ] || { fail "SIG$sig: the renderer did not start"; kill -KILL $validate; continue; }
  kill -$sig $validate
  wait $validate
  sleep 0.2
  alive "$child" && { fail "SIG$sig: the renderer ($child) survived"; kill -KILL "$child"; }
  alive "$grandchild" && { fail "SIG$sig: the renderer's child ($grandchild) survived"; kill -KILL "$grandchild"; }
  ls -a "$work/cache-$sig" | grep -q "stipple-tmp" && fail "SIG$sig: the work folder was left: $(ls -a "$work/cache-$sig")"
done

# 3. SIGKILL: the folder stays (nothing can run), the next run sweeps it.
rm -f "$work/pids"
"$bin" "$dir/external-renderer.yaml" -o "$work/killed" --cache "$work/cache-kill" --renderer "$work/hang.sh" \
  --renderer-command "$commands" > "$work/kill.log" 2>&1 &
validate=$!
for _ in $(seq 200); do [ -s "$work/pids" ] && break; sleep 0.1; done
read -r child grandchild <<< "$(pids)"
kill -KILL $validate; wait $validate 2> /dev/null
kill -KILL -"$child" 2> /dev/null # its group: what a shell's job control would do
ls -a "$work/cache-kill" | grep -q "external-work.stipple-tmp" || fail "SIGKILL: no work folder to sweep (named?)"
"$bin" "$dir/external-renderer.yaml" -o "$work/after-kill" --cache "$work/cache-kill" --renderer "$host" \
  --renderer-command "$commands" > "$work/after-kill.log" 2>&1 || fail "the run after a SIGKILL failed: $(tail -3 "$work/after-kill.log")"
ls -a "$work/cache-kill" | grep -q "stipple-tmp" && fail "the next run did not sweep the work folder: $(ls -a "$work/cache-kill")"

# 4. No permission: no folder.
"$bin" "$dir/external-renderer.yaml" -o "$work/refused" --cache "$work/cache-refused" > "$work/refused.log" 2>&1
ls -a "$work/cache-refused" 2> /dev/null | grep -q "external-work" && fail "a refused run made a work folder"

[ $ok -eq 1 ] && echo "PASSED: renderers killed at the timeout and on signals with their children, work folders removed or swept"
[ $ok -eq 1 ]
