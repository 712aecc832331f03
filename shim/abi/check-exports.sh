#!/usr/bin/env bash
# Checks the product's surface: the dynamic symbol table defines only stipple_* functions (plus the STIPPLE_1.0
# version node), every stipple_* function of the header is exported, and the SONAME is libstipple.so.1.
#   usage: check-exports.sh <libstipple.so.1> <stipple.h>
set -euo pipefail
lib="$1" header="$2"
status=0
defined="$(nm -D --defined-only "$lib" | awk '{print $NF}' | sed 's/@.*//')"
echo "exported symbols:"; echo "$defined" | sed 's/^/  /'
stray="$(echo "$defined" | grep -v -E '^(stipple_[a-z_]+|STIPPLE_1\.0)$' || true)"
if [ -n "$stray" ]; then echo "FAIL: symbols outside stipple_*:"; echo "$stray"; status=1; fi
declared=0
for fn in $(grep -o -E 'STIPPLE_API [^(]*\b(stipple_[a-z_]+)\(' "$header" | grep -o -E 'stipple_[a-z_]+\($' | tr -d '('); do
  declared=$((declared + 1))
  if ! echo "$defined" | grep -qx "$fn"; then echo "FAIL: $fn is declared in the header but not exported"; status=1; fi
done
echo "functions declared in the header: $declared (checked above)"
versioned="$(nm -D --defined-only "$lib" | grep -c '@@STIPPLE_1.0' || true)"
echo "symbols under version node STIPPLE_1.0: $versioned"
soname="$(readelf -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')"
echo "SONAME: $soname"
if [ "$soname" != "libstipple.so.1" ]; then echo "FAIL: SONAME is '$soname', expected libstipple.so.1"; status=1; fi
exit $status
