#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# stipple-validate driving an external renderer (shim/examples/analytic_host) through a matrix's command template.
#  1. The matrix with --renderer PROGRAM and the template file (--renderer-command): checks pass, report and results.json as for any matrix, every cell's CPU
#     seconds measured from the child; a second run reads the reference from the cache.
#  2. The same matrix without --renderer or --allow-renderer runs nothing and says how to allow it.
#  3. Bad templates (unknown placeholder, no {output}) are refused when the matrix is read, naming file:line.
#  4. Renderers that exit non-zero, crash, write no image or an image of the wrong size, and a placeholder whose
#     value would mean something to a shell: each scene skipped with an error naming its cell; the rest completes.
#  5. The trusted side alone says what a program receives: a matrix that adds arguments to an allowed template
#     (here '--output <a user's file>') is refused before anything runs and the file is untouched; a {scene} that
#     starts with '-' or holds a newline is refused at load with file:line:column; --renderer without a template
#     file, or with a matrix that has no external scene, is a usage error (exit 2).
#  6. No verdict from a broken image: a renderer whose stratified images are all NaN ends with the cells named as
#     unmeasurable (exit 3), never a PASS of "stratified < independent".
#  7. Every cache entry verifies: the variance copied over the image, or a FIFO in its place, is rendered again
#     (no hang); a folder of the program's name earlier on PATH does not change the key (the cache is used).
#  8. -o made into a user's folder during the run is left untouched, the new report kept beside it (exit 3);
#     --references-only with a failing renderer says so (exit 3).
#  9. A PFM header claiming 60000x60000 is refused by its size; a failing renderer's 300 MB log is read from its
#     end: peak memory stays under 200 MB.
# 10. The report speaks of an external renderer (no triangle count, times with start-up); a renderer that maps
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
run "$work/good.log" "$bin" "$dir/external-renderer.yaml" -o "$work/good" --cache "$work/cache" --renderer "$host" --renderer-command "$dir/analytic-host.command"
cat "$work/good.log"
[ "$(tail -1 "$work/good.log")" = "exit 0" ] || fail "the external-renderer matrix did not pass"
grep -qE "3 checks, 0 failed" "$work/good.log" || fail "not 3 checks passed"
[ -f "$work/good/index.html" ] || fail "no report"
rows=$(python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); print(len(r["rows"]), sum(1 for x in r["rows"] if x["cpu_seconds"] > 0), r["scenes"][0]["integrator"])' "$work/good/results.json")
[ "$rows" = "36 36 external: analytic_host" ] || fail "results.json rows / cpu-timed rows / integrator: $rows (expected 36 36 external: analytic_host)"
run "$work/again.log" "$bin" "$dir/external-renderer.yaml" -o "$work/again" --cache "$work/cache" --renderer "$host" --renderer-command "$dir/analytic-host.command"
grep -qE "cached:" "$work/again.log" || fail "the second run did not read the reference from the cache"
! grep -q " triangles" "$work/good/index.html" || fail "the report counts triangles for an external renderer"
grep -q "start-up and scene load included" "$work/good/index.html" || fail "the report's times assume stipple-render"

# 10. Seeds that collapse: a wrapper that keeps no seed, then one that maps the cells' seeds (1..4) to 1.
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
    --renderer "$wrapper" --renderer-command "$dir/analytic-host.command"
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
run "$work/placeholder.log" "$bin" "$dir/bad-placeholder.yaml" -o "$work/placeholder" --renderer "$host" \
  --renderer-command "$dir/analytic-host.command"
grep -qE "bad-placeholder.yaml:[0-9]+:[0-9]+: argument 4 '\{sample_count\}': unknown placeholder \{sample_count\}" \
  "$work/placeholder.log" || fail "unknown placeholder not named: $(cat "$work/placeholder.log")"
[ "$(tail -1 "$work/placeholder.log")" = "exit 2" ] || fail "unknown placeholder: not exit 2"
run "$work/nooutput.log" "$bin" "$dir/no-output.yaml" -o "$work/nooutput" --renderer "$host" \
  --renderer-command "$dir/analytic-host.command"
