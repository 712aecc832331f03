#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# cmake --install of the library and the Python package into a temporary prefix: the installed package, put on
# PYTHONPATH as the README says, finds the installed library by itself (no $STIPPLE_LIBRARY, no build tree, no
# loader path) and serves samples equal to the build tree's library.
# Usage: check_installed.sh <build dir> <libstipple.so.1 of the build> <python3 with numpy>
set -euo pipefail
build=$1 library=$2 python=$3

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for component in stipple python; do
  cmake --install "$build" --component "$component" --prefix "$work/prefix" >>"$work/install.log" ||
    { cat "$work/install.log"; exit 1; }
done
site=$(find "$work/prefix" -type d -path '*/python3/site-packages' | head -n1)
if [ -z "$site" ] || [ ! -f "$site/stipple/_install_location.py" ]; then
  echo "check_installed: no stipple package with its install location under the prefix" >&2
  cat "$work/install.log"
  exit 1
fi

mkdir "$work/run"
cd "$work/run"
env -u STIPPLE_LIBRARY -u LD_LIBRARY_PATH PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 \
  "$python" - "$work/prefix" "$library" <<'PY'
import pathlib, sys
import numpy as np
import stipple

prefix, built = pathlib.Path(sys.argv[1]), sys.argv[2]
lib = stipple.Library()
assert pathlib.Path(lib.path).is_relative_to(prefix), f"loaded {lib.path}, not the installed library under {prefix}"
assert stipple.search_path()[0][0] == "installed prefix", stipple.search_path()
installed = lib.sampler("pmj02", 16, 3).pixels([[0, 0], [5, -7]], 2, 3)
reference = stipple.Library(built).sampler("pmj02", 16, 3).pixels([[0, 0], [5, -7]], 2, 3)
np.testing.assert_array_equal(installed, reference)
print(f"check_installed: {lib} found from the installed package")
PY
