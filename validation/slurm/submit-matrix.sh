#!/usr/bin/env bash
# Submits a validation matrix to Slurm as an array job, one task per shard, and a merge job that runs when every
# task has succeeded (--dependency=afterok). Every path is made absolute: the tasks, the merge job and the shared
# reference cache must see the same filesystem.
#
# usage: submit-matrix.sh MATRIX OUTDIR --tasks N [options] [-- extra sbatch options]
#   --tasks N         shards (array tasks 1..N; each runs stipple-validate --shard i/N)
#   --threads T       CPUs per task and render threads (default 2)
#   --mem MB          memory per task (default 2000)
#   --time LIMIT      time limit per task, sbatch syntax (default 04:00:00)
#   --cache DIR       shared reference cache (default OUTDIR/cache); the cache locks each entry while it renders
#   --indices LIST    resubmit only these tasks (e.g. 3,7-9) of an earlier submission of the same N; the new
#                     merge job waits for them and merges all N shard folders
#   --bin PATH        stipple-validate (default: build/release/bin/stipple-validate of this repository)
#   --partition P     partition (default: the cluster's default)
#   --exclusive       one task per node: timing claims need quiet machines
# Output: OUTDIR/shards/<i> (shard report folders), OUTDIR/logs/ (task logs), OUTDIR/report (the merged report,
# its status in logs/merge-<job>.out). Prints "array job <id>" and "merge job <id>"; with --parsable only
# "<array id> <merge id>".
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
usage() { sed -n '/^# usage:/,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

[ $# -ge 2 ] || usage
matrix=$1 out=$2
shift 2
tasks="" threads=2 mem=2000 limit=04:00:00 cache="" indices="" partition="" exclusive=0 parsable=0
bin=$here/../../build/release/bin/stipple-validate
extra=()
while [ $# -gt 0 ]; do
    case "$1" in
        --tasks) tasks=$2; shift 2 ;;
        --threads) threads=$2; shift 2 ;;
        --mem) mem=$2; shift 2 ;;
        --time) limit=$2; shift 2 ;;
        --cache) cache=$2; shift 2 ;;
        --indices) indices=$2; shift 2 ;;
        --bin) bin=$2; shift 2 ;;
        --partition) partition=$2; shift 2 ;;
        --exclusive) exclusive=1; shift ;;
        --parsable) parsable=1; shift ;;
        --) shift; extra=("$@"); break ;;
        *) echo "submit-matrix: unknown option '$1'" >&2; usage ;;
    esac
done
[[ "$tasks" =~ ^[1-9][0-9]*$ ]] || { echo "submit-matrix: --tasks N (N >= 1) is required" >&2; exit 2; }
[[ "$threads" =~ ^[1-9][0-9]*$ ]] || { echo "submit-matrix: --threads: expected a count, got '$threads'" >&2; exit 2; }
[ -f "$matrix" ] || { echo "submit-matrix: no matrix file '$matrix'" >&2; exit 2; }
[ -x "$bin" ] || { echo "submit-matrix: stipple-validate not found at '$bin' (build it, or pass --bin)" >&2; exit 2; }

matrix=$(realpath "$matrix")
bin=$(realpath "$bin")
mkdir -p "$out"
out=$(realpath "$out")
cache=${cache:-$out/cache}
mkdir -p "$cache" "$out/shards" "$out/logs"
cache=$(realpath "$cache")

common=(--parsable --export=ALL --chdir="$out")
[ -n "$partition" ] && common+=(--partition="$partition")

# One shard per array task: its own folder and thread count, the shared cache.
task_args=(--job-name=stipple-shard --array="${indices:-1-$tasks}" --cpus-per-task="$threads" --mem="$mem"
           --time="$limit" --output="$out/logs/shard-%A_%a.out")
[ "$exclusive" -eq 1 ] && task_args+=(--exclusive)
array=$(sbatch "${common[@]}" "${task_args[@]}" "${extra[@]}" <<JOB
#!/usr/bin/env bash
set -eu
i=\$SLURM_ARRAY_TASK_ID
exec "$bin" "$matrix" --shard "\$i/$tasks" --threads "\${SLURM_CPUS_PER_TASK:-$threads}" --cache "$cache" \\
    -o "$out/shards/\$i"
JOB
)
array=${array%%;*}

# The merge: all N shard folders into the report; its exit status is the verdict of the matrix's checks.
folders=""
for i in $(seq 1 "$tasks"); do folders+=" \"$out/shards/$i\""; done
merge=$(sbatch "${common[@]}" --job-name=stipple-merge --dependency=afterok:"$array" --cpus-per-task=1 \
    --mem="$mem" --time=00:30:00 --output="$out/logs/merge-%j.out" "${extra[@]}" <<JOB
#!/usr/bin/env bash
exec "$bin" "$matrix" --merge$folders -o "$out/report"
JOB
)
merge=${merge%%;*}

if [ "$parsable" -eq 1 ]; then
    echo "$array $merge"
else
    echo "array job $array: tasks ${indices:-1-$tasks} of $tasks, $threads CPUs and $mem MB each, logs in $out/logs"
    echo "merge job $merge: after the array succeeds, the report in $out/report"
fi
