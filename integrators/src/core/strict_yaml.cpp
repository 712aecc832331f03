#include <stipple/yaml/strict_yaml.h>
#include <stipple/render/input_limits.h>
#include <yaml-cpp/depthguard.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace stipple::yaml {

std::string StrictYaml::where(const YAML::Node& node) const {
    const YAML::Mark m = node.Mark();
    if (m.line < 0) return file_;
    return file_ + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

void StrictYaml::fail(const YAML::Node& node, const std::string& message) const {
    throw Error(where(node) + ": " + message);
}

YAML::Node StrictYaml::parse(const std::string& text) const {
    YAML::Node root;
    try {
        root = YAML::Load(text);
    } catch (const YAML::DeepRecursion& e) {
        throw Error(file_ + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                    ": YAML nested deeper than the parser's limit");
    } catch (const YAML::ParserException& e) {
        throw Error(file_ + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                    ": YAML syntax error: " + e.msg);
    } catch (const YAML::Exception& e) {
        throw Error(file_ + ": cannot read YAML: " + e.msg);
    }
    rejectDuplicateKeys(root);
    return root;
}

YAML::Node StrictYaml::load() const {
    std::string text;
    try {
        text = render::readFileBounded(file_, render::limits::kMaxYamlFileBytes, "YAML file");
    } catch (const render::InputLimitError& e) {
        throw Error(e.what());
    }
    return parse(text);
}

void StrictYaml::rejectDuplicateKeys(const YAML::Node& node) const {
    if (node.IsMap()) {
        std::set<std::string> seen;
        for (const auto& kv : node) {
            if (kv.first.IsScalar() && !seen.insert(kv.first.Scalar()).second)
                fail(kv.first, "duplicate key '" + kv.first.Scalar() + "'");
            rejectDuplicateKeys(kv.second);
        }
    } else if (node.IsSequence()) {
        for (const auto& item : node) rejectDuplicateKeys(item);
    }
}

void StrictYaml::onlyKeys(const YAML::Node& map, const std::vector<std::string>& allowed,
                          const std::string& context) const {
    for (const auto& kv : map) {
        // A complex key ("? [a, b]" or "? {a: b}") has no string form.
        if (!kv.first.IsScalar()) fail(kv.first, "keys in " + context + " must be plain names");
        const std::string& key = kv.first.Scalar();
        bool known = false;
        for (const auto& a : allowed) known |= a == key;
        if (!known) fail(kv.first, "unknown key '" + key + "' in " + context + " (allowed: " + joined(allowed) + ")");
    }
}

StrictYaml::Number StrictYaml::parseNumber(const YAML::Node& node, double& out) {
    if (!node.IsScalar()) return Number::NotANumber;
    const std::string& s = node.Scalar();
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return Number::NotANumber;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return Number::NotANumber;
    if (!std::isfinite(v)) return Number::NotFinite;
    out = v;
    return Number::Ok;
}

bool StrictYaml::parseInteger(const YAML::Node& node, long long& out) {
    if (!node.IsScalar()) return false;
    const std::string& s = node.Scalar();
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (end != s.c_str() + s.size() || errno == ERANGE) return false;
    out = v;
    return true;
}

std::string StrictYaml::joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

} // namespace stipple::yaml
