#!/usr/bin/env bash
# The README's test command: install what is missing, configure, build and run the whole CTest suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh
export BOOST_TEST_COLOR_OUTPUT=no
cmake --preset release
cmake --build --preset release -j 2
ctest --preset release
