// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// gnuplot as the report's plotter: its single-quoted strings, and one script run in a folder without a shell, so
// that any file name works in both.
#pragma once

#include <string>

namespace stipple::validation {

// s as a single-quoted gnuplot string (a quote doubled, nothing else special).
std::string gnuplotQuoted(const std::string& s);

// Runs `gnuplot <script>` in `dir` with its stderr to `<dir>/<log>`. Returns gnuplot's exit status, or -1 when it
// could not be started or did not exit.
int runGnuplot(const std::string& dir, const std::string& script, const std::string& log);

} // namespace stipple::validation
