// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/shard_fingerprint.h"
#include "matrix/check_kind.h"
#include "run/results.h" // resultsFileByteLimit

#include <stipple/render/input_limits.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace stipple::validation {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

const FingerprintField* Fingerprint::find(const std::string& name) const {
    for (const auto& f : fields)
        if (f.name == name) return &f;
    return nullptr;
}

namespace {

std::optional<FingerprintDifference> compare(const Fingerprint& a, const Fingerprint& b, const std::string& prefix) {
    auto selected = [&](const std::string& name) { return name.compare(0, prefix.size(), prefix) == 0; };
    for (const auto& f : a.fields) {
        if (!selected(f.name)) continue;
        const FingerprintField* g = b.find(f.name);
        if (!g) return FingerprintDifference{f.name, f.value, "(absent)"};
        if (g->value != f.value) return FingerprintDifference{f.name, f.value, g->value};
    }
    for (const auto& g : b.fields)
        if (selected(g.name) && !a.find(g.name)) return FingerprintDifference{g.name, "(absent)", g.value};
    return std::nullopt;
}

} // namespace

Fingerprint matrixFingerprint(const Matrix& m) {
    Fingerprint f;
    ordered_json names = ordered_json::array();
    for (const auto& s : m.scenes) names.push_back(s.name);
    f.add("matrix.scenes", names.dump());
    f.add("matrix.patterns", ordered_json(m.patterns).dump());
    f.add("matrix.spp", ordered_json(m.spp).dump());
    f.add("matrix.seeds", ordered_json(m.seeds).dump());
    f.add("matrix.reference.pattern", ordered_json(m.reference.pattern).dump());
    f.add("matrix.reference.seed", ordered_json(m.reference.seed).dump());
    const uint32_t cropSpp = m.crop.spp ? m.crop.spp : (m.spp.empty() ? 0 : m.spp.back());
    f.add(
        "matrix.crop",
        ordered_json{{"x", m.crop.x}, {"y", m.crop.y}, {"size", m.crop.size}, {"scale", m.crop.scale}, {"spp", cropSpp}}
            .dump());
    ordered_json checks = ordered_json::array();
    for (const auto& c : m.checks) checks.push_back(checkClaimJson(c)); // the fields its kind reads
    f.add("matrix.checks", checks.dump());
    return f;
}

Fingerprint runFingerprint(const Matrix& m, const std::vector<SceneFingerprint>& scenes,
                           const std::string& rendererVersion, const std::string& shimIdentity) {
    if (scenes.size() != m.scenes.size())
        throw std::logic_error("runFingerprint: one SceneFingerprint per matrix scene expected");
    Fingerprint f = matrixFingerprint(m);
    for (size_t i = 0; i < m.scenes.size(); ++i) {
        const std::string p = "scene." + m.scenes[i].name + ".";
        const SceneFingerprint& s = scenes[i];
        f.add(p + "file", ordered_json(m.scenes[i].file).dump());
        // A scene that did not load has no resolved settings; null on both sides compares equal, and the merge
        // reports the scene as skipped.
        auto value = [&](const auto& v) { return s.loaded ? ordered_json(v).dump() : std::string("null"); };
        f.add(p + "content_hash", value(s.contentHash));
        f.add(p + "width", value(s.width));
        f.add(p + "height", value(s.height));
        f.add(p + "integrator", value(s.integrator));
        f.add(p + "max_depth", value(s.maxDepth));
        f.add(p + "reference_spp", value(s.referenceSpp));
    }
    f.add("renderer.version", ordered_json(rendererVersion).dump());
    f.add("shim.identity", ordered_json(shimIdentity).dump());
    return f;
}

std::string fingerprintJson(const Fingerprint& fp, const std::string& indent) {
    std::string out = "{";
    for (size_t i = 0; i < fp.fields.size(); ++i)
        out += (i ? ",\n" : "\n") + indent + "  " + ordered_json(fp.fields[i].name).dump() + ": " + fp.fields[i].value;
    return out + "\n" + indent + "}";
}

Fingerprint readFingerprint(const std::string& path, uint64_t maxBytes) {
    try {
        return parseFingerprint(render::readFileBounded(path, maxBytes, "results file"), path);
    } catch (const render::InputLimitError& e) {
        throw std::runtime_error(e.what());
    }
}

Fingerprint parseFingerprint(const std::string& text, const std::string& path) {
    ordered_json root;
    try {
        root = ordered_json::parse(text);
    } catch (const ordered_json::parse_error& e) {
        throw std::runtime_error(path + ": malformed results.json: " + e.what());
    }
    Fingerprint f;
    if (!root.is_object() || !root.contains("fingerprint")) return f;
    const ordered_json& j = root["fingerprint"];
    if (!j.is_object()) throw std::runtime_error(path + ": \"fingerprint\" is not an object");
    for (const auto& [name, value] : j.items()) f.add(name, value.dump());
    return f;
}

std::optional<FingerprintDifference> firstDifference(const Fingerprint& a, const Fingerprint& b) {
    return compare(a, b, "");
}

std::optional<FingerprintDifference> firstDifference(const Fingerprint& a, const Fingerprint& b,
                                                     const std::string& prefix) {
    return compare(a, b, prefix);
}

void checkShardFingerprints(const Matrix& matrix, const std::vector<std::string>& dirs) {
    std::vector<Fingerprint> prints;
    for (const auto& dir : dirs) {
        const std::string path = (fs::path(dir) / "results.json").string();
        prints.push_back(readFingerprint(path, resultsFileByteLimit(matrix)));
        if (prints.back().empty())
            throw std::runtime_error(
                "merge: " + path + " has no fingerprint (written by an older stipple-validate): run that shard again");
    }
    for (size_t i = 1; i < dirs.size(); ++i)
        if (auto d = firstDifference(prints[0], prints[i]))
            throw std::runtime_error("merge: shards " + dirs[0] + " and " + dirs[i] +
                                     " cannot be merged: they differ first in " + d->field + ": " + d->a + " (" +
                                     dirs[0] + ") vs " + d->b + " (" + dirs[i] + ")");
    // The checks are the merge matrix's to evaluate (they change no row): claims may be re-checked on finished
    // shards with an edited list of checks.
    auto withoutChecks = [](Fingerprint f) {
        std::erase_if(f.fields, [](const FingerprintField& x) { return x.name == "matrix.checks"; });
        return f;
    };
    if (auto d = firstDifference(withoutChecks(prints[0]), withoutChecks(matrixFingerprint(matrix)), "matrix."))
        throw std::runtime_error("merge: the shards ran another matrix than " + matrix.path +
                                 ": they differ first in " + d->field + ": " + d->a + " (" + dirs[0] + ") vs " + d->b +
                                 " (" + matrix.path + ")");
}

} // namespace stipple::validation