grep -qE "no-output.yaml:[0-9]+:[0-9]+: no argument has \{output\}" "$work/nooutput.log" || fail "missing {output} not named"
[ "$(tail -1 "$work/nooutput.log")" = "exit 2" ] || fail "missing {output}: not exit 2"

# 4. Failing renderers beside a working one (programs found on PATH, as the matrix names them).
run "$work/failing.log" env PATH="$(dirname "$host"):$PATH" "$bin" "$dir/failing-renderers.yaml" -o "$work/failing" \
  --cache "$work/cache" --allow-renderer --renderer-command "$dir/failing-renderers.commands"
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

# 5. A matrix can fill placeholders, nothing else.
mkdir -p "$work/trust" && cp "$dir/analytic-lights.scene" "$work/trust/lights.scene"
echo "a user's file" > "$work/trust/victim.txt"
template='[analytic_host, --pattern, "{pattern}", --spp, "{spp}", --seed, "{seed}", --width, "{width}", --height, "{height}", --output, "{output}"'
matrix() { # name scene-file command-tail
  printf 'name: %s\nscenes:\n  - { file: "%s", name: s, width: 8, height: 6, renderer: { command: %s, format: pfm } }\npatterns: [independent]\nspp: [4]\nseeds: 4\nreference: { spp: 16, seed: 7 }\n' \
    "$1" "$2" "$3" > "$work/trust/$1.yaml"
}
matrix escape lights.scene "$template, --output, $work/trust/victim.txt]"
(cd "$work/trust" && "$bin" escape.yaml -o "$work/trust/out-escape" --renderer "$host" \
  --renderer-command "$dir/analytic-host.command") > "$work/escape.log" 2>&1; echo "exit $?" >> "$work/escape.log"
[ "$(tail -1 "$work/escape.log")" = "exit 2" ] || fail "a matrix that adds arguments was not refused with exit 2: $(cat "$work/escape.log")"
grep -qE "escape.yaml:[0-9]+:[0-9]+: scene s: the command .* is not one the command line allows" "$work/escape.log" ||
  fail "the refusal does not name the matrix's template: $(cat "$work/escape.log")"
[ "$(cat "$work/trust/victim.txt")" = "a user's file" ] || fail "the user's file was changed"
cp "$work/trust/lights.scene" "$work/trust/-lights.scene"
matrix dash -lights.scene "$template]"
(cd "$work/trust" && "$bin" dash.yaml -o "$work/trust/out-dash" --renderer "$host" \
  --renderer-command "$dir/analytic-host.command") > "$work/dash.log" 2>&1; echo "exit $?" >> "$work/dash.log"
grep -qE "dash.yaml:[0-9]+:[0-9]+: the scene file '-lights.scene' cannot fill \{scene\}: it starts with '-'" "$work/dash.log" ||
  fail "a {scene} starting with '-' was not refused at load: $(cat "$work/dash.log")"
[ "$(tail -1 "$work/dash.log")" = "exit 2" ] || fail "a {scene} starting with '-': not exit 2"
cp "$work/trust/lights.scene" "$work/trust/new
line.scene"
matrix newline 'new\nline.scene' "$template]"
(cd "$work/trust" && "$bin" newline.yaml -o "$work/trust/out-nl" --renderer "$host" \
  --renderer-command "$dir/analytic-host.command") > "$work/newline.log" 2>&1; echo "exit $?" >> "$work/newline.log"
grep -qE "newline.yaml:[0-9]+:[0-9]+: the scene file" "$work/newline.log" &&
  grep -qE "cannot fill \{scene\}: it holds a control character" "$work/newline.log" ||
  fail "a {scene} with a newline was not refused at load: $(cat "$work/newline.log")"
run "$work/notemplate.log" "$bin" "$dir/external-renderer.yaml" -o "$work/notemplate" --renderer "$host"
[ "$(tail -1 "$work/notemplate.log")" = "exit 2" ] || fail "--renderer without --renderer-command: not exit 2"
grep -q -- "--renderer-command" "$work/notemplate.log" || fail "--renderer without a template file: no word of --renderer-command"
run "$work/unused.log" "$bin" "$dir/../matrices/cache.yaml" -o "$work/unused" --renderer "$host" \
  --renderer-command "$dir/analytic-host.command"
