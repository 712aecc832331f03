#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Installs the package the way its README says — a fresh virtual environment of Debian's python3 that sees the
# system's NumPy, pip offline without build isolation — from a copy of the source (the library given through
# STIPPLE_LIBRARY at install time only), then runs the README's example with the installed package (not the
# source) and no environment variable: the package must carry the library it was built with.
# Usage: check_pip_install.sh <package source folder> <libstipple.so.1> <python3 with numpy>
set -euo pipefail
source_dir=$1 library=$(realpath "$2") python=$3

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$source_dir" "$work/package"
rm -rf "$work/package/build" "$work/package/src/"*.egg-info

"$python" -m venv --system-site-packages "$work/venv" ||
  { echo "check_pip_install: python3 -m venv failed (Debian: python3-venv, python3-pip)" >&2; exit 1; }
PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1 STIPPLE_LIBRARY="$library" \
  "$work/venv/bin/pip" install --quiet --no-build-isolation "$work/package"

# The README's first python block, run from an empty folder so only the installed package can be imported.
sed -n '/^```python$/,/^```$/{/^```/d;p}' "$source_dir/README.md" > "$work/example.py"
[ -s "$work/example.py" ] || { echo "check_pip_install: no python block in README.md" >&2; exit 1; }
mkdir "$work/run"
cd "$work/run"
unset STIPPLE_LIBRARY STIPPLE_SHIM
installed=$("$work/venv/bin/python" -c 'import stipple; print(stipple.__file__, stipple.Library().path)')
case $installed in
  "$work/venv/"*" $work/venv/"*/stipple/_lib/libstipple.so.1) ;;
  *) echo "check_pip_install: stipple and its library came from $installed, not the virtual environment" >&2
     exit 1 ;;
esac
output=$("$work/venv/bin/python" "$work/example.py")
echo "$output"
grep -q "^pi/4 = 0.78540, mean estimate 0.78" <<<"$output" ||
  { echo "check_pip_install: the README example printed an unexpected estimate" >&2; exit 1; }
echo "check_pip_install: installed into a fresh virtual environment offline; the README example ran with the library the package carries"
