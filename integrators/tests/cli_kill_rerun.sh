#!/bin/bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# stipple-render's outputs are all-or-nothing:
#  1. a scene whose name: is a path writes only <safe name>.exr/.png in the working folder;
#  2. SIGTERM at any moment of a run leaves no temporary and the EXR/PNG pair either both old or both new;
#  3. after SIGKILL (which no handler sees) the next run sweeps the dead run's temporaries;
#  4. a SIGKILL between the EXR and PNG renames (the state built exactly: both temporaries, the publish journal,
#     the EXR renamed) is finished by the next run's sweep: the new pair, no temporary, no journal.
# usage: cli_kill_rerun.sh STIPPLE_RENDER SCENE WORKDIR
set -u
exe=$1 scene=$2 work=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work/run/inner" "$work/out" || exit 1
cd "$work/run/inner" || exit 1

# 1. name: "../../escape/../x" must not leave the working folder.
sed 's|^name: .*|name: "../../escape/../x"|' "$scene" > evil.yaml
grep -q '^name: "../../escape' evil.yaml || fail "could not make the evil scene"
"$exe" evil.yaml --spp 1 --width 8 --height 8 --threads 1 > /dev/null || fail "evil scene did not render"
[ -f _.._escape_.._x.exr ] && [ -f _.._escape_.._x.png ] || fail "safe names not written: $(ls -a)"
[ -z "$(find "$work" -name 'x.exr' -o -name 'x.png' -o -name escape)" ] || fail "wrote outside the working folder"

temps() { find "$work/out" -name '*.stipple-tmp-*' | wc -l; }
sum() { md5sum < "$1" | cut -d' ' -f1; }
# exec: a backgrounded render's $! is then stipple-render itself, not a subshell around it.
render() { ( exec "$exe" "$scene" --spp 1 --width "$1" --height "$1" --seed "$2" --threads 2 -o "$work/out/img.exr" ); }
render_bg() { "$exe" "$scene" --spp 1 --width "$1" --height "$1" --seed "$2" --threads 2 -o "$work/out/img.exr" > /dev/null 2>&1 & }

# 2. An old pair, then SIGTERM during the render, as soon as the first temporary appears (the writing phase) and a
#    little after; each must leave no temporary and an old-old or new-new pair.
render 16 1 > /dev/null || fail "first render"
old_exr=$(sum "$work/out/img.exr") old_png=$(sum "$work/out/img.png")
wait_temp() { for _ in $(seq 3000); do [ "$(temps)" -gt 0 ] && return; kill -0 $1 2> /dev/null || return; sleep 0.003; done; }
for when in render write write+0.01 write+0.03 write+0.1; do
  render_bg 512 3; pid=$!
  case $when in
    render) sleep 0.3 ;;
    write) wait_temp $pid ;;
    write+*) wait_temp $pid; sleep "${when#write+}" ;;
  esac
  kill -TERM $pid 2> /dev/null; wait $pid; rc=$?
  [ "$(temps)" -eq 0 ] || fail "SIGTERM at $when (rc $rc) left temporaries: $(ls -a "$work/out")"
  e=$(sum "$work/out/img.exr") p=$(sum "$work/out/img.png")
  if { [ "$e" = "$old_exr" ] && [ "$p" != "$old_png" ]; } || { [ "$e" != "$old_exr" ] && [ "$p" = "$old_png" ]; }; then
    fail "SIGTERM at $when (rc $rc) left a mismatched EXR/PNG pair"
  fi
  echo "SIGTERM at $when: rc $rc, $([ "$e" = "$old_exr" ] && echo old || echo new) pair, no temporaries"
  render 16 1 > /dev/null; old_exr=$(sum "$work/out/img.exr") old_png=$(sum "$work/out/img.png")
done

# 3. SIGKILL: a dead run's temporaries (planted, as SIGKILL during a write leaves them) are swept by the next run;
#    a live process's temporaries are not.
true & dead=$!; wait $dead
host=$(hostname | tr -- '-/' '__')
touch "$work/out/.img.exr.stipple-tmp-$host-$dead-0.exr" "$work/out/.img.png.stipple-tmp-$host-$dead-1.png"
touch "$work/out/.img.exr.stipple-tmp-$host-$$-0.exr"  # this shell is alive: must stay
render_bg 512 4; pid=$!
wait_temp $pid; kill -KILL $pid 2> /dev/null; wait $pid
render 16 5 > /dev/null || fail "rerun after SIGKILL"
left=$(find "$work/out" -name '*.stipple-tmp-*' ! -name "*-$$-0.exr" | wc -l)
[ "$left" -eq 0 ] || fail "the rerun did not sweep dead temporaries: $(ls -a "$work/out")"
[ -f "$work/out/.img.exr.stipple-tmp-$host-$$-0.exr" ] || fail "the sweep removed a live process's temporary"

# 4. The interrupted publication. The journal's format is documented in publish_journal.h.
rm -f "$work/out/.img.exr.stipple-tmp-$host-$$-0.exr"
render 16 6 > /dev/null || fail "old pair for 4"
old_png=$(sum "$work/out/img.png")
mkdir -p "$work/new"
"$exe" "$scene" --spp 1 --width 16 --height 16 --seed 7 --threads 2 -o "$work/new/img.exr" > /dev/null || fail "new pair"
new_exr=$(sum "$work/new/img.exr") new_png=$(sum "$work/new/img.png")
[ "$new_png" != "$old_png" ] || fail "the new PNG equals the old one: the test would prove nothing"
true & dead=$!; wait $dead
t_exr=".img.exr.stipple-tmp-$host-$dead-0.exr" t_png=".img.png.stipple-tmp-$host-$dead-1.png"
cp "$work/new/img.exr" "$work/out/$t_exr" && cp "$work/new/img.png" "$work/out/$t_png" || fail "planting"
printf 'stipple-publish 1\n%d %d\n%s%s\n%d %d\n%s%s\nend\n' ${#t_exr} 7 "$t_exr" img.exr ${#t_png} 7 "$t_png" img.png \
  > "$work/out/.img.exr.publish.stipple-tmp-$host-$dead-2.publish"
mv "$work/out/$t_exr" "$work/out/img.exr"  # killed here: new EXR, old PNG
"$exe" "$scene" --print-layout -o "$work/out/img.exr" > /dev/null || fail "the run after the interrupted publication"
e=$(sum "$work/out/img.exr") p=$(sum "$work/out/img.png")
[ "$e" = "$new_exr" ] && [ "$p" = "$new_png" ] ||
  fail "after recovery: EXR $([ "$e" = "$new_exr" ] && echo new || echo other), PNG $([ "$p" = "$new_png" ] && echo new || echo old)"
[ "$(temps)" -eq 0 ] || fail "recovery left temporaries or the journal: $(ls -a "$work/out")"
echo "SIGKILL between the renames: the next run completed the new pair"
echo "PASS"