[ "$(tail -1 "$work/unused.log")" = "exit 2" ] || fail "--renderer with no external scene: not exit 2: $(cat "$work/unused.log")"
grep -q "no scene of .* has an external renderer" "$work/unused.log" || fail "an unused --renderer not named"
[ ! -e "$work/unused/index.html" ] || fail "an unused --renderer still made a report"

# 6. Images of stratified cells with no finite pixel.
cat > "$work/nan-host.sh" << EOF
#!/bin/sh
"$host" "\$@" || exit \$?
case " \$* " in *" stratified "*) ;; *) exit 0 ;; esac
while [ \$# -gt 1 ]; do [ "\$1" = --output ] && out=\$2; shift; done
python3 -c 'import struct,sys; open(sys.argv[1],"wb").write(b"PF\\n16 12\\n-1.0\\n" + struct.pack("<f", float("nan")) * (16*12*3))' "\$out"
EOF
chmod +x "$work/nan-host.sh"
run "$work/nan.log" "$bin" "$dir/external-renderer.yaml" -o "$work/nan" --cache "$work/cache" \
  --renderer "$work/nan-host.sh" --renderer-command "$dir/analytic-host.command"
[ "$(tail -1 "$work/nan.log")" = "exit 3" ] || fail "NaN images: not exit 3: $(tail -5 "$work/nan.log")"
grep -qE "stratified, [0-9]+ spp, seed [0-9]+: the image cannot be measured: no pixel is finite" "$work/nan.log" ||
  fail "the NaN cell is not named as unmeasurable"
! grep -qE "PASS +ordering" "$work/nan.log" || fail "a PASS from NaN images: $(grep -E "PASS" "$work/nan.log")"

# 7. Tampered cache entries of the external reference (the cache of step 1).
entry=$(sed -n 's/.*cached: \(.*\)\.exr, noise floor.*/\1/p' "$work/again.log" | head -1) # step 1's entry
cp "$entry-variance.exr" "$entry.exr"
run "$work/tamper.log" "$bin" "$dir/external-renderer.yaml" -o "$work/tamper" --cache "$work/cache" \
  --renderer "$host" --renderer-command "$dir/analytic-host.command"
grep -q "did not verify (the pixels do not match their checksums)" "$work/tamper.log" ||
  fail "the variance copied over the image was not caught: $(grep -E "cached|rendered" "$work/tamper.log")"
rm "$entry.exr" && mkfifo "$entry.exr"
timeout 120 "$bin" "$dir/external-renderer.yaml" -o "$work/fifo" --cache "$work/cache" --renderer "$host" \
  --renderer-command "$dir/analytic-host.command" > "$work/fifo.log" 2>&1
rc=$?
[ $rc -ne 124 ] || fail "a FIFO in the cache hung the run"
grep -q "is not a regular file" "$work/fifo.log" || fail "the FIFO in the cache was not named: $(tail -3 "$work/fifo.log")"
[ -f "$entry.exr" ] && [ ! -p "$entry.exr" ] || fail "the FIFO entry was not replaced"
mkdir -p "$work/shadow/analytic_host"
(cd "$work" && env PATH="$(dirname "$host"):$PATH" "$bin" "$dir/external-renderer.yaml" -o "$work/shadow-out" \
  --cache "$work/cache" --renderer analytic_host --renderer-command "$dir/analytic-host.command") > /dev/null 2>&1
(cd "$work" && env PATH="$work/shadow:$(dirname "$host"):$PATH" "$bin" "$dir/external-renderer.yaml" -o "$work/shadow-out" \
  --cache "$work/cache" --renderer analytic_host --renderer-command "$dir/analytic-host.command") > "$work/shadow.log" 2>&1
grep -q "cached:" "$work/shadow.log" ||
  fail "a folder named like the program earlier on PATH changed the key: $(grep -E "cached|rendered|ERROR" "$work/shadow.log")"

# A FIFO given as the program is refused at once (it was opened to be hashed, and hung).
mkfifo -m 755 "$work/fifo-host"
timeout 60 "$bin" "$dir/external-renderer.yaml" -o "$work/fifo-prog" --cache "$work/cache" --renderer "$work/fifo-host" \
  --renderer-command "$dir/analytic-host.command" > "$work/fifo-prog.log" 2>&1
rc=$?
[ $rc -eq 3 ] || fail "a FIFO as --renderer: exit $rc, expected 3"
grep -q "which is not a regular file" "$work/fifo-prog.log" || fail "a FIFO as --renderer not named: $(tail -2 "$work/fifo-prog.log")"

# 8. -o filled by someone else during the run; --references-only with a failing renderer.
cat > "$work/fill-host.sh" << EOF
#!/bin/sh
mkdir -p "$work/filled" && echo "a user's notes" > "$work/filled/notes.txt"
exec "$host" "\$@"
EOF
chmod +x "$work/fill-host.sh"
run "$work/filled.log" "$bin" "$dir/external-renderer.yaml" -o "$work/filled" --cache "$work/cache" \
  --renderer "$work/fill-host.sh" --renderer-command "$dir/analytic-host.command"
[ "$(cat "$work/filled/notes.txt" 2> /dev/null)" = "a user's notes" ] || fail "the user's file in -o was deleted"
[ ! -e "$work/filled/index.html" ] || fail "the report was swapped into a folder that changed during the run"
[ "$(tail -1 "$work/filled.log")" = "exit 3" ] || fail "-o changed during the run: not exit 3: $(tail -3 "$work/filled.log")"
grep -q "changed during the run" "$work/filled.log" || fail "the refusal to publish is not explained"
ls -d "$work"/filled.unpublished-*/index.html > /dev/null 2>&1 || fail "the staged report was not kept"
printf '#!/bin/sh\nexit 7\n' > "$work/fail-host.sh" && chmod +x "$work/fail-host.sh"
run "$work/refonly.log" "$bin" "$dir/external-renderer.yaml" --references-only --cache "$work/cache-refonly" \
  --renderer "$work/fail-host.sh" --renderer-command "$dir/analytic-host.command"
[ "$(tail -1 "$work/refonly.log")" = "exit 3" ] || fail "--references-only with a failed reference: $(tail -1 "$work/refonly.log")"
! grep -q "references ready" "$work/refonly.log" || fail "--references-only says ready after a failure"

# 9. Memory bounded by the matrix, not by a file or a child: a PFM whose header claims 60000x60000 is refused by
#    its size before any allocation; a failing renderer's 300 MB log is read from its end (peak RSS of the run).
cat > "$work/liar-host.sh" << EOF
#!/bin/sh
while [ \$# -gt 1 ]; do [ "\$1" = --output ] && out=\$2; shift; done
printf 'PF\\n60000 60000\\n-1.0\\n12345678' > "\$out"
EOF
cat > "$work/chatty-host.sh" << EOF
#!/bin/sh
head -c 300000000 /dev/zero | tr '\\0' x
echo "the last words"
exit 2
EOF
chmod +x "$work/liar-host.sh" "$work/chatty-host.sh"
for h in liar chatty; do
  python3 -c 'import resource,subprocess,sys; r=subprocess.run(sys.argv[1:]); print("exit", r.returncode, "maxrss_kib", resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)' \
    "$bin" "$dir/external-renderer.yaml" -o "$work/$h" --cache "$work/cache-$h" --renderer "$work/$h-host.sh" \
    --renderer-command "$dir/analytic-host.command" > "$work/$h.log" 2>&1
done
grep -q "the image is 60000x60000; the matrix asks for 16x12" "$work/liar.log" ||
  fail "a lying PFM header was not refused by its size: $(grep -E "ERROR" "$work/liar.log" | head -1)"
grep -q "its output ends: \.\.\.x*" "$work/chatty.log" && grep -q "the last words" "$work/chatty.log" ||
  fail "the end of a long log was not shown"
for h in liar chatty; do
  rss=$(sed -n 's/^exit [0-9]* maxrss_kib //p' "$work/$h.log")
  [ -n "$rss" ] && [ "$rss" -lt 200000 ] || fail "$h renderer: peak RSS ${rss:-?} KiB (expected < 200 MB)"
done

[ $ok -eq 1 ] && echo "PASSED: external renderer driven, refused without permission, bad templates and failing renderers named, matrix arguments refused, NaN images and tampered caches caught, -o rechecked"
[ $ok -eq 1 ]
