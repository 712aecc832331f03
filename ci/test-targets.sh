#!/usr/bin/env bash
# The build targets a selection of CTest tests runs, one per line, for `cmake --build --target`: so that a stage
# that runs some of the tests (the sanitizer stages) builds those and nothing else.
#
#   bash ci/test-targets.sh BUILD_DIR [ctest selection: -L, -LE, -R, -E ...]
#
# A test's targets are the programs and libraries of the build tree its command names (BUILD_DIR/bin/<target>,
# BUILD_DIR/lib/lib<target>.so...; stipple_add_test names every program by its $<TARGET_FILE>), plus libstipple,
# which every host dlopens. BUILD_DIR must be configured.
set -euo pipefail
dir=$(cd "$1" && pwd)
shift
ctest --test-dir "$dir" --show-only=json-v1 "$@" | python3 -c '
import json, re, sys
root = re.escape(sys.argv[1])
program = re.compile(root + r"/bin/([A-Za-z0-9_.+-]+)")
library = re.compile(root + r"/lib/lib([A-Za-z0-9_+-]+)\.so")
targets = {"stipple"}
for test in json.load(sys.stdin)["tests"]:
    for word in test.get("command", []):
        targets.update(program.findall(word))
        targets.update(library.findall(word))
print("\n".join(sorted(targets)))
' "$dir"
