#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# stipple-render's command line on careless input, each case a usage error (exit 2) or a failure found before
# rendering, with a message naming what is wrong:
#  - empty values of --shim, --integrator, -o are errors, not the defaults (-o "" used to write into the
#    working folder);
#  - --exposure out of range names the range (1e308 used to say "expected a number"); a hex float is refused;
#  - an output folder that cannot take a file, and a broken $OCIO, fail before the render (not after it);
#  - -o naming the scene file itself is refused and the scene file stays;
#  - a scene with no emitter renders with a warning;
#  - --opt=value, --quiet (nothing on stdout) and --help listing every option with its default.
# usage: cli_hardening.sh STIPPLE_RENDER SCENE WORKDIR
set -u
bin=$1 scene=$2 work=$3
umount "$work/full" 2> /dev/null  # left mounted by an interrupted run
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
failed=0
fail() { echo "FAILED: $*"; failed=1; }
small=(--spp 1 --width 8 --height 8 --threads 2)
expect() {  # LABEL STATUS REGEX ARGS...
  local label=$1 status=$2 regex=$3; shift 3
  "$bin" "$@" > out.log 2> err.log; local rc=$?
  [ $rc -eq "$status" ] || { cat out.log err.log; fail "$label: exit $rc, expected $status"; return 1; }
  grep -qE -- "$regex" err.log || { cat err.log; fail "$label: stderr lacks /$regex/"; return 1; }
  echo "ok: $label: $(head -1 err.log)"
}
rendered() { grep -q "^render " out.log; }

expect "--shim \"\"" 2 "option --shim: expected a value, got an empty one" "$scene" --shim ""
expect "--integrator \"\"" 2 "option --integrator: expected a value, got an empty one" "$scene" --integrator ""
expect "-o \"\"" 2 "option -o: expected a value, got an empty one" "$scene" -o ""
ls ./*.exr > /dev/null 2>&1 && fail "-o \"\" wrote into the working folder: $(ls)"
expect "--exposure 1e308" 2 "option --exposure: expected a number in \[-64, 64\], got '1e308'" "$scene" --exposure 1e308
expect "--exposure 0x1p3" 2 "option --exposure: expected a decimal number, got '0x1p3'" "$scene" --exposure 0x1p3

expect "output folder missing" 1 "output .*missing/out.exr cannot be written \(checked before rendering\)" \
  "$scene" "${small[@]}" -o "$work/missing/out.exr" && { rendered && fail "rendered before finding the folder missing"; }
touch "$work/file"
expect "output folder is a file" 1 "cannot be written \(checked before rendering\)" \
  "$scene" "${small[@]}" -o "$work/file/out.exr" && { rendered && fail "rendered before finding the folder unusable"; }
echo "not: [a config" > "$work/broken.ocio"
OCIO="$work/broken.ocio" expect "broken \$OCIO" 1 "checked before rendering.*broken.ocio" \
  "$scene" "${small[@]}" -o "$work/ocio.exr" && { rendered && fail "rendered before finding \$OCIO broken"; }

cp "$scene" "$work/x.exr"
expect "-o the scene file" 2 "output .*x.exr is the scene file" "$work/x.exr" "${small[@]}" -o "$work/x.exr"
cmp -s "$scene" "$work/x.exr" || fail "the scene file was replaced"

sed -e '/emission/d' -e 's/^name: .*/name: dark/' "$scene" > "$work/dark.yaml"
grep -q emission "$work/dark.yaml" && fail "the test scene still has an emitter"
expect "no emitter" 0 "warning: scene dark has no emitter" "$work/dark.yaml" "${small[@]}" -o "$work/dark.exr"

"$bin" "$scene" --spp=1 --width=8 --height=8 --threads=2 -o "$work/quiet.exr" --quiet > out.log 2> err.log; rc=$?
[ $rc -eq 0 ] && [ ! -s out.log ] && [ -f "$work/quiet.exr" ] || { cat out.log err.log; fail "--opt=value --quiet: exit $rc"; }
echo "ok: --opt=value and --quiet (stdout empty)"

"$bin" --help > help.log 2>&1 || fail "--help failed"
for opt in --pattern --blue-noise --spp --seed --integrator --width --height --max-depth --threads --exposure --shim \
           --print-layout --output --quiet; do
  line=$(grep -A1 -- "^  .*$opt" help.log | tr '\n' ' ')
  [ -n "$line" ] && grep -q "default" <<<"$line" || fail "--help does not describe $opt with its default"
done
echo "ok: --help describes every option with its default"
# A full disk is named as such (OIIO's own message says only that the write failed): a 256 KiB tmpfs filled to
# 8 KiB free, as root; elsewhere skipped.
if [ "$(id -u)" -eq 0 ] && mkdir -p "$work/full" && mount -t tmpfs -o size=256k tmpfs "$work/full" 2> /dev/null; then
  dd if=/dev/zero of="$work/full/filler" bs=4k count=62 status=none 2> /dev/null
  expect "full disk" 1 "no space left on device\\? [0-9]+ bytes free" "$scene" --spp 1 --width 128 --height 128 \
    --threads 2 -o "$work/full/out.exr"
  ls -a "$work/full" | grep -q stipple-tmp && fail "a temporary was left on the full disk"
  umount "$work/full"
else
  echo "skipped: the full-disk case needs root (to mount a small tmpfs)"
fi
[ $failed -eq 0 ] || exit 1
echo PASSED
