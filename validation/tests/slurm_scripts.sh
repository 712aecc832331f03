#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The Slurm scripts (validation/slurm) on hostile or careless arguments, without a cluster (sbatch is a stand-in
# that keeps each job's script and environment; the test then runs them as a task would):
#  - submit-matrix.sh: an OUTDIR holding $(...), backticks and a quote reaches stipple-validate as one literal
#    path, in the task and in the merge job, and runs nothing; --indices beyond --tasks, a --tasks too large for
#    the shell, --tasks without a value and an extra sbatch option that overrides the script's are usage errors;
#  - estimate-cost.py: a failing stipple-validate with an old work folder fails (no table from stale results);
#    --divisor 0, --tasks 0 and a missing matrix are usage errors without a traceback; a scene named "../x"
#    writes nothing outside --work;
#  - local-slurm.sh: start on a folder it did not create is refused and leaves its files and mode alone; a
#    daemon that fails before writing its log is named (as root only: start needs root).
# usage: slurm_scripts.sh STIPPLE_VALIDATE SCENE WORKDIR
set -u
validate=$1 scene=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
slurm=$here/../slurm
rm -rf "$work" && mkdir -p "$work/fakebin" || exit 1
failed=0
fail() { echo "FAILED: $*"; failed=1; }
expect() {  # LABEL STATUS REGEX COMMAND...
  local label=$1 status=$2 regex=$3; shift 3
  timeout 20 "$@" > "$work/out.log" 2> "$work/err.log"; local rc=$?
  [ $rc -eq "$status" ] || { cat "$work/out.log" "$work/err.log"; fail "$label: exit $rc, expected $status"; return 1; }
  grep -qE -- "$regex" "$work/err.log" || { cat "$work/err.log"; fail "$label: stderr lacks /$regex/"; return 1; }
  grep -q Traceback "$work/err.log" && { cat "$work/err.log"; fail "$label: a Python traceback"; return 1; }
  echo "ok: $label: $(head -1 "$work/err.log")"
}

# ---- submit-matrix.sh ---------------------------------------------------------------------------------------
# sbatch's stand-in: job N's script, arguments and STIPPLE_* environment are kept; it prints the job id.
cat > "$work/fakebin/sbatch" <<'FAKE'
#!/usr/bin/env bash
n=$(( $(ls "$FAKE_JOBS" | grep -c '\.sh$') + 1 ))
cat > "$FAKE_JOBS/$n.sh"
printf '%s\n' "$@" > "$FAKE_JOBS/$n.args"
export -p | grep ' STIPPLE_' > "$FAKE_JOBS/$n.env"
echo "$((1000 + n))"
FAKE
# stipple-validate's stand-in: its arguments, one per line.
cat > "$work/fakebin/validate" <<'FAKE'
#!/usr/bin/env bash
printf '%s\n' "$@" > "$FAKE_ARGV"
FAKE
chmod +x "$work/fakebin/sbatch" "$work/fakebin/validate"
export FAKE_JOBS=$work/jobs && mkdir -p "$FAKE_JOBS"
printf 'name: m\n' > "$work/m.yaml"
submit() { PATH="$work/fakebin:$PATH" bash "$slurm/submit-matrix.sh" "$work/m.yaml" "$@" --bin "$work/fakebin/validate"; }
sub=(env "PATH=$work/fakebin:$PATH" bash "$slurm/submit-matrix.sh" "$work/m.yaml" "$work/o" --bin "$work/fakebin/validate")

out="$work/out \$(touch $work/pwned1) \`touch $work/pwned2\` \"q"
if submit "$out" --tasks 2 --parsable > "$work/out.log" 2> "$work/err.log"; then
  mkdir -p "$work/run" && cd "$work/run" || exit 1
  for job in 1 2; do
    ( source "$FAKE_JOBS/$job.env"; export FAKE_ARGV="$work/argv.$job" SLURM_ARRAY_TASK_ID=2; bash "$FAKE_JOBS/$job.sh" )
  done
  cd "$work" || exit 1
  real=$(realpath -- "$out")
  [ ! -e "$work/pwned1" ] && [ ! -e "$work/pwned2" ] && [ ! -e "$work/run/pwned1" ] || fail "a path in OUTDIR ran as code"
  grep -qxF -- "$real/shards/2" "$work/argv.1" 2> /dev/null || { cat "$work/argv.1"; fail "the task's -o is not the literal shard path"; }
  { grep -qxF -- "$real/shards/1" "$work/argv.2" && grep -qxF -- "$real/report" "$work/argv.2"; } 2> /dev/null \
    || { cat "$work/argv.2"; fail "the merge job's folders are not the literal paths"; }
  echo "ok: OUTDIR with \$(...), backticks and a quote reaches stipple-validate literally"
else
  cat "$work/err.log"; fail "submit-matrix.sh refused an OUTDIR with special characters"
