#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# Makes a small report, copies its folder elsewhere (it must be self-contained) and checks the copy in headless
# Chromium (report_browser.py). usage: report_browser.sh STIPPLE_VALIDATE MATRIX WORKDIR
set -u
validate=$1 matrix=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
chromium=$(command -v chromium || command -v chromium-browser) || { echo "FAILED: no chromium (ci/install-deps.sh installs it)"; exit 1; }
rm -rf "$work/report" "$work/moved"
mkdir -p "$work"
"$validate" "$matrix" -o "$work/report" --cache "$work/cache" --threads 2 > "$work/run.log" 2>&1
status=$?
[ $status -le 1 ] || { cat "$work/run.log"; echo "FAILED: stipple-validate exit status $status"; exit 1; }
cp -r "$work/report" "$work/moved"
python3 "$here/report_browser.py" "$chromium" "$work/moved" "$work"
