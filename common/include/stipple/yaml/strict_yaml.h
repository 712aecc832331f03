// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Strict YAML input for every file the project reads (scenes, validation matrices): positions as
// file:line:column, duplicate keys rejected (yaml-cpp keeps both silently), unknown keys named with the allowed
// ones, and one number parser (the whole scalar, finite) behind every numeric field.
#pragma once

#include <stipple/yaml/document.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace stipple::yaml {

// Bad input; the message starts with file:line:column.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class StrictYaml {
public:
    explicit StrictYaml(std::string file) : file_(std::move(file)) {}

    // Parses `text` (named file() in messages) into a compact Document; duplicate keys anywhere are errors.
    Node parse(const std::string& text) const;
    // Reads and parses the file named file().
    Node load() const;

    const std::string& file() const { return file_; }
    // "file:line:column" of the node, or "file" when it has no position.
    std::string where(const Node& node) const;
    [[noreturn]] void fail(const Node& node, const std::string& message) const;

    // A map's keys must be plain names from `allowed`; otherwise "unknown key 'k' in <context> (allowed: ...)".
    void onlyKeys(const Node& map, const std::vector<std::string>& allowed, const std::string& context) const;

    // The one number parser: the whole scalar must be a finite number (no trailing text, no nan/inf).
    // Sets `out` only when it returns Number::Ok.
    enum class Number { Ok, NotANumber, NotFinite };
    static Number parseNumber(const Node& node, double& out);
    // A whole-scalar integer in [lo, hi]; false otherwise.
    static bool parseInteger(const Node& node, long long& out);

    static std::string joined(const std::vector<std::string>& names);

private:
    std::string file_;
};

} // namespace stipple::yaml
