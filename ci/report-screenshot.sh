#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The first screen of a report as a reader sees it (headless Chromium, WIDTH × 900), for the README:
#   bash ci/report-screenshot.sh [REPORT_DIR] [OUT.png] [WIDTH]
#   (defaults: report, validation/report-first-screen.png, 1280; 800 shows a narrow window)
set -euo pipefail
cd "$(dirname "$0")/.."
report=${1:-report} out=${2:-validation/report-first-screen.png} width=${3:-1280}
case $width in ''|*[!0-9]*) echo "report-screenshot: WIDTH must be a number of pixels, got '$width'" >&2; exit 2 ;; esac
[ -f "$report/index.html" ] || { echo "report-screenshot: no $report/index.html (run bash ci/main.sh first)" >&2; exit 2; }
report=$(realpath "$report") out=$(realpath -m "$out") # relative or absolute, from the repository root
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run --user-data-dir="$profile" \
  --window-size="$width",900 --screenshot="$out" "file://$report/index.html" 2>/dev/null
echo "report-screenshot: $out"
