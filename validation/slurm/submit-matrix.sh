#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Submits a validation matrix to Slurm as an array job, one task per shard, and a merge job that runs when every
# task has succeeded (--dependency=afterok). Every path is made absolute: the tasks, the merge job and the shared
# reference cache must see the same filesystem. The job scripts are fixed text: paths and counts reach them as
# exported variables (STIPPLE_*), never pasted into the script, so no path can run as code or split a word.
#
# usage: submit-matrix.sh MATRIX OUTDIR --tasks N [options] [-- extra sbatch options]
#   --tasks N         shards, 1..10000 (array tasks 1..N; each runs stipple-validate --shard i/N)
#   --threads T       CPUs per task and render threads, 1..1024 (default 2)
#   --mem MB          memory per task in MB, 1..10000000 (default 2000)
#   --time LIMIT      time limit per task, sbatch syntax such as 04:00:00 or 1-12:00:00 (default 04:00:00)
#   --cache DIR       shared reference cache (default OUTDIR/cache); the cache locks each entry while it renders
#   --indices LIST    resubmit only these tasks (e.g. 3,7-9), each within 1..N, of an earlier submission of the
#                     same N; the new merge job waits for them and merges all N shard folders
#   --bin PATH        stipple-validate (default: build/release/bin/stipple-validate of this repository)
#   --partition P     partition (default: the cluster's default)
#   --exclusive       one task per node: timing claims need quiet machines
#   --renderer PROGRAM, --renderer-command FILE, --allow-renderer, --renderer-timeout S
#                     passed to every task for a matrix with external renderers (see validation/README.md); the
#                     program and the file are made absolute (a bare program name is looked up on the task's PATH)
#   -- OPTIONS        more sbatch options for both jobs; not those this script sets (--array, --dependency,
#                     --output, --chdir, --export, --job-name, --cpus-per-task, --mem, --time, --parsable)
# Output: OUTDIR/shards/<i> (shard report folders), OUTDIR/logs/ (task logs), OUTDIR/report (the merged report,
# its status in logs/merge-<job>.out). Prints "array job <id>" and "merge job <id>"; with --parsable only
# "<array id> <merge id>". Exit status 2: a bad argument (named on stderr).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
usage() { sed -n '/^# usage:/,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
bad() { echo "submit-matrix: $*" >&2; exit 2; }

[ $# -ge 2 ] || usage
matrix=$1 out=$2
shift 2
[ -n "$matrix" ] && [ -n "$out" ] || bad "MATRIX and OUTDIR must not be empty"
tasks="" threads=2 mem=2000 limit=04:00:00 cache="" indices="" partition="" exclusive=0 parsable=0
renderer="" renderer_command="" allow_renderer=0 renderer_timeout=""
bin=$here/../../build/release/bin/stipple-validate
extra=()
while [ $# -gt 0 ]; do
    case "$1" in
        --tasks | --threads | --mem | --time | --cache | --indices | --bin | --partition)
            [ $# -ge 2 ] || bad "$1 needs a value"
            case "$1" in
                --tasks) tasks=$2 ;; --threads) threads=$2 ;; --mem) mem=$2 ;; --time) limit=$2 ;;
                --cache) cache=$2 ;; --indices) indices=$2 ;; --bin) bin=$2 ;; --partition) partition=$2 ;;
            esac
            shift 2 ;;
        --renderer | --renderer-command | --renderer-timeout)
            [ $# -ge 2 ] && [ -n "$2" ] || bad "$1 needs a value"
            case "$1" in
                --renderer) renderer=$2 ;; --renderer-command) renderer_command=$2 ;;
                --renderer-timeout) renderer_timeout=$2 ;;
            esac
            shift 2 ;;
        --allow-renderer) allow_renderer=1; shift ;;
        --exclusive) exclusive=1; shift ;;
        --parsable) parsable=1; shift ;;
        --) shift; extra=("$@"); break ;;
        *) echo "submit-matrix: unknown option '$1'" >&2; usage ;;
    esac
done
# Counts as decimal numbers of bounded length before any arithmetic (bash would wrap 99999999999999999999999).
in_range() { [[ "$2" =~ ^[1-9][0-9]{0,7}$ ]] && [ "$2" -le "$3" ] || bad "$1: expected an integer in [1, $3], got '$2'"; }
[ -n "$tasks" ] || bad "--tasks N (N >= 1) is required"
in_range --tasks "$tasks" 10000
in_range --threads "$threads" 1024
in_range --mem "$mem" 10000000
[[ "$limit" =~ ^([0-9]+-)?[0-9]+(:[0-9]{1,2}){0,2}$ ]] || bad "--time: expected a limit such as 04:00:00, got '$limit'"
[ -z "$partition" ] || [[ "$partition" =~ ^[A-Za-z0-9_.,-]+$ ]] || bad "--partition: expected a partition name, got '$partition'"
if [ -n "$indices" ]; then
    [[ "$indices" =~ ^[0-9]+(-[0-9]+)?(,[0-9]+(-[0-9]+)?)*$ ]] || bad "--indices: expected a list such as 3,7-9, got '$indices'"
    IFS=, read -ra ranges <<< "$indices"
    for r in "${ranges[@]}"; do
        lo=${r%-*} hi=${r#*-}
        for v in "$lo" "$hi"; do
            [[ "$v" =~ ^[1-9][0-9]{0,7}$ ]] && [ "$v" -le "$tasks" ] \
                || bad "--indices: task '$v' of '$indices' is not within 1..$tasks (--tasks)"
        done
        [ "$lo" -le "$hi" ] || bad "--indices: range '$r' runs backwards"
    done
fi
for x in "${extra[@]}"; do
    case "$x" in
        --array* | -a* | --dependency* | -d* | --output* | -o* | --chdir* | -D* | --export* | --job-name* | -J* | \
            --cpus-per-task* | -c* | --mem* | --time* | -t* | --parsable* | --wrap*)
            bad "extra sbatch option '$x' would override one this script sets" ;;
    esac
