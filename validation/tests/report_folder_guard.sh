#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Only a folder stipple-validate made is ever replaced, and --merge copies only what it should:
#  - a folder with an index.html, results.json and other files (a website) is refused with exit 2, untouched;
#  - --merge -o onto (or around) one of its own shard folders is refused with exit 2, the shard untouched;
#  - -o through a symlink to a report publishes into the folder it points to and keeps the link;
#  - empty values of -o, --cache and --baseline are usage errors (exit 2), not the defaults;
#  - --merge copies only the crops the rows name, regular files only: a crop symlinked to a private file is
#    not copied, a symlinked folder is skipped with a warning (no raw filesystem error);
#  - --merge refuses rows no measurement could give (negative RMS, a time < 0, a size against the scene's);
#  - another user's temporary beside the report folder is left alone and named in a warning (as root only);
#  - a full disk under the report folder is named in the error (as root only: a small tmpfs).
# usage: report_folder_guard.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
bin=$1 matrix=$2 work=$3
umount "$work/full" 2> /dev/null  # left mounted by an interrupted run
rm -rf "$work" && mkdir -p "$work" || exit 1
failed=0
fail() { echo "FAILED: $*"; failed=1; }  # every case is tried, so a run lists all that fail
die() { echo "FAILED: $*"; exit 1; }
run() { "$bin" "$matrix" --cache "$work/cache" --threads 2 "$@" > "$work/log" 2>&1; }
expect2() {  # LABEL REGEX ARGS...
  local label=$1 regex=$2; shift 2
  run "$@"; local rc=$?
  [ $rc -eq 2 ] || { cat "$work/log"; fail "$label: exit $rc, expected 2"; return; }
  grep -qE -- "$regex" "$work/log" || { cat "$work/log"; fail "$label: message lacks /$regex/"; return; }
  echo "ok: $label: $(grep stipple-validate "$work/log" | head -1)"
}
snapshot() { (cd "$1" && find . | sort && find . -type f | sort | xargs md5sum); }

# A website folder that happens to hold index.html and results.json.
mkdir -p "$work/site/src" && echo '<html>' > "$work/site/index.html" && echo '{}' > "$work/site/results.json"
echo 'int main() {}' > "$work/site/src/main.c" && echo notes > "$work/site/notes.txt"
site=$(snapshot "$work/site")
expect2 "-o a folder stipple-validate did not make" "not a report folder" -o "$work/site"
[ "$(snapshot "$work/site")" = "$site" ] || fail "the website folder was changed"

for opt in -o --output= --cache --baseline; do
  if [ "${opt: -1}" = "=" ]; then expect2 "$opt empty" "expected a value, got an empty one" "$opt"
  else expect2 "$opt \"\"" "expected a value, got an empty one" "$opt" ""; fi
done

# Two shards, then the merge guards.
rm -rf "$work/s1" "$work/s2"
run -o "$work/s1" --shard 1/2 || { cat "$work/log"; die "shard 1"; }
run -o "$work/s2" --shard 2/2 || { cat "$work/log"; die "shard 2"; }
[ -f "$work/s1/.stipple-report" ] || fail "a report folder lacks its .stipple-report marker"
# A report of an earlier version (no marker, exactly a report's files) is replaced; one file more and it is not.
cp -r "$work/s1" "$work/old" && rm -rf "$work/old/.stipple-report" "$work/old/exr" # 1.1 wrote no exr/
run -o "$work/old" --shard 1/2 || { cat "$work/log"; fail "a report without the marker (an earlier version's) was refused"; }
[ -f "$work/old/.stipple-report" ] || fail "the earlier report was not replaced"
cp -r "$work/s1" "$work/old2" && rm "$work/old2/.stipple-report" && echo mine > "$work/old2/crops/notes.txt"
expect2 "-o a report folder with a file no report has" "not a report folder" -o "$work/old2" --shard 1/2
[ -f "$work/old2/crops/notes.txt" ] || fail "the extra file was removed"
s1=$(snapshot "$work/s1")
expect2 "--merge -o onto its own shard" "overlaps the shard folder" -o "$work/s1" --merge "$work/s1" "$work/s2"
expect2 "--merge -o around its own shard" "overlaps the shard folder" -o "$work" --merge "$work/s1" "$work/s2"
[ "$(snapshot "$work/s1")" = "$s1" ] || fail "a shard folder was changed"

