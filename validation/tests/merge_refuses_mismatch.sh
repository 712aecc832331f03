#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# --merge must refuse shards that ran different matrices or builds, naming the first differing fingerprint field,
# both values and both shard folders. Shard 1/2 always runs the base matrix; shard 2/2 runs a variant (image size,
# max depth, reference spp, the scene file's content) or has its recorded renderer version edited. A control pair
# of the base matrix must merge; extra, duplicate and missing rows are refused.
# usage: merge_refuses_mismatch.sh STIPPLE_VALIDATE SCENE_FILE WORKDIR
set -eu
bin=$1 scene=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cache="$work/cache"
failures=0

# matrix FILE SCENE W H DEPTH REF_SPP: a tiny matrix (8 renders of a few pixels per shard pair).
matrix() {
  cat > "$1" <<YAML
name: fingerprint
scenes:
  - { file: $2, name: box, width: $3, height: $4, max_depth: $5 }
patterns: [independent, stratified]
spp: [1]
seeds: 4
reference: { spp: $6, seed: 777 }
YAML
}
cp "$scene" "$work/box.yaml"
matrix "$work/base.yaml" box.yaml 8 8 2 8

shard() { # matrix shard-folder i/n
  "$bin" "$1" -o "$2" --cache "$cache" --threads 1 --shard "$3" > "$2.log" 2>&1 \
    || { echo "FAILED: shard $3 of $1 exited $? (log $2.log)"; cat "$2.log"; exit 1; }
}
# expect_refusal NAME FIELD VALUE1 VALUE2: merges base shard 1 with NAME's shard 2; exit 3 and the message.
expect_refusal() {
  local name=$1 field=$2 v1=$3 v2=$4 status=0
  "$bin" "$work/base.yaml" -o "$work/merged-$name" --merge "$work/s1" "$work/$name" > "$work/merged-$name.log" 2>&1 \
    || status=$?
  local want="differ first in $field: $v1 ($work/s1) vs $v2 ($work/$name)"
  if [ "$status" -ne 3 ]; then
    echo "FAILED ($name): merge exited $status, expected 3"; cat "$work/merged-$name.log"; failures=$((failures + 1))
  elif ! grep -qF -- "$want" "$work/merged-$name.log"; then
    echo "FAILED ($name): the message does not say: $want"; cat "$work/merged-$name.log"; failures=$((failures + 1))
  elif [ -e "$work/merged-$name/results.json" ]; then
    echo "FAILED ($name): a refused merge wrote a report"; failures=$((failures + 1))
  else
    echo "ok ($name): $(grep -F 'differ first' "$work/merged-$name.log")"
  fi
}

shard "$work/base.yaml" "$work/s1" 1/2
shard "$work/base.yaml" "$work/s2" 2/2

# Control: the same matrix merges (exit 0: the matrix has no checks).
"$bin" "$work/base.yaml" -o "$work/merged-same" --merge "$work/s1" "$work/s2" > "$work/merged-same.log" 2>&1 \
  || { echo "FAILED: shards of one matrix did not merge"; cat "$work/merged-same.log"; exit 1; }
grep -q '"renderer.version"' "$work/s1/results.json" || { echo "FAILED: no fingerprint in results.json"; exit 1; }

matrix "$work/size.yaml" box.yaml 16 8 2 8
shard "$work/size.yaml" "$work/size" 2/2
expect_refusal size scene.box.width 8 16

matrix "$work/depth.yaml" box.yaml 8 8 3 8
shard "$work/depth.yaml" "$work/depth" 2/2
expect_refusal depth scene.box.max_depth 2 3

matrix "$work/refspp.yaml" box.yaml 8 8 2 16
shard "$work/refspp.yaml" "$work/refspp" 2/2
expect_refusal refspp scene.box.reference_spp 8 16

# The scene file edited between the two shards (a comment: same pixels, yet another file): shard 2 runs the same
# matrix text beside its own copy of the scene.
mkdir -p "$work/edited"
cp "$scene" "$work/edited/box.yaml"
echo "# edited" >> "$work/edited/box.yaml"
cp "$work/base.yaml" "$work/edited/base.yaml"
shard "$work/edited/base.yaml" "$work/content" 2/2
hash() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["fingerprint"]["scene.box.content_hash"])' "$1"; }
hash1=$(hash "$work/s1/results.json") hash2=$(hash "$work/content/results.json")
expect_refusal content scene.box.content_hash "\"$hash1\"" "\"$hash2\""

# Another renderer build: the shard's recorded renderer version edited, as a shard of an older build would read.
cp -r "$work/s2" "$work/renderer"
python3 - "$work/renderer/results.json" <<'PY'
import json, sys
p = sys.argv[1]
r = json.load(open(p))
r["fingerprint"]["renderer.version"] = "stipple-render 0.9.0"
json.dump(r, open(p, "w"), indent=2)
PY
version=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["fingerprint"]["renderer.version"])' "$work/s1/results.json")
expect_refusal renderer renderer.version "\"$version\"" '"stipple-render 0.9.0"'

# The shards agree, but --merge is given an edited matrix: the first differing matrix field names the matrix file.
sed 's/seeds: 4/seeds: [1, 2, 3, 5]/' "$work/base.yaml" > "$work/other-seeds.yaml"
status=0
"$bin" "$work/other-seeds.yaml" -o "$work/merged-other" --merge "$work/s1" "$work/s2" > "$work/merged-other.log" 2>&1 \
  || status=$?
if [ "$status" -ne 3 ] || ! grep -qF "differ first in matrix.seeds: [1,2,3,4] ($work/s1) vs [1,2,3,5] ($work/other-seeds.yaml)" "$work/merged-other.log"; then
  echo "FAILED (merge matrix): exit $status"; cat "$work/merged-other.log"; failures=$((failures + 1))
else
  echo "ok (merge matrix): $(grep -F 'differ first' "$work/merged-other.log")"
fi

# Rows: an extra one (a seed the matrix does not have), a shard given twice (duplicates), a shard left out.
cp -r "$work/s2" "$work/extra"
python3 - "$work/extra/results.json" <<'PY'
import json, sys
p = sys.argv[1]
r = json.load(open(p))
row = dict(r["rows"][0]); row["seed"] = 99
r["rows"].append(row)
json.dump(r, open(p, "w"), indent=2)
PY
expect_rows() { # name expected-message folders...
  local name=$1 want=$2 status=0
  shift 2
  "$bin" "$work/base.yaml" -o "$work/merged-$name" --merge "$@" > "$work/merged-$name.log" 2>&1 || status=$?
  if [ "$status" -ne 3 ] || ! grep -qE -- "$want" "$work/merged-$name.log"; then
    echo "FAILED ($name): exit $status, expected 3 and /$want/"; cat "$work/merged-$name.log"; failures=$((failures + 1))
  else
    echo "ok ($name): $(tail -n 1 "$work/merged-$name.log")"
  fi
}
expect_rows extra "extra: box .* spp seed 99 is not a cell × seed of" "$work/s1" "$work/extra"
expect_rows duplicate "appears in two shards" "$work/s1" "$work/s2" "$work/s1"
expect_rows missing "cell × seed rows of .* are in none of the folders" "$work/s1"

[ "$failures" -eq 0 ] || { echo "FAILED: $failures mismatches were not refused as expected"; exit 1; }
echo "PASSED: every mismatch refused, naming the field, both values and both folders"
