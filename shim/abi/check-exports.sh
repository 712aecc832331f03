#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Checks the product's surface: the dynamic symbol table defines only stipple_* functions (plus the STIPPLE_1.x
# version nodes), every stipple_* function of the header is exported, and the SONAME is libstipple.so.1.
#   usage: check-exports.sh <libstipple.so.1> <stipple.h>
set -euo pipefail
lib="$1" header="$2"
status=0
defined="$(nm -D --defined-only "$lib" | awk '{print $NF}' | sed 's/@.*//')"
echo "exported symbols:"; echo "$defined" | sed 's/^/  /'
stray="$(echo "$defined" | grep -v -E '^(stipple_[a-z_]+|STIPPLE_1\.[0-9]+)$' || true)"
if [ -n "$stray" ]; then echo "FAIL: symbols outside stipple_*:"; echo "$stray"; status=1; fi
declared=0
# Here-strings, not pipes: under pipefail, grep -q exiting at its match can fail the writer with SIGPIPE.
for fn in $(grep -o -E 'STIPPLE_API [^(]*\b(stipple_[a-z_]+)\(' "$header" | grep -o -E 'stipple_[a-z_]+\($' | tr -d '('); do
  declared=$((declared + 1))
  if ! grep -qx "$fn" <<< "$defined"; then echo "FAIL: $fn is declared in the header but not exported"; status=1; fi
done
echo "functions declared in the header: $declared (checked above)"
for node in STIPPLE_1.0 STIPPLE_1.1; do
  echo "symbols under version node $node: $(nm -D --defined-only "$lib" | grep -c "@@$node\$" || true)"
done
# A stipple_* function with no version node would bind to whatever a host's first definition is.
unversioned="$(nm -D --defined-only "$lib" | grep ' stipple_' | grep -v '@@STIPPLE_1\.' || true)"
if [ -n "$unversioned" ]; then echo "FAIL: unversioned symbols:"; echo "$unversioned"; status=1; fi
soname="$(readelf -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')"
echo "SONAME: $soname"
if [ "$soname" != "libstipple.so.1" ]; then echo "FAIL: SONAME is '$soname', expected libstipple.so.1"; status=1; fi
exit $status
