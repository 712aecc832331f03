#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# stipple-validate driving an external renderer (shim/examples/analytic_host) through a matrix's command template.
#  1. The matrix with --renderer PROGRAM: checks pass, report and results.json as for any matrix, every cell's CPU
#     seconds measured from the child; a second run reads the reference from the cache.
#  2. The same matrix without --renderer or --allow-renderer runs nothing and says how to allow it.
#  3. Bad templates (unknown placeholder, no {output}) are refused when the matrix is read, naming file:line.
#  4. Renderers that exit non-zero, crash, write no image or an image of the wrong size, and a placeholder whose
#     value would mean something to a shell: each scene skipped with an error naming its cell; the rest completes.
#  5. The report speaks of an external renderer (no triangle count, times with start-up); a renderer that maps
#     every seed to one value (its reference's halves bitwise equal) or the cells' seeds to one value (their images
#     equal): an error naming the seeds, exit status 3.
# usage: external_renderer.sh STIPPLE_VALIDATE ANALYTIC_HOST MATRIX_DIR WORKDIR
set -u
bin=$1 host=$2 dir=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
ok=1
fail() { echo "FAILED: $*"; ok=0; }
run() { local log=$1; shift; (cd "$work" && "$@") > "$log" 2>&1; echo "exit $?" >> "$log"; }

# 1. A passing run, then the same from the cache.
run "$work/good.log" "$bin" "$dir/external-renderer.yaml" -o "$work/good" --cache "$work/cache" --renderer "$host"
cat "$work/good.log"
[ "$(tail -1 "$work/good.log")" = "exit 0" ] || fail "the external-renderer matrix did not pass"
grep -qE "3 checks, 0 failed" "$work/good.log" || fail "not 3 checks passed"
[ -f "$work/good/index.html" ] || fail "no report"
rows=$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(len(r["rows"]), sum(1 for x in r["rows"] if x["cpu_seconds"] > 0), r["scenes"][0]["integrator"])' "$work/good/results.json")
[ "$rows" = "36 36 external: analytic_host" ] || fail "results.json rows / cpu-timed rows / integrator: $rows (expected 36 36 external: analytic_host)"
run "$work/again.log" "$bin" "$dir/external-renderer.yaml" -o "$work/again" --cache "$work/cache" --renderer "$host"
grep -qE "cached:" "$work/again.log" || fail "the second run did not read the reference from the cache"
! grep -q " triangles" "$work/good/index.html" || fail "the report counts triangles for an external renderer"
grep -q "start-up and scene load included" "$work/good/index.html" || fail "the report's times assume stipple-render"

# 5. Seeds that collapse: a wrapper that keeps no seed, then one that maps the cells' seeds (1..4) to 1.
for kind in none cells; do
  wrapper="$work/seed-$kind.sh"
  {
    echo '#!/usr/bin/env bash'
    echo 'args=(); while [ $# -gt 0 ]; do'
    if [ $kind = none ]; then echo '  if [ "$1" = --seed ]; then args+=(--seed 7); shift 2; continue; fi'
    else echo '  if [ "$1" = --seed ] && [ "$2" -lt 1000 ]; then args+=(--seed 1); shift 2; continue; fi'; fi
    echo '  args+=("$1"); shift; done'
    echo "exec \"$host\" \"\${args[@]}\""
  } > "$wrapper"
  chmod +x "$wrapper"
  run "$work/seed-$kind.log" "$bin" "$dir/external-renderer.yaml" -o "$work/seed-$kind" --cache "$work/cache-$kind" \
    --renderer "$wrapper"
  [ "$(tail -1 "$work/seed-$kind.log")" = "exit 3" ] || fail "seeds mapped to one value ($kind): not exit 3"
done
grep -q "the reference's two halves (seeds 99991 and [0-9]*, 512 spp) are bitwise equal" "$work/seed-none.log" ||
  fail "equal reference halves not named: $(grep -m1 stipple-validate "$work/seed-none.log")"
grep -q "lights, independent, 4 spp: bitwise-equal images from seeds 1, 2, 3, 4" "$work/seed-cells.log" ||
  fail "equal cell images not named: $(grep -m1 bitwise "$work/seed-cells.log")"

# 2. No permission: nothing runs.
run "$work/denied.log" "$bin" "$dir/external-renderer.yaml" -o "$work/denied" --cache "$work/cache-denied"
cat "$work/denied.log"
[ "$(tail -1 "$work/denied.log")" = "exit 3" ] || fail "a matrix alone ran (or failed otherwise): $(tail -1 "$work/denied.log")"
grep -q -- "--allow-renderer" "$work/denied.log" || fail "the refusal does not say how to allow the renderer"
[ ! -d "$work/cache-denied" ] || [ -z "$(ls -A "$work/cache-denied")" ] || fail "a reference was made without permission"

# 3. Bad templates, refused when read.
run "$work/placeholder.log" "$bin" "$dir/bad-placeholder.yaml" -o "$work/placeholder" --renderer "$host"
grep -qE "bad-placeholder.yaml:[0-9]+:[0-9]+: argument 4 '\{sample_count\}': unknown placeholder \{sample_count\}" \
  "$work/placeholder.log" || fail "unknown placeholder not named: $(cat "$work/placeholder.log")"
[ "$(tail -1 "$work/placeholder.log")" = "exit 2" ] || fail "unknown placeholder: not exit 2"
run "$work/nooutput.log" "$bin" "$dir/no-output.yaml" -o "$work/nooutput" --renderer "$host"
grep -qE "no-output.yaml:[0-9]+:[0-9]+: no argument has \{output\}" "$work/nooutput.log" || fail "missing {output} not named"
[ "$(tail -1 "$work/nooutput.log")" = "exit 2" ] || fail "missing {output}: not exit 2"

# 4. Failing renderers beside a working one (programs found on PATH, as the matrix names them).
run "$work/failing.log" env PATH="$(dirname "$host"):$PATH" "$bin" "$dir/failing-renderers.yaml" -o "$work/failing" \
  --cache "$work/cache" --allow-renderer
cat "$work/failing.log"
[ "$(tail -1 "$work/failing.log")" = "exit 3" ] || fail "failing renderers: not exit 3"
for pattern in \
  "scene exits, independent, 32 spp, seed [0-9]+ .*exited with status 2; its output ends: analytic_host: unknown option --no-such-option" \
  "scene crashes, independent, 32 spp, seed [0-9]+ .*killed by signal 11" \
  "scene writes-nothing, .*exited with status 0 but wrote no image" \
  "scene wrong-size, .*the image is 6x8; the matrix asks for 8x6" \
  "scene quoted, .*exited with status 1; its output ends: analytic_host: stipple_pattern_parse: name is \"independent ; touch injected\""; do
  grep -qE -- "$pattern" "$work/failing.log" || fail "output lacks /$pattern/"
done
[ ! -e "$work/injected" ] || fail "a placeholder's value was interpreted by a shell"
python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); s={x["scene"] for x in r["rows"]}; k={x["name"] for x in r["skipped_scenes"]}; sys.exit(0 if s=={"works"} and k=={"exits","crashes","writes-nothing","wrong-size","quoted"} and len(r["rows"])==8 else 1)' \
  "$work/failing/results.json" || fail "results.json: the working scene's 8 rows and the 5 skipped scenes expected"

[ $ok -eq 1 ] && echo "PASSED: external renderer driven, refused without permission, bad templates and failing renderers named"
[ $ok -eq 1 ]