done
[ -f "$matrix" ] || bad "no matrix file '$matrix'"
# The renderer options are checked by stipple-validate itself; here only made absolute (tasks run elsewhere).
if [ -n "$renderer_command" ]; then
    [ -f "$renderer_command" ] || bad "--renderer-command: no file '$renderer_command'"
    renderer_command=$(realpath -- "$renderer_command")
fi
if [ -n "$renderer" ] && [[ "$renderer" == */* ]]; then
    [ -f "$renderer" ] || bad "--renderer: no file '$renderer'"
    renderer=$(realpath -- "$renderer")
fi
[ -z "$renderer_timeout" ] || [[ "$renderer_timeout" =~ ^[0-9]+(\.[0-9]+)?$ ]] \
    || bad "--renderer-timeout: expected seconds, got '$renderer_timeout'"
[ -x "$bin" ] && [ -f "$bin" ] || bad "stipple-validate not found at '$bin' (build it, or pass --bin)"

matrix=$(realpath -- "$matrix")
bin=$(realpath -- "$bin")
mkdir -p -- "$out"
out=$(realpath -- "$out")
cache=${cache:-$out/cache}
mkdir -p -- "$cache" "$out/shards" "$out/logs"
cache=$(realpath -- "$cache")

# What the job scripts read (sbatch --export=ALL hands the submitting environment to the jobs).
export STIPPLE_BIN=$bin STIPPLE_MATRIX=$matrix STIPPLE_OUT=$out STIPPLE_CACHE=$cache STIPPLE_TASKS=$tasks \
    STIPPLE_THREADS=$threads STIPPLE_RENDERER=$renderer STIPPLE_RENDERER_COMMAND=$renderer_command \
    STIPPLE_ALLOW_RENDERER=$allow_renderer STIPPLE_RENDERER_TIMEOUT=$renderer_timeout
common=(--parsable --export=ALL --chdir="$out")
[ -n "$partition" ] && common+=(--partition="$partition")

# One shard per array task: its own folder and thread count, the shared cache.
task_args=(--job-name=stipple-shard --array="${indices:-1-$tasks}" --cpus-per-task="$threads" --mem="$mem"
           --time="$limit" --output="$out/logs/shard-%A_%a.out")
[ "$exclusive" -eq 1 ] && task_args+=(--exclusive)
array=$(sbatch "${common[@]}" "${task_args[@]}" "${extra[@]}" <<'JOB'
#!/usr/bin/env bash
set -eu
i=$SLURM_ARRAY_TASK_ID
renderer=()
[ -z "${STIPPLE_RENDERER_COMMAND:-}" ] || renderer+=(--renderer-command "$STIPPLE_RENDERER_COMMAND")
[ -z "${STIPPLE_RENDERER:-}" ] || renderer+=(--renderer "$STIPPLE_RENDERER")
[ "${STIPPLE_ALLOW_RENDERER:-0}" != 1 ] || renderer+=(--allow-renderer)
[ -z "${STIPPLE_RENDERER_TIMEOUT:-}" ] || renderer+=(--renderer-timeout "$STIPPLE_RENDERER_TIMEOUT")
exec "$STIPPLE_BIN" "$STIPPLE_MATRIX" --shard "$i/$STIPPLE_TASKS" --threads "${SLURM_CPUS_PER_TASK:-$STIPPLE_THREADS}" \
    --cache "$STIPPLE_CACHE" -o "$STIPPLE_OUT/shards/$i" "${renderer[@]}"
JOB
)
array=${array%%;*}

# The merge: all N shard folders into the report; its exit status is the verdict of the matrix's checks.
merge=$(sbatch "${common[@]}" --job-name=stipple-merge --dependency=afterok:"$array" --cpus-per-task=1 \
    --mem="$mem" --time=00:30:00 --output="$out/logs/merge-%j.out" "${extra[@]}" <<'JOB'
#!/usr/bin/env bash
set -eu
folders=()
for ((i = 1; i <= STIPPLE_TASKS; i++)); do folders+=("$STIPPLE_OUT/shards/$i"); done
exec "$STIPPLE_BIN" "$STIPPLE_MATRIX" --merge "${folders[@]}" -o "$STIPPLE_OUT/report"
JOB
)
merge=${merge%%;*}

if [ "$parsable" -eq 1 ]; then
    echo "$array $merge"
else
    echo "array job $array: tasks ${indices:-1-$tasks} of $tasks, $threads CPUs and $mem MB each, logs in $out/logs"
    echo "merge job $merge: after the array succeeds, the report in $out/report"
fi