# Crops: a symlink to a private file under a crop's own name, a symlinked folder, a stray file.
echo secret > "$work/private.txt" && chmod 600 "$work/private.txt"
cp -r "$work/s1" "$work/h1"
crop=$(cd "$work/h1/crops" && ls *-independent.png 2> /dev/null | head -1)
[ -n "$crop" ] || die "shard 1 made no crop of independent"
rm "$work/h1/crops/$crop" && ln -s "$work/private.txt" "$work/h1/crops/$crop"
ln -s /etc "$work/h1/crops/etc" && echo stray > "$work/h1/crops/stray.png"
run -o "$work/merged" --merge "$work/h1" "$work/s2"; rc=$?
grep -q "filesystem error" "$work/log" && { cat "$work/log"; fail "a raw filesystem error"; }
[ $rc -le 1 ] || { cat "$work/log"; fail "merge with hostile crops: exit $rc"; }
[ ! -e "$work/merged/crops/$crop" ] || ! grep -q secret "$work/merged/crops/$crop" || fail "the private file was copied"
[ ! -e "$work/merged/crops/etc" ] && [ ! -e "$work/merged/crops/stray.png" ] || fail "crops no row names were copied"
grep -q "left .*$crop alone" "$work/log" || { cat "$work/log"; fail "no warning names the symlinked crop"; }
echo "ok: --merge copies only the named crops, regular files only"

# -o through a symlink to a report folder: the report lands in the target, the link stays.
ln -s "$work/merged" "$work/link"
run -o "$work/link" --merge "$work/s1" "$work/s2" || [ $? -eq 1 ] || { cat "$work/log"; fail "merge into a symlink"; }
[ -L "$work/link" ] || fail "the symlink was replaced by a folder"
[ -f "$work/merged/crops/$crop" ] && ! grep -q secret "$work/merged/crops/$crop" || fail "the report did not land in the link's target"
ls -a "$work" | grep -q stipple-tmp && fail "a temporary was left: $(ls -a "$work")"
echo "ok: -o through a symlink publishes into its target"

# Rows no measurement could give.
for edit in 's/"rms": [0-9.e+-]*/"rms": -0.5/' 's/"render_seconds": [0-9.e+-]*/"render_seconds": -1/' \
            's/"width": \([0-9]*\)/"width": 999/'; do
  rm -rf "$work/bad" && cp -r "$work/s1" "$work/bad" && sed -i "$edit" "$work/bad/results.json"
  run -o "$work/merged-bad" --merge "$work/bad" "$work/s2"; rc=$?
  [ $rc -ne 0 ] && [ $rc -ne 1 ] || { cat "$work/log"; fail "merge accepted a row edited by '$edit'"; }
  grep -qE "results.json: cornell .*(not a finite value|not the square root|not a time|not the scene's)" "$work/log" \
    || { cat "$work/log"; fail "no message for '$edit'"; }
  echo "ok: refused: $(grep -o 'results.json: .*' "$work/log" | head -1)"
done

# Another user's temporary beside the report folder (its pid dead on this host) is left alone, with a warning.
if [ "$(id -u)" -eq 0 ]; then
  planted="$work/.merged.stipple-tmp-$(hostname | tr '/-' '__')-999999999-0"
  mkdir "$planted" && echo theirs > "$planted/f" && chown -R nobody "$planted"
  run -o "$work/merged" --merge "$work/s1" "$work/s2" || [ $? -eq 1 ] || { cat "$work/log"; fail "merge beside a foreign temporary"; }
  [ -f "$planted/f" ] || fail "another user's temporary folder was removed"
  grep -q "left $planted alone: owned by uid" "$work/log" || { cat "$work/log"; fail "no warning names it"; }
  echo "ok: another user's temporary is left alone and named"
  rm -rf "$planted"
else
  echo "skipped: the foreign-owner case needs root (to create a file owned by nobody)"
fi

# A full disk under the report folder is named (the writers' own messages do not say why), as root only.
if [ "$(id -u)" -eq 0 ] && mkdir -p "$work/full" && mount -t tmpfs -o size=256k tmpfs "$work/full" 2> /dev/null; then
  dd if=/dev/zero of="$work/full/filler" bs=4k count=62 status=none 2> /dev/null
  run -o "$work/full/report"; rc=$?
  [ $rc -eq 3 ] && grep -q "no space left on device? [0-9]* bytes free" "$work/log" \
    || { cat "$work/log"; fail "a full disk is not named (exit $rc)"; }
  [ ! -e "$work/full/report" ] && [ -z "$(ls -A "$work/full" | grep -v filler)" ] || fail "the full disk kept a half report"
  echo "ok: a full disk: $(grep -o 'no space left on device?.*' "$work/log" | head -1)"
  umount "$work/full"
else
  echo "skipped: the full-disk case needs root (to mount a small tmpfs)"
fi

# --opt=value and --quiet.
run -o "$work/quiet" --quiet --threads=2 --shard=1/2; rc=$?
[ $rc -eq 0 ] && [ ! -s "$work/log" ] || { cat "$work/log"; fail "--quiet printed something or failed (exit $rc)"; }
[ -f "$work/quiet/index.html" ] || fail "--quiet wrote no report"
echo "ok: --opt=value and --quiet"
[ $failed -eq 0 ] || exit 1
echo PASSED
