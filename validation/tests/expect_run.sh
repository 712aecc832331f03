#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Runs a command and checks its exit status and output (stdout + stderr), so a test can demand that a
# run FAILs with the right message (a crash or a different failure does not pass).
# usage: expect_run.sh EXPECTED_STATUS REGEX [REGEX ...] -- COMMAND [ARGS ...]
set -u
expected=$1; shift
patterns=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do patterns+=("$1"); shift; done
[ $# -gt 0 ] || { echo "expect_run.sh: no -- before the command" >&2; exit 2; }
shift
output=$("$@" 2>&1)
status=$?
echo "$output"
echo "---- exit status $status (expected $expected)"
ok=1
[ "$status" -eq "$expected" ] || { echo "FAILED: exit status $status, expected $expected"; ok=0; }
for p in "${patterns[@]}"; do
  if grep -qE -- "$p" <<<"$output"; then echo "found: $p"; else echo "FAILED: output lacks /$p/"; ok=0; fi
done
[ $ok -eq 1 ]
