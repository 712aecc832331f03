#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
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
# ctest selects the tests; their commands are read from the CTestTestfile.cmake files (ctest leaves out the command
# of a test whose program is not built yet).
ctest --test-dir "$dir" --show-only=json-v1 "$@" | python3 -c '
import json, pathlib, re, sys
root = sys.argv[1]
selected = {t["name"] for t in json.load(sys.stdin)["tests"]}
program = re.compile(re.escape(root) + r"/bin/([A-Za-z0-9_+-][A-Za-z0-9_.+-]*)")  # not bin/.. or bin/.
library = re.compile(re.escape(root) + r"/lib/lib([A-Za-z0-9_+-]+)[.]so")
registration = re.compile(r"^add_test\(\[=\[(.*?)\]=\] (.*)\)$")
targets = {"stipple"}
for testfile in pathlib.Path(root).rglob("CTestTestfile.cmake"):
    for line in testfile.read_text().splitlines():
        match = registration.match(line)
        if match and match.group(1) in selected:
            targets.update(program.findall(match.group(2)))
            targets.update(library.findall(match.group(2)))
print("\n".join(sorted(targets)))
' "$dir"
