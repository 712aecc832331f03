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

// The argument vector with every placeholder replaced by its value (name -> value); the template is valid.
std::vector<std::string> expandCommand(const std::vector<std::string>& command,
                                       const std::vector<std::pair<std::string, std::string>>& values);

} // namespace stipple::validation
