// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "matrix/external_command.h"

#include <algorithm>
#include <stdexcept>

#include <stipple/render/input_limits.h>

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

std::string checkPlaceholderValue(const std::string& value) {
    if (value.empty()) return "it is empty";
    if (value[0] == '-') return "it starts with '-' (a program would read it as an option)";
    for (unsigned char c : value)
        if (c < 0x20 || c == 0x7f) return "it holds a control character (a newline, tab or NUL)";
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
                if (key == name) {
                    if (const std::string why = checkPlaceholderValue(value); !why.empty())
                        throw std::runtime_error("the value of {" + name + "}, '" + value + "', cannot be passed: " +
                                                 why);
                    out += value;
                }
            from = close + 1;
            return std::string();
        });
        argv.push_back(out + a.substr(from));
    }
    return argv;
}

std::vector<std::vector<std::string>> parseTrustedCommands(const std::string& text, const std::string& path) {
    std::vector<std::vector<std::string>> commands;
    std::vector<std::string> current;
    size_t firstLine = 0, line = 0, from = 0;
    auto finish = [&] {
        if (current.empty()) return;
        if (const std::string why = checkCommandTemplate(current); !why.empty())
            throw std::runtime_error(path + ":" + std::to_string(firstLine) + ": " + why);
        commands.push_back(std::move(current));
        current.clear();
    };
    while (from < text.size()) {
        size_t end = text.find('\n', from);
        if (end == std::string::npos) end = text.size();
        const std::string argument = text.substr(from, end - from);
        from = end + 1;
        ++line;
        if (argument.empty()) {
            finish();
            continue;
        }
        if (argument[0] == '#') continue;
        for (unsigned char c : argument)
            if (c < 0x20 || c == 0x7f)
                throw std::runtime_error(path + ":" + std::to_string(line) +
                                         ": a control character in an argument (a carriage return?)");
        if (current.empty()) firstLine = line;
        current.push_back(argument);
    }
    finish();
    if (commands.empty()) throw std::runtime_error(path + ": no command template (one argument per line)");
    return commands;
}

std::vector<std::vector<std::string>> readTrustedCommands(const std::string& path) {
    return parseTrustedCommands(render::readFileBounded(path, 1u << 20, "renderer command file"), path);
}

} // namespace stipple::validation
