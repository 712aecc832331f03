// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "matrix/check_kind.h"

#include <algorithm>
#include <stdexcept>

namespace stipple::validation {

CheckReader::CheckReader(const MatrixReader& yaml_, const Matrix& matrix_) : yaml(yaml_), matrix(matrix_) {
    for (const auto& s : matrix.scenes) sceneNames_.insert(s.name);
}

std::string CheckReader::scene(const yaml::Node& n, bool allowAll) const {
    auto s = yaml.get<std::string>(n, "scene");
    if (allowAll && s == "all") return s;
    if (!sceneNames_.count(s)) {
        std::vector<std::string> names;
        for (const auto& ms : matrix.scenes)
            if (names.size() < 20) names.push_back(ms.name);
        if (matrix.scenes.size() > names.size()) names.push_back("...");
        fail(n, "unknown scene '" + s + "' (matrix scenes: " + joined(names) + (allowAll ? ", or all" : "") + ")");
    }
    return s;
}

std::string CheckReader::pattern(const yaml::Node& n) const {
    auto p = yaml.pattern(n);
    if (std::find(matrix.patterns.begin(), matrix.patterns.end(), p) == matrix.patterns.end())
        fail(n, "pattern '" + p + "' is not among the matrix's patterns (" + joined(matrix.patterns) + ")");
    return p;
}

uint32_t CheckReader::spp(const yaml::Node& n, const std::string& what) const {
    auto v = yaml.spp(n, what);
    if (std::find(matrix.spp.begin(), matrix.spp.end(), v) == matrix.spp.end())
        fail(n, what + " " + n.Scalar() + " is not among the matrix's spp");
    return v;
}

// ---- shared keys and values --------------------------------------------------------------------------------------

CheckKey sceneKey(bool required) {
    return makeKey<std::string>(
        "scene", shared(&Check::scene),
        [](const CheckReader& r, const yaml::Node& n, const Check&) { return r.scene(n, true); }, required);
}

CheckKey studyKey() {
    CheckKey k = optionalKey<std::string>(
        "study", shared(&Check::study),
        [](const CheckReader& r, const yaml::Node& n, const Check&) { return r.yaml.get<std::string>(n, "study"); });
    k.fingerprinted = false;
    return k;
}

CheckKey notSeparatedKey(bool failsByDefault) {
    CheckKey k = choiceKey<bool>("not_separated", shared(&Check::notSeparatedFails), {{"fail", true}, {"pass", false}});
    k.absent = [failsByDefault](const CheckReader&, Check& c) { c.notSeparatedFails = failsByDefault; };
    return k;
}

CheckKey failsRunKey() { return choiceKey<bool>("fails_run", shared(&Check::failFails), {{"true", true}, {"false", false}}); }

std::vector<std::string> readPatternList(const CheckReader& r, const yaml::Node& node, const std::string& key,
                                         const std::string& what) {
    if (!node.IsSequence() || node.size() < 2) r.fail(node, key + " must list at least two patterns" + what);
    std::vector<std::string> out;
    // A pattern compared with itself is a matrix error, not a failed claim.
    for (const auto& p : node) {
        out.push_back(r.pattern(p));
        if (std::count(out.begin(), out.end(), out.back()) > 1)
            r.fail(p, "pattern '" + out.back() + "' appears twice in " + key);
    }
    return out;
}

std::pair<double, double> readMargin(const CheckReader& r, const yaml::Node& margin, const Check&) {
    if (!margin.IsSequence() || margin.size() != 2) r.fail(margin, "margin must be [lo, hi]");
    const double lo = r.yaml.positive(margin[0], "margin lo"), hi = r.yaml.positive(margin[1], "margin hi");
    if (!(lo < 1 && hi > 1)) r.fail(margin, "margin must hold 1 strictly inside: [lo < 1, hi > 1]");
    return {lo, hi};
}

double readNumber(const CheckReader& r, const yaml::Node& node, const std::string& what) {
    return r.yaml.get<double>(node, what);
}

double readPositive(const CheckReader& r, const yaml::Node& node, const std::string& what) {
    return r.yaml.positive(node, what);
}

std::vector<const MatrixScene*> scenesOf(const Check& c, const Matrix& m) {
    std::vector<const MatrixScene*> out;
    for (const auto& s : m.scenes)
        if (c.scene == "all" || c.scene == s.name) out.push_back(&s);
    return out;
}

// ---- reading, spelling and evaluating a check by its kind --------------------------------------------------------

namespace {

// "an ordering check", "a slope check".
std::string describe(const CheckKind& kind) {
    const char first = kind.name[0];
    const bool vowel = first == 'a' || first == 'e' || first == 'i' || first == 'o' || first == 'u';
    return std::string(vowel ? "an " : "a ") + kind.name + " check";
}

std::string kindList() {
    std::string list;
    for (const CheckKind* k : checkKinds()) list += (list.empty() ? "" : ", ") + std::string(k->name);
    return list;
}

} // namespace

Check readCheck(const CheckReader& r, const yaml::Node& c) {
    const MatrixReader& P = r.yaml;
    P.expectMap(c, "a check");
    Check k;
    k.where = P.yaml.where(c);
    const auto type = P.get<std::string>(P.required(c, "type", "a check"), "check type");
    k.kind = findCheckKind(type);
    if (!k.kind) P.fail(c["type"], "unknown check type '" + type + "' (known: " + kindList() + ")");
    const CheckKind& kind = *k.kind;
    const std::string what = describe(kind);
    std::vector<std::string> allowed = {"type"};
    for (const auto& key : kind.keys) allowed.push_back(key.name);
    P.onlyKeys(c, allowed, what);
    k.params = kind.makeParams();
    for (const auto& key : kind.keys) {
        if (const yaml::Node n = c[key.name])
            key.read(r, n, k);
        else if (key.required)
            P.fail(c, what + " needs '" + key.name + "'");
        else if (key.absent)
            key.absent(r, k);
    }
    if (kind.validate) kind.validate(r, c, k);
    return k;
}

Check parseCheck(const std::string& text, const std::string& path, const Matrix& matrix,
                 const MatrixVocabulary& vocabulary) {
    const MatrixReader P{yaml::StrictYaml(path), vocabulary};
    yaml::Node root;
    try {
        root = P.yaml.parse(text);
    } catch (const yaml::Error& e) {
        throw MatrixError(e.what());
    }
    return readCheck(CheckReader(P, matrix), root);
}

Json checkClaimJson(const Check& c) {
    Json j;
    j["type"] = c.kind->name;
    for (const auto& key : c.kind->keys)
        if (key.fingerprinted) j[key.name] = key.value(c);
    return j;
}

} // namespace stipple::validation