fi
# The renderer options reach every task (an external matrix's shards would otherwise skip every scene).
rm -f "$FAKE_JOBS"/* && printf 'analytic_host\n{output}\n' > "$work/host.command" && touch "$work/host"
if submit "$work/o-ext" --tasks 2 --renderer "$work/host" --renderer-command "$work/host.command" \
     --renderer-timeout 30 > "$work/out.log" 2> "$work/err.log"; then
  ( source "$FAKE_JOBS/1.env"; export FAKE_ARGV="$work/argv.ext" SLURM_ARRAY_TASK_ID=1; bash "$FAKE_JOBS/1.sh" )
  tr '\n' ' ' < "$work/argv.ext" | grep -qF -- "--renderer-command $work/host.command --renderer $work/host --renderer-timeout 30" ||
    fail "the task does not pass the renderer options: $(tr '\n' ' ' < "$work/argv.ext")"
  echo "ok: --renderer, --renderer-command and --renderer-timeout reach the task"
else
  cat "$work/err.log"; fail "submit-matrix.sh refused the renderer options"
fi
rm -f "$FAKE_JOBS"/*
expect "--indices beyond --tasks" 2 "--indices: task '5' .* not within 1..2" "${sub[@]}" --tasks 2 --indices 1,5
expect "--tasks too large" 2 "--tasks: expected an integer in \[1, 10000\]" "${sub[@]}" --tasks 99999999999999999999999
expect "--tasks without a value" 2 "--tasks needs a value" "${sub[@]}" --tasks
expect "an extra --array" 2 "extra sbatch option '--array=1-3' would override" "${sub[@]}" --tasks 2 -- --array=1-3

# ---- estimate-cost.py ---------------------------------------------------------------------------------------
cat > "$work/cost.yaml" <<YAML
name: cost
scenes:
  - { file: $scene, name: cornell, width: 16, height: 16 }
patterns: [independent]
spp: [1]
seeds: 4
reference: { spp: 4, seed: 777 }
YAML
est=(python3 "$slurm/estimate-cost.py")
timeout 120 python3 "$slurm/estimate-cost.py" "$work/cost.yaml" --bin "$validate" --work "$work/est" --divisor 4 \
  > "$work/out.log" 2> "$work/err.log" || { cat "$work/err.log"; fail "estimate-cost.py with a working stipple-validate"; }
printf '#!/bin/sh\necho "broken build" >&2\nexit 3\n' > "$work/fakebin/broken" && chmod +x "$work/fakebin/broken"
expect "failing stipple-validate, old work folder" 3 "exited 3" \
  "${est[@]}" "$work/cost.yaml" --bin "$work/fakebin/broken" --work "$work/est" --divisor 4
grep -q "CPU-hours" "$work/out.log" && fail "a table was printed from stale results"
expect "--divisor 0" 2 "--divisor: expected an integer" "${est[@]}" "$work/cost.yaml" --bin "$validate" --divisor 0
expect "--tasks 0" 2 "--tasks: expected an integer" "${est[@]}" "$work/cost.yaml" --bin "$validate" --tasks 0
expect "missing matrix" 2 "cannot read the matrix" "${est[@]}" "$work/none.yaml" --bin "$validate"
printf 'renderer: { command: [host, "{output}"] }\n' | cat "$work/cost.yaml" - > "$work/cost-external.yaml"
expect "an external matrix" 2 "use an external renderer; estimate-cost samples stipple-render only" \
  "${est[@]}" "$work/cost-external.yaml" --bin "$validate"
sed 's/name: cornell,/name: "..\/..\/escape",/' "$work/cost.yaml" > "$work/escape.yaml"
mkdir -p "$work/deep/er"
timeout 120 python3 "$slurm/estimate-cost.py" "$work/escape.yaml" --bin "$validate" --work "$work/deep/er/est" \
  --divisor 4 > "$work/out.log" 2> "$work/err.log" || { cat "$work/err.log"; fail "estimate-cost.py with a scene named ../../escape"; }
[ -z "$(find "$work/deep" -maxdepth 2 -name '*escape*')" ] || fail "files written outside --work: $(find "$work/deep" -maxdepth 2 -name '*escape*')"
echo "ok: a scene named ../../escape stays inside --work"

# ---- local-slurm.sh -----------------------------------------------------------------------------------------
# A stand-in for munged that fails at once: whatever the script does, no real daemon starts here (the others
# start only after munged).
mkdir -p "$work/nodaemons"
for d in munged; do printf '#!/bin/sh\nexit 1\n' > "$work/nodaemons/$d"; chmod +x "$work/nodaemons/$d"; done
mkdir -p "$work/mine" && echo keep > "$work/mine/notes.log" && chmod 755 "$work/mine"
expect "start on a folder it did not create" 2 "is not a state folder made by local-slurm.sh" \
  env PATH="$work/nodaemons:$PATH" bash "$slurm/local-slurm.sh" start "$work/mine"
[ -f "$work/mine/notes.log" ] || fail "local-slurm.sh deleted notes.log"
[ "$(stat -c %a "$work/mine")" = 755 ] || fail "local-slurm.sh changed the folder's mode"
expect "stop on a folder it did not create" 2 "is not a state folder" bash "$slurm/local-slurm.sh" stop "$work/mine"
if [ "$(id -u)" -eq 0 ] && command -v slurmd > /dev/null && command -v munged > /dev/null; then
  expect "a daemon failing before its log" 1 "munged did not start" \
    env PATH="$work/nodaemons:$PATH" STIPPLE_SLURM_PORT=6997 bash "$slurm/local-slurm.sh" start "$work/fresh-state"
  grep -q "munged.log: not written" "$work/err.log" || fail "the missing log is not named"
  bash "$slurm/local-slurm.sh" stop "$work/fresh-state" > /dev/null 2>&1
else
  echo "skipped: the failing-daemon case needs root and Debian's slurm-wlm and munge"
fi
[ $failed -eq 0 ] || exit 1
echo PASSED
