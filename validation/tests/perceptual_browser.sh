#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Runs perceptual_browser.py with a Python that has Debian's Selenium (python3-selenium; ci/install-deps.sh tests):
# the first of python3 on PATH and /usr/bin/python3 that imports it.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
for py in python3 /usr/bin/python3; do
  if "$py" -c "import selenium" 2>/dev/null; then
    exec "$py" "$here/perceptual_browser.py" "$@"
  fi
done
echo "perceptual_browser: no python3 with selenium (install python3-selenium chromium-driver: bash ci/install-deps.sh tests)" >&2
exit 1
