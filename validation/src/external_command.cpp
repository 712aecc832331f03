// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "external_command.h"

#include <algorithm>

namespace stipple::validation {

const std::vector<std::string>& externalPlaceholders() {
    static const std::vector<std::string> names = {"scene", "pattern", "spp", "seed", "width", "height", "output"};
    return names;
}

namespace {

// Calls f(name, open, close) for each {name} of an argument; returns "" or what is malformed (or what f says).
template <typename F>
std::string forEachPlaceholder(const std::string& argument, F&& f) {
    for (size_t i = 0; i < argument.size(); ++i) {
        if (argument[i] == '}') return "a '}' without its '{'";
        if (argument[i] != '{') continue;
        const size_t close = argument.find('}', i);
        if (close == std::string::npos) return "a '{' without its '}'";
        const std::string name = argument.substr(i + 1, close - i - 1);
        if (name.find('{') != std::string::npos) return "a '{' inside a placeholder";
        if (std::string why = f(name, i, close); !why.empty()) return why;
        i = close;
    }
    return "";
}

} // namespace

std::string checkCommandTemplate(const std::vector<std::string>& command) {
    if (command.empty() || command[0].empty()) return "the command needs a program (its first argument)";
    const auto& known = externalPlaceholders();
    bool output = false;
    for (size_t a = 0; a < command.size(); ++a) {
        const std::string why = forEachPlaceholder(command[a], [&](const std::string& name, size_t, size_t) {
            if (std::find(known.begin(), known.end(), name) == known.end()) {
                std::string list;
                for (const auto& k : known) list += (list.empty() ? "{" : ", {") + k + "}";
                return "unknown placeholder {" + name + "} (known: " + list + ")";
            }
            output |= name == "output";
            return std::string();
        });
        if (!why.empty()) return "argument " + std::to_string(a) + " '" + command[a] + "': " + why;
    }
    if (command[0].find('{') != std::string::npos) return "the program (argument 0) cannot be a placeholder";
    if (!output) return "no argument has {output}: the run could not find the image";
    return "";
}

std::vector<std::string> expandCommand(const std::vector<std::string>& command,
                                       const std::vector<std::pair<std::string, std::string>>& values) {
    std::vector<std::string> argv;
    for (const std::string& a : command) {
        std::string out;
        size_t from = 0;
        forEachPlaceholder(a, [&](const std::string& name, size_t open, size_t close) {
            out += a.substr(from, open - from);
            for (const auto& [key, value] : values)
                if (key == name) out += value;
            from = close + 1;
            return std::string();
        });
        argv.push_back(out + a.substr(from));
    }
    return argv;
}

} // namespace stipple::validation
