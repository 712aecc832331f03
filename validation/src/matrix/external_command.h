// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The command template of an external renderer (external_renderer.h): an argument vector whose arguments may
// hold placeholders {scene}, {pattern}, {spp}, {seed}, {width}, {height}, {output}. Each placeholder is replaced
// inside its own argument: an argument never splits, nothing is interpreted (no shell, no quoting, no globbing).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace stipple::validation {

// The placeholders a command template may use.
const std::vector<std::string>& externalPlaceholders();

// "" when the template is valid: a program first, every {name} a known placeholder, braces balanced, {output} in
// some argument. Else what is wrong, naming the argument.
std::string checkCommandTemplate(const std::vector<std::string>& command);

// "" when `value` may fill a placeholder: non-empty, not starting with '-' (it cannot be read as an option) and
// without control characters (no newline, no NUL). Else why not.
std::string checkPlaceholderValue(const std::string& value);

// The argument vector with every placeholder replaced by its value (name -> value); the template is valid.
// Throws std::runtime_error when a value fails checkPlaceholderValue: a matrix never adds an option this way.
std::vector<std::string> expandCommand(const std::vector<std::string>& command,
                                       const std::vector<std::pair<std::string, std::string>>& values);

// The command templates the command line trusts (--renderer-command FILE): one argument per line, verbatim (no
// quoting, no trimming); a blank line ends a template; a line starting with '#' is a comment. Each template is
// checked as checkCommandTemplate does. Throws std::runtime_error naming "file:line: what" on a bad file; `path`
// names the file in messages.
std::vector<std::vector<std::string>> parseTrustedCommands(const std::string& text, const std::string& path);
// Reads and parses the file (a regular file of at most 1 MiB).
std::vector<std::vector<std::string>> readTrustedCommands(const std::string& path);

} // namespace stipple::validation
