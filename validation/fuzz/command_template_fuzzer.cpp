// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// command_template_fuzzer.cpp — libFuzzer harness of an external renderer's command template and its placeholders
// (external_command.h). The input up to its first NUL is a --renderer-command file; the rest, split at NULs, is a
// template followed by a value for each placeholder. Expected: a list of templates or a std::runtime_error
// naming "file:line"; every template accepted is valid (checkCommandTemplate); an expansion keeps the template's
// argument count, its arguments without placeholders byte for byte, and never passes a value that is empty,
// starts with '-' or holds a control character (it throws instead). Any other exception, a crash or a sanitizer
// report is a finding.
#include "matrix/external_command.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

void require(bool condition) {
    if (!condition) __builtin_trap();
}

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> parts;
    size_t from = 0;
    for (size_t at; (at = text.find('\0', from)) != std::string::npos; from = at + 1)
        parts.push_back(text.substr(from, at - from));
    parts.push_back(text.substr(from));
    return parts;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 16384) return 0;
    using namespace stipple::validation;
    const std::string input(reinterpret_cast<const char*>(data), size);
    const size_t nul = input.find('\0');
    try {
        for (const auto& t : parseTrustedCommands(input.substr(0, nul), "fuzz.command"))
            require(checkCommandTemplate(t).empty());
    } catch (const std::runtime_error& e) {
        require(std::string(e.what()).rfind("fuzz.command:", 0) == 0);
    }
    if (nul == std::string::npos) return 0;
    std::vector<std::string> parts = split(input.substr(nul + 1));
    const auto& names = externalPlaceholders();
    if (parts.size() <= names.size()) return 0;
    std::vector<std::pair<std::string, std::string>> values;
    for (size_t i = 0; i < names.size(); ++i) values.emplace_back(names[i], parts[parts.size() - names.size() + i]);
    parts.resize(parts.size() - names.size());
    if (!checkCommandTemplate(parts).empty()) return 0;
    bool valuesOk = true;
    for (const auto& [name, value] : values) valuesOk = valuesOk && checkPlaceholderValue(value).empty();
    try {
        const std::vector<std::string> argv = expandCommand(parts, values);
        require(argv.size() == parts.size());
        for (size_t i = 0; i < parts.size(); ++i)
            if (parts[i].find('{') == std::string::npos) require(argv[i] == parts[i]);
        require(argv[0] == parts[0]); // the program is never a placeholder
    } catch (const std::runtime_error& e) {
        require(!valuesOk); // only a value that cannot be passed is refused
        require(std::string(e.what()).rfind("the value of {", 0) == 0);
    }
    return 0;
}
