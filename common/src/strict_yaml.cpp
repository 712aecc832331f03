// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include <stipple/yaml/strict_yaml.h>
#include <stipple/render/input_limits.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace stipple::yaml {

std::string StrictYaml::where(const Node& node) const {
    const Mark m = node.Mark();
    if (m.line < 0) return file_;
    return file_ + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

void StrictYaml::fail(const Node& node, const std::string& message) const { throw Error(where(node) + ": " + message); }

Node StrictYaml::parse(const std::string& text) const {
    std::shared_ptr<const Document> doc;
    try {
        doc = Document::parse(text);
    } catch (const DocumentError& e) {
        const std::string at =
            e.mark.line < 0 ? file_
                            : file_ + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1);
        switch (e.kind) {
        case DocumentError::Kind::TooDeep: throw Error(at + ": YAML nested deeper than the parser's limit");
        case DocumentError::Kind::Syntax: throw Error(at + ": YAML syntax error: " + e.what());
        case DocumentError::Kind::DuplicateKey: throw Error(at + ": " + e.what());
        case DocumentError::Kind::Other: break;
        }
        throw Error(file_ + ": cannot read YAML: " + e.what());
    }
    return Node(doc, doc->root());
}

Node StrictYaml::load() const {
    std::string text;
    try {
        text = render::readFileBounded(file_, render::limits::kMaxYamlFileBytes, "YAML file");
    } catch (const render::InputLimitError& e) {
        throw Error(e.what());
    }
    return parse(text);
}

void StrictYaml::onlyKeys(const Node& map, const std::vector<std::string>& allowed, const std::string& context) const {
    for (const auto& kv : map) {
        // A complex key ("? [a, b]" or "? {a: b}") has no string form.
        if (!kv.first.IsScalar()) fail(kv.first, "keys in " + context + " must be plain names");
        const std::string_view key = kv.first.ScalarView();
        bool known = false;
        for (const auto& a : allowed) known |= a == key;
        if (!known)
            fail(kv.first,
                 "unknown key '" + std::string(key) + "' in " + context + " (allowed: " + joined(allowed) + ")");
    }
}

StrictYaml::Number StrictYaml::parseNumber(const Node& node, double& out) {
    if (!node.IsScalar() || node.IsQuoted()) return Number::NotANumber;
    const std::string_view s = node.ScalarView(); // NUL-terminated
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return Number::NotANumber;
    // Decimal only, as the integers: strtod would also take a hex float (0x1p-2).
    if (s.find_first_of("xX") != std::string_view::npos) return Number::NotANumber;
    char* end = nullptr;
    const double v = std::strtod(s.data(), &end);
    if (end != s.data() + s.size()) return Number::NotANumber;
    if (!std::isfinite(v)) return Number::NotFinite;
    out = v;
    return Number::Ok;
}

bool StrictYaml::parseInteger(const Node& node, long long& out) {
    if (!node.IsScalar() || node.IsQuoted()) return false;
    const std::string_view s = node.ScalarView(); // NUL-terminated
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(s.data(), &end, 10);
    if (end != s.data() + s.size() || errno == ERANGE) return false;
    out = v;
    return true;
}

std::string StrictYaml::joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

} // namespace stipple::yaml
