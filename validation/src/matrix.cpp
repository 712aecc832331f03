// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "matrix.h"
#include "external_command.h"

#include "report.h"

#include <stipple/render/input_limits.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <stipple/yaml/strict_yaml.h>

#include <limits>
#include <type_traits>

namespace stipple::validation {

namespace fs = std::filesystem;

const char* checkTypeName(CheckType type) {
    switch (type) {
    case CheckType::Ordering: return "ordering";
    case CheckType::Slope: return "slope";
    case CheckType::TimeRatio: return "time_ratio";
    case CheckType::TimeCeiling: return "time_ceiling";
    case CheckType::EqualTime: return "equal_time";
    case CheckType::EqualSpp: return "equal_spp";
    case CheckType::Compare: return "compare";
    }
    return "?";
}

const MatrixScene* Matrix::findScene(const std::string& name) const {
    for (const auto& s : scenes)
        if (s.name == name) return &s;
    return nullptr;
}

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
}

// Parsing context: the strict YAML reader of the file (positions, keys, numbers) and the names it may use.
struct Parser {
    yaml::StrictYaml yaml;
    const MatrixVocabulary& vocabulary;

    [[noreturn]] void fail(const yaml::Node& node, const std::string& what) const {
        throw MatrixError(yaml.where(node) + ": " + what);
    }

    void expectMap(const yaml::Node& node, const std::string& what) const {
        if (!node.IsMap()) fail(node, what + " must be a map");
    }
    // Unknown keys are errors: a typo must not silently become a default.
    void onlyKeys(const yaml::Node& map, const std::vector<std::string>& allowed, const std::string& what) const {
        try {
            yaml.onlyKeys(map, allowed, what);
        } catch (const yaml::Error& e) {
            throw MatrixError(e.what());
        }
    }
    template <typename T>
    T get(const yaml::Node& node, const std::string& what) const {
        if (!node.IsScalar()) fail(node, what + " must be a scalar");
        if constexpr (std::is_same_v<T, std::string>) {
            return node.Scalar();
        } else if (node.IsQuoted()) {
            fail(node, what + " must be a number, not quoted text ('" + node.Scalar() + "')");
        } else if constexpr (std::is_floating_point_v<T>) {
            double v = 0;
            if (yaml::StrictYaml::parseNumber(node, v) != yaml::StrictYaml::Number::Ok)
                fail(node, "cannot read " + what + " from '" + node.Scalar() + "'");
            return T(v);
        } else {
            long long v = 0;
            if (!yaml::StrictYaml::parseInteger(node, v) || v < (long long)std::numeric_limits<T>::min() ||
                (v > 0 && (unsigned long long)v > (unsigned long long)std::numeric_limits<T>::max()))
                fail(node, "cannot read " + what + " from '" + node.Scalar() + "'");
            return T(v);
        }
    }
    double positive(const yaml::Node& node, const std::string& what) const {
        double v = get<double>(node, what);
        if (!(v > 0)) fail(node, what + " must be > 0, got " + node.Scalar());
        return v;
    }
    // A sample count: at most the library's N limit (STIPPLE_MAX_SAMPLES_PER_PIXEL), checked here rather than
    // after every render; a reference is rendered as two halves, so its limit is twice that.
    uint32_t spp(const yaml::Node& node, const std::string& what, bool reference = false) const {
        const long long limit = kMaxSamplesPerPixel * (reference ? 2 : 1);
        long long v = get<long long>(node, what);
        if (v < 1 || v > limit)
            fail(node, what + " must be in [1, " + std::to_string(limit) + "] (the library's limit on samples per " +
                           "pixel" + (reference ? ", for each of the reference's two halves" : "") + "), got " +
                           node.Scalar());
        return uint32_t(v);
    }
    // A name shown in reports, file names and messages: valid UTF-8, 1 to kMaxNameBytes bytes, no control
    // characters.
    static constexpr size_t kMaxNameBytes = 128;
    std::string name(const yaml::Node& node, const std::string& what) const {
        const std::string v = get<std::string>(node, what);
        if (v.empty() || v.size() > kMaxNameBytes)
            fail(node, what + " must be 1 to " + std::to_string(kMaxNameBytes) + " bytes long, got " +
                           std::to_string(v.size()));
        for (size_t i = 0; i < v.size();) {
            const unsigned char c = static_cast<unsigned char>(v[i]);
            const size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
            bool ok = n > 0 && i + n <= v.size() && !(n == 1 && (c < 0x20 || c == 0x7f));
            for (size_t k = 1; ok && k < n; ++k) ok = (static_cast<unsigned char>(v[i + k]) >> 6) == 0x2;
            if (ok && n > 1) { // no overlong forms, surrogates or code points past U+10FFFF
                uint32_t cp = c & (0xff >> (n + 1));
                for (size_t k = 1; k < n; ++k) cp = (cp << 6) | (static_cast<unsigned char>(v[i + k]) & 0x3f);
                ok = cp >= (n == 2 ? 0x80u : n == 3 ? 0x800u : 0x10000u) && cp <= 0x10ffff && !(cp >= 0xd800 && cp <= 0xdfff);
            }
            if (!ok)
                fail(node, what + " must be valid UTF-8 without control characters (byte " + std::to_string(i) + ")");
            i += n;
        }
        return v;
    }
    // An image side: the renderer's range (render::checkRenderSettings refuses the same).
    int imageSide(const yaml::Node& node, const std::string& what) const {
        long long v = get<long long>(node, what);
        if (v < 1 || v > render::limits::kMaxImageSide)
            fail(node, what + " must be in [1, " + std::to_string(render::limits::kMaxImageSide) + "], got " +
                           node.Scalar());
        return int(v);
    }
    int dimension(const yaml::Node& node, const std::string& what) const {
        long long v = get<long long>(node, what);
        if (v < 1 || v > 16384) fail(node, what + " must be in [1, 16384], got " + node.Scalar());
        return int(v);
    }
    std::string pattern(const yaml::Node& node) const {
        auto p = get<std::string>(node, "pattern");
        const auto& known = vocabulary.patterns;
        // "<pattern>+blue-noise": the shim's screen-space blue-noise option on that pattern.
        static const std::string kBlueNoise = "+blue-noise";
        std::string base = p;
        if (base.size() > kBlueNoise.size() && base.ends_with(kBlueNoise)) base.resize(base.size() - kBlueNoise.size());
        if (std::find(known.begin(), known.end(), base) == known.end())
            fail(node, "unknown pattern '" + p + "' (known: " + joined(known) + ", each optionally followed by " +
                           kBlueNoise + ")");
        return p;
    }
    // renderer: { command: [program, arg, ...], format: exr | pfm } (external_renderer.h).
    ExternalCommand renderer(const yaml::Node& node) const {
        expectMap(node, "renderer");
        onlyKeys(node, {"command", "format", "timeout"}, "renderer");
        ExternalCommand r;
        r.where = yaml.where(node);
        const yaml::Node command = required(node, "command", "renderer");
        if (!command.IsSequence() || command.size() == 0)
            fail(command, "command must be a list: the program, then its arguments (no shell)");
        for (const auto& a : command) r.command.push_back(get<std::string>(a, "a command argument"));
        if (const std::string why = checkCommandTemplate(r.command); !why.empty()) fail(command, why);
        if (node["timeout"]) {
            r.timeoutSeconds = get<double>(node["timeout"], "timeout");
            if (!(r.timeoutSeconds > 0 && r.timeoutSeconds <= 1e6))
                fail(node["timeout"], "timeout must be seconds in (0, 1000000]");
        }
        if (node["format"]) {
            r.format = get<std::string>(node["format"], "format");
            if (r.format != "exr" && r.format != "pfm") fail(node["format"], "format must be exr or pfm");
        }
        return r;
    }
    const yaml::Node required(const yaml::Node& map, const std::string& key, const std::string& what) const {
        const yaml::Node n = map[key];
        if (!n) fail(map, what + " needs '" + key + "'");
        return n;
    }
};

// ---- the sections of a matrix, each read into m ------------------------------------------------------------------

void parseScenes(const Parser& P, const yaml::Node& croot, const fs::path& base, Matrix& m) {
    auto resolve = [&](const std::string& p) { return (base / p).lexically_normal().string(); };
    const yaml::Node scenes = P.required(croot, "scenes", "the matrix");
    if (!scenes.IsSequence() || scenes.size() == 0) P.fail(scenes, "scenes must be a non-empty list");
    std::set<std::string> sceneNames; // a linear findScene per entry made a 15 MB matrix take minutes
    std::map<std::string, std::string> fileNames; // safeName -> scene name
    for (const auto& s : scenes) {
        MatrixScene ms;
        if (s.IsScalar()) {
            ms.file = P.get<std::string>(s, "scene file");
        } else {
            P.expectMap(s, "a scene entry");
            P.onlyKeys(s,
                       {"file", "name", "width", "height", "integrator", "max_depth", "reference_spp", "regions",
                        "renderer"},
                       "a scene entry");
            if (s["renderer"]) ms.renderer = P.renderer(s["renderer"]);
            ms.file = P.get<std::string>(P.required(s, "file", "a scene entry"), "file");
            if (s["name"]) ms.name = P.name(s["name"], "name");
            if (s["width"]) ms.width = P.imageSide(s["width"], "width");
            if (s["height"]) ms.height = P.imageSide(s["height"], "height");
            if (s["integrator"]) {
                ms.integrator = P.get<std::string>(s["integrator"], "integrator");
                const auto& known = P.vocabulary.integrators;
                if (std::find(known.begin(), known.end(), ms.integrator) == known.end())
                    P.fail(s["integrator"],
                           "unknown integrator '" + ms.integrator + "' (known: " + joined(known) + ")");
            }
            if (s["reference_spp"]) ms.referenceSpp = P.spp(s["reference_spp"], "reference_spp", true);
            if (const yaml::Node regions = s["regions"]) {
                if (!regions.IsSequence())
                    P.fail(regions, "regions must be a list of { name, rect: [x0, y0, x1, y1] }");
                std::map<std::string, std::string> regionFiles; // safeName -> region name
                for (const auto& rn : regions) {
                    P.expectMap(rn, "a region");
                    P.onlyKeys(rn, {"name", "rect"}, "a region");
                    Region rg;
                    rg.name = P.name(P.required(rn, "name", "a region"), "region name");
                    const yaml::Node rect = P.required(rn, "rect", "a region");
                    if (!rect.IsSequence() || rect.size() != 4)
                        P.fail(rect, "rect must be [x0, y0, x1, y1], fractions of the image's width and height");
                    double v[4];
                    for (int i = 0; i < 4; ++i) v[i] = P.get<double>(rect[i], "rect coordinate");
                    if (!(0 <= v[0] && v[0] < v[2] && v[2] <= 1 && 0 <= v[1] && v[1] < v[3] && v[3] <= 1))
                        P.fail(rect, "rect must satisfy 0 ≤ x0 < x1 ≤ 1 and 0 ≤ y0 < y1 ≤ 1");
                    rg.x0 = v[0], rg.y0 = v[1], rg.x1 = v[2], rg.y1 = v[3];
                    // By file name in a map: O(n log n), where a scan of the earlier regions was quadratic.
                    const auto [it, fresh] = regionFiles.emplace(safeName(rg.name), rg.name);
                    if (!fresh && it->second == rg.name) P.fail(rn, "region '" + rg.name + "' appears twice");
                    if (!fresh)
                        P.fail(rn, "region names '" + it->second + "' and '" + rg.name + "' have the same file name '" +
                                       it->first + "' in the report; rename one");
                    ms.regions.push_back(rg);
                }
            }
            if (s["max_depth"]) {
                ms.maxDepth = P.get<int>(s["max_depth"], "max_depth");
                if (ms.maxDepth < 0 || ms.maxDepth > render::limits::kMaxPathDepth)
                    P.fail(s["max_depth"], "max_depth must be in [0, " +
                                               std::to_string(render::limits::kMaxPathDepth) + "], got " +
                                               s["max_depth"].Scalar());
            }
        }
        if (ms.renderer.empty() && croot["renderer"]) ms.renderer = P.renderer(croot["renderer"]);
        // An external renderer has no scene defaults to fall back on, and no integrator or depth of ours.
        if (!ms.renderer.empty() && (!ms.width || !ms.height))
            P.fail(s, "a scene rendered by an external renderer needs its width and height");
        if (!ms.renderer.empty() && (!ms.integrator.empty() || ms.maxDepth >= 0))
            P.fail(s, "integrator and max_depth are stipple-render's; the external renderer has its own");
        ms.path = resolve(ms.file);
        std::error_code fileError; // the throwing overload aborted the run on a name too long for the system
        if (!fs::is_regular_file(ms.path, fileError))
            P.fail(s, "unknown scene file '" + ms.file + "' (looked for " + ms.path + ")");
        // The path fills an external renderer's {scene}: it must not read as an option or break a line.
        if (!ms.renderer.empty())
            if (const std::string why = checkPlaceholderValue(ms.path); !why.empty())
                P.fail(s, "the scene file '" + ms.path + "' cannot fill {scene}: " + why);
        if (ms.name.empty()) ms.name = fs::path(ms.file).stem().string();
        if (ms.name == "all") P.fail(s, "'all' is reserved for checks; give the scene another name");
        if (!sceneNames.insert(ms.name).second)
            P.fail(s, "scene name '" + ms.name + "' appears twice; give one a 'name'");
        // The report names a scene's crops and plots by safeName: two names that reduce to one file name would
        // show one scene's figures for both.
        if (auto [it, fresh] = fileNames.emplace(safeName(ms.name), ms.name); !fresh)
            P.fail(s, "scene names '" + it->second + "' and '" + ms.name + "' have the same file name '" + it->first +
                          "' in the report; rename one");
        m.scenes.push_back(ms);
    }
}

void parsePatterns(const Parser& P, const yaml::Node& croot, Matrix& m) {
    const yaml::Node patterns = P.required(croot, "patterns", "the matrix");
    if (!patterns.IsSequence() || patterns.size() == 0) P.fail(patterns, "patterns must be a non-empty list");
    for (const auto& p : patterns) {
        auto name = P.pattern(p);
        if (std::find(m.patterns.begin(), m.patterns.end(), name) != m.patterns.end())
            P.fail(p, "pattern '" + name + "' listed twice");
        m.patterns.push_back(name);
    }
}

void parseSpp(const Parser& P, const yaml::Node& croot, Matrix& m) {
    const yaml::Node spp = P.required(croot, "spp", "the matrix");
    if (spp.IsScalar())
        m.spp.push_back(P.spp(spp, "spp"));
    else if (spp.IsSequence() && spp.size() > 0)
        for (const auto& n : spp) m.spp.push_back(P.spp(n, "spp"));
    else
        P.fail(spp, "spp must be a number or a non-empty list");
    std::sort(m.spp.begin(), m.spp.end());
    if (std::adjacent_find(m.spp.begin(), m.spp.end()) != m.spp.end()) P.fail(spp, "spp lists a value twice");
}

// K (seeds 1..K) or an explicit list.
void parseSeeds(const Parser& P, const yaml::Node& croot, Matrix& m) {
    const yaml::Node seeds = P.required(croot, "seeds", "the matrix");
    if (seeds.IsScalar()) {
        long long k = P.get<long long>(seeds, "seeds");
        if (k < 4 || k > 1000)
            P.fail(seeds, "seeds must be a count in [4, 1000] (K ≥ 4 for an interval), got " + seeds.Scalar());
        for (long long i = 1; i <= k; ++i) m.seeds.push_back(uint64_t(i));
    } else if (seeds.IsSequence()) {
        std::set<uint64_t> seen;
        for (const auto& n : seeds) {
            auto v = P.get<uint64_t>(n, "seed");
            if (!seen.insert(v).second) P.fail(n, "seed " + n.Scalar() + " listed twice");
            m.seeds.push_back(v);
        }
        if (m.seeds.size() < 4) P.fail(seeds, "seeds must list at least 4 values (K ≥ 4 for an interval)");
    } else
        P.fail(seeds, "seeds must be a count or a list of seeds");
}

// The reference's settings, and its spp against the cells' (per scene too).
void parseReference(const Parser& P, const yaml::Node& croot, Matrix& m) {
    const yaml::Node scenes = croot["scenes"];
    if (const yaml::Node r = croot["reference"]) {
        P.expectMap(r, "reference");
        P.onlyKeys(r, {"pattern", "spp", "seed"}, "reference");
        if (r["pattern"]) m.reference.pattern = P.pattern(r["pattern"]);
        if (r["spp"]) m.reference.spp = P.spp(r["spp"], "reference spp", true);
        if (r["seed"]) m.reference.seed = P.get<uint64_t>(r["seed"], "reference seed");
        if (std::find(m.seeds.begin(), m.seeds.end(), m.reference.seed) != m.seeds.end())
            P.fail(r, "the reference seed must differ from the cells' seeds (its noise would correlate with theirs)");
    }
    for (size_t i = 0; i < m.scenes.size(); ++i)
        if (m.scenes[i].referenceSpp && m.scenes[i].referenceSpp < 4 * m.spp.back())
            P.fail(scenes[i], "reference_spp (" + std::to_string(m.scenes[i].referenceSpp) +
                                  ") must be ≥ 4× the largest cell spp (" + std::to_string(m.spp.back()) + ")");
    if (m.reference.spp < 4 * m.spp.back())
        P.fail(croot["reference"] ? croot["reference"] : croot, "reference spp (" + std::to_string(m.reference.spp) +
                                                                    ") must be ≥ 4× the largest cell spp (" +
                                                                    std::to_string(m.spp.back()) + ")");
    // The largest render a scene entry asks for (its reference) must fit the renderer's budget: found now, not
    // after the other scenes have rendered.
    for (size_t i = 0; i < m.scenes.size(); ++i) {
        const MatrixScene& ms = m.scenes[i];
        if (!ms.width || !ms.height) continue;
        try {
            render::checkRenderBudget(ms.width, ms.height, ms.referenceSpp ? ms.referenceSpp : m.reference.spp);
        } catch (const std::invalid_argument& e) {
            P.fail(scenes[i], std::string("the reference of this scene: ") + e.what());
        }
    }
}

void parseCrop(const Parser& P, const yaml::Node& croot, Matrix& m) {
    if (const yaml::Node c = croot["crop"]) {
        P.expectMap(c, "crop");
        P.onlyKeys(c, {"x", "y", "size", "scale", "spp"}, "crop");
        auto fraction = [&](const yaml::Node& n, const char* what) {
            double v = P.get<double>(n, what);
            if (!(v >= 0 && v <= 1)) P.fail(n, std::string(what) + " is a fraction of the image, in [0, 1]");
            return v;
        };
        if (c["x"]) m.crop.x = fraction(c["x"], "crop x");
        if (c["y"]) m.crop.y = fraction(c["y"], "crop y");
        if (c["size"]) m.crop.size = P.dimension(c["size"], "crop size");
        if (c["scale"]) m.crop.scale = std::clamp(P.dimension(c["scale"], "crop scale"), 1, 16);
        if (c["spp"]) {
            m.crop.spp = P.spp(c["spp"], "crop spp");
            if (std::find(m.spp.begin(), m.spp.end(), m.crop.spp) == m.spp.end())
                P.fail(c["spp"], "crop spp must be one of the matrix's spp");
        }
    }
}

void parseBaseline(const Parser& P, const yaml::Node& croot, Matrix& m) {
    if (const yaml::Node b = croot["baseline"]) {
        P.expectMap(b, "baseline");
        P.onlyKeys(b, {"time_factor"}, "baseline");
        if (b["time_factor"]) m.baselineTimeFactor = P.positive(b["time_factor"], "time_factor");
    }
}

void parseChecks(const Parser& P, const yaml::Node& croot, Matrix& m) {
    std::set<std::string> sceneNames; // a linear findScene per check made a matrix of many checks take minutes
    for (const auto& ms : m.scenes) sceneNames.insert(ms.name);
    auto sceneRef = [&](const yaml::Node& n, bool allowAll) {
        auto s = P.get<std::string>(n, "scene");
        if (allowAll && s == "all") return s;
        if (!sceneNames.count(s)) {
            std::vector<std::string> names;
            for (const auto& ms : m.scenes)
                if (names.size() < 20) names.push_back(ms.name);
            if (m.scenes.size() > names.size()) names.push_back("...");
            P.fail(n,
                   "unknown scene '" + s + "' (matrix scenes: " + joined(names) + (allowAll ? ", or all" : "") + ")");
        }
        return s;
    };
    auto matrixPattern = [&](const yaml::Node& n) {
        auto p = P.pattern(n);
        if (std::find(m.patterns.begin(), m.patterns.end(), p) == m.patterns.end())
            P.fail(n, "pattern '" + p + "' is not among the matrix's patterns (" + joined(m.patterns) + ")");
        return p;
    };
    auto matrixSpp = [&](const yaml::Node& n, const char* what) {
        auto v = P.spp(n, what);
        if (std::find(m.spp.begin(), m.spp.end(), v) == m.spp.end())
            P.fail(n, std::string(what) + " " + n.Scalar() + " is not among the matrix's spp");
        return v;
    };
    // A pattern compared with itself is a matrix error, not a failed claim.
    auto orderOf = [&](const yaml::Node& order, std::vector<std::string>& out) {
        for (const auto& p : order) {
            out.push_back(matrixPattern(p));
            if (std::count(out.begin(), out.end(), out.back()) > 1)
                P.fail(p, "pattern '" + out.back() + "' appears twice in order");
        }
    };
    auto notSeparated = [&](const yaml::Node& c, bool fails) {
        if (!c["not_separated"]) return fails;
        auto v = P.get<std::string>(c["not_separated"], "not_separated");
        if (v != "fail" && v != "pass") P.fail(c["not_separated"], "not_separated must be fail or pass");
        return v == "fail";
    };
    if (const yaml::Node checks = croot["checks"]) {
        if (!checks.IsSequence()) P.fail(checks, "checks must be a list");
        for (const auto& c : checks) {
            P.expectMap(c, "a check");
            Check k;
            k.where = P.yaml.where(c);
            auto type = P.get<std::string>(P.required(c, "type", "a check"), "check type");
            if (type == "ordering") {
                k.type = CheckType::Ordering;
                P.onlyKeys(c, {"type", "scene", "spp_min", "order", "not_separated"}, "an ordering check");
                k.scene = sceneRef(P.required(c, "scene", "an ordering check"), true);
                k.sppMin = c["spp_min"] ? P.spp(c["spp_min"], "spp_min") : m.spp.back();
                if (k.sppMin > m.spp.back()) P.fail(c["spp_min"], "spp_min is above every spp of the matrix");
                const yaml::Node order = P.required(c, "order", "an ordering check");
                if (!order.IsSequence() || order.size() < 2)
                    P.fail(order, "order must list at least two patterns, best first");
                orderOf(order, k.order);
                k.notSeparatedFails = notSeparated(c, true);
            } else if (type == "slope") {
                k.type = CheckType::Slope;
                P.onlyKeys(c, {"type", "scene", "pattern", "expected", "tolerance"}, "a slope check");
                k.scene = sceneRef(P.required(c, "scene", "a slope check"), true);
                k.pattern = matrixPattern(P.required(c, "pattern", "a slope check"));
                k.expected = P.get<double>(P.required(c, "expected", "a slope check"), "expected");
                k.tolerance = P.positive(P.required(c, "tolerance", "a slope check"), "tolerance");
                if (m.spp.size() < 2) P.fail(c, "a slope check needs at least two spp in the matrix");
            } else if (type == "time_ratio") {
                k.type = CheckType::TimeRatio;
                P.onlyKeys(c, {"type", "scene", "numerator", "denominator", "max", "margin", "spp", "not_separated"},
                           "a time_ratio check");
                k.scene = c["scene"] ? sceneRef(c["scene"], true) : "all";
                k.numerator = matrixPattern(P.required(c, "numerator", "a time_ratio check"));
                k.denominator = matrixPattern(P.required(c, "denominator", "a time_ratio check"));
                if (k.denominator == k.numerator)
                    P.fail(c["denominator"], "numerator and denominator are the same pattern '" + k.numerator + "'");
                // A bound (≤ max) or an equivalence (within [lo, hi], two one-sided tests), not both.
                if (const yaml::Node margin = c["margin"]) {
                    if (c["max"]) P.fail(margin, "a time_ratio check takes max or margin, not both");
                    if (!margin.IsSequence() || margin.size() != 2) P.fail(margin, "margin must be [lo, hi]");
                    k.marginLo = P.positive(margin[0], "margin lo");
                    k.marginHi = P.positive(margin[1], "margin hi");
                    if (!(k.marginLo < 1 && k.marginHi > 1))
                        P.fail(margin, "margin must hold 1 strictly inside: [lo < 1, hi > 1]");
                    k.timeEquivalence = true;
                } else {
                    k.maxRatio = P.positive(P.required(c, "max", "a time_ratio check"), "max");
                }
                k.spp = c["spp"] ? matrixSpp(c["spp"], "spp") : m.spp.back();
                // An interval straddling the bound says the run could not tell, not that the claim is false.
                k.notSeparatedFails = notSeparated(c, false);
            } else if (type == "time_ceiling") {
                k.type = CheckType::TimeCeiling;
                P.onlyKeys(c, {"type", "scene", "seconds"}, "a time_ceiling check");
                k.scene = c["scene"] ? sceneRef(c["scene"], true) : "all";
                k.seconds = P.positive(P.required(c, "seconds", "a time_ceiling check"), "seconds");
            } else if (type == "equal_time" || type == "equal_spp") {
                k.type = type == "equal_time" ? CheckType::EqualTime : CheckType::EqualSpp;
                const std::string what = "an " + type + " check";
                P.onlyKeys(c, {"type", "scene", "region", "order", "spp", "study", "not_separated", "metric"}, what);
                if (c["metric"]) {
                    auto v = P.get<std::string>(c["metric"], "metric");
                    if (v != "mse" && v != "flip") P.fail(c["metric"], "metric must be mse or flip, got '" + v + "'");
                    k.flipMetric = v == "flip";
                }
                k.scene = sceneRef(P.required(c, "scene", what), true);
                if (c["region"]) {
                    k.region = P.get<std::string>(c["region"], "region");
                    const MatrixScene* ms = m.findScene(k.scene);
                    bool known = false;
                    std::vector<std::string> names;
                    for (const auto& r : ms ? ms->regions : std::vector<Region>{}) {
                        names.push_back(r.name);
                        known |= r.name == k.region;
                    }
                    if (!ms) P.fail(c["region"], "a region needs one scene, not 'all'");
                    if (!known)
                        P.fail(c["region"], "unknown region '" + k.region + "' of scene " + k.scene +
                                                " (its regions: " + joined(names) + ")");
                }
                const yaml::Node order = P.required(c, "order", what);
                if (!order.IsSequence() || order.size() < 2)
                    P.fail(order, "order must list at least two patterns, most efficient first");
                orderOf(order, k.order);
                k.spp = c["spp"] ? matrixSpp(c["spp"], "spp") : m.spp.back();
                if (c["study"]) k.study = P.get<std::string>(c["study"], "study");
                k.notSeparatedFails = notSeparated(c, false);
            } else if (type == "compare") {
                k.type = CheckType::Compare;
                const std::string what = "a compare check";
                P.onlyKeys(c, {"type", "scene", "region", "patterns", "basis", "metric", "expect", "margin", "spp",
                               "study", "fails_run", "not_separated"},
                           what);
                k.scene = c["scene"] ? sceneRef(c["scene"], true) : "all";
                if (c["region"]) {
                    k.region = P.get<std::string>(c["region"], "region");
                    // With scene: all, a region every scene has (one claim for a region the scenes share).
                    std::vector<std::string> lacking;
                    for (const auto& s : m.scenes) {
                        if (k.scene != "all" && s.name != k.scene) continue;
                        bool has = false;
                        for (const auto& r : s.regions) has |= r.name == k.region;
                        if (!has) lacking.push_back(s.name);
                    }
                    if (k.region != "image" && !lacking.empty())
                        P.fail(c["region"], k.scene == "all"
                                                ? "region '" + k.region + "' is not a region of every scene (" +
                                                      joined(lacking) + " lack it); 'image' or a region all have"
                                                : "region must be 'image' or a region of the one scene named, got '" +
                                                      k.region + "'");
                }
                const yaml::Node patterns = P.required(c, "patterns", what);
                if (!patterns.IsSequence() || patterns.size() < 2)
                    P.fail(patterns, "patterns must list at least two patterns (A, B, ...)");
                for (const auto& p : patterns) k.patterns.push_back(matrixPattern(p));
                if (c["basis"]) {
                    auto v = P.get<std::string>(c["basis"], "basis");
                    if (v != "samples" && v != "time") P.fail(c["basis"], "basis must be samples or time, got '" + v + "'");
                    k.equalTime = v == "time";
                }
                if (c["metric"]) {
                    auto v = P.get<std::string>(c["metric"], "metric");
                    if (v != "mse" && v != "flip") P.fail(c["metric"], "metric must be mse or flip, got '" + v + "'");
                    k.flipMetric = v == "flip";
                    if (k.flipMetric && k.equalTime)
                        P.fail(c["metric"], "metric flip is compared at equal samples only (basis: samples)");
                }
                if (c["expect"]) {
                    auto v = P.get<std::string>(c["expect"], "expect");
                    if (v == "any") k.expect = Expectation::Any;
                    else if (v == "equivalent") k.expect = Expectation::Equivalent;
                    else if (v == "better") k.expect = Expectation::Better;
                    else if (v == "worse") k.expect = Expectation::Worse;
                    else P.fail(c["expect"], "expect must be any, equivalent, better or worse, got '" + v + "'");
                }
                if (const yaml::Node margin = c["margin"]) {
                    if (!margin.IsSequence() || margin.size() != 2) P.fail(margin, "margin must be [lo, hi]");
                    k.marginLo = P.positive(margin[0], "margin lo");
                    k.marginHi = P.positive(margin[1], "margin hi");
                    if (!(k.marginLo < 1 && k.marginHi > 1))
                        P.fail(margin, "margin must hold 1 strictly inside: [lo < 1, hi > 1]");
                }
                k.spp = c["spp"] ? matrixSpp(c["spp"], "spp") : m.spp.back();
                if (c["study"]) k.study = P.get<std::string>(c["study"], "study");
                if (c["fails_run"]) {
                    auto v = P.get<std::string>(c["fails_run"], "fails_run");
                    if (v != "true" && v != "false") P.fail(c["fails_run"], "fails_run must be true or false");
                    k.failFails = v == "true";
                }
                k.notSeparatedFails = notSeparated(c, false);
            } else {
                P.fail(c["type"], "unknown check type '" + type +
                                      "' (known: ordering, slope, time_ratio, time_ceiling, equal_time, equal_spp, "
                                      "compare)");
            }
            m.checks.push_back(k);
        }
    }
}

} // namespace
// perceptual: { trials, repeats, controls, control_spp, margin, sets: [{ scene, region, patterns, spp }] }
void parsePerceptual(const Parser& P, const yaml::Node& croot, Matrix& m) {
    const yaml::Node p = croot["perceptual"];
    if (!p) return;
    P.expectMap(p, "perceptual");
    P.onlyKeys(p, {"trials", "repeats", "controls", "control_spp", "margin", "sets"}, "perceptual");
    PerceptualPlan& plan = m.perceptual;
    auto count = [&](const char* key, int lo, int hi, int& out) {
        if (!p[key]) return;
        const long long v = P.get<long long>(p[key], key);
        if (v < lo || v > hi)
            P.fail(p[key], std::string(key) + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                               "], got " + p[key].Scalar());
        out = int(v);
    };
    auto matrixSpp = [&](const yaml::Node& n, const std::string& what) {
        const uint32_t v = P.spp(n, what);
        if (std::find(m.spp.begin(), m.spp.end(), v) == m.spp.end()) P.fail(n, what + " must be one of the matrix's spp");
        return v;
    };
    count("trials", 1, 10, plan.trials);
    count("controls", 1, 10, plan.controls);
    plan.controlSpp = p["control_spp"] ? matrixSpp(p["control_spp"], "control_spp") : m.spp.front();
    if (p["margin"]) plan.margin = P.positive(p["margin"], "margin");
    const yaml::Node sets = p["sets"];
    if (!sets || !sets.IsSequence() || sets.size() == 0) P.fail(sets ? sets : p, "perceptual needs a list of sets");
    for (const auto& n : sets) {
        P.expectMap(n, "a perceptual set");
        P.onlyKeys(n, {"scene", "region", "patterns", "spp"}, "a perceptual set");
        PerceptualSet s;
        s.where = P.yaml.where(n);
        for (const char* key : {"scene", "region", "patterns", "spp"})
            if (!n[key]) P.fail(n, std::string("a perceptual set needs '") + key + "'");
        s.scene = P.get<std::string>(n["scene"], "scene");
        const MatrixScene* scene = m.findScene(s.scene);
        if (!scene) P.fail(n["scene"], "unknown scene '" + s.scene + "'");
        s.region = P.get<std::string>(n["region"], "region");
        if (std::none_of(scene->regions.begin(), scene->regions.end(), [&](const Region& r) { return r.name == s.region; }))
            P.fail(n["region"], "scene '" + s.scene + "' has no region '" + s.region + "'");
        const yaml::Node patterns = n["patterns"];
        if (!patterns.IsSequence() || patterns.size() < 2 || patterns.size() > 4)
            P.fail(patterns, "patterns must be a list of 2 to 4 of the matrix's patterns");
        for (const auto& q : patterns) {
            const std::string name = P.get<std::string>(q, "pattern");
            if (std::find(m.patterns.begin(), m.patterns.end(), name) == m.patterns.end())
                P.fail(q, "pattern '" + name + "' is not one of the matrix's patterns");
            if (std::find(s.patterns.begin(), s.patterns.end(), name) != s.patterns.end())
                P.fail(q, "pattern '" + name + "' is named twice");
            s.patterns.push_back(name);
        }
        s.spp = matrixSpp(n["spp"], "spp");
        if (s.spp <= plan.controlSpp)
            P.fail(n["spp"], "a set's spp must be above control_spp (the control, at fewer samples, is the known worst)");
        plan.sets.push_back(s);
    }
    count("repeats", 0, int(plan.sets.size()) * plan.trials, plan.repeats);
}

Matrix parseMatrix(const std::string& text, const std::string& path, const MatrixVocabulary& vocabulary) {
    Parser P{yaml::StrictYaml(path), vocabulary};
    yaml::Node root;
    try {
        root = P.yaml.parse(text);
    } catch (const yaml::Error& e) {
        throw MatrixError(e.what());
    }
    if (!root || !root.IsMap()) throw MatrixError(path + ":1:1: a matrix must be a YAML map");
    const yaml::Node& croot = root;
    P.onlyKeys(
        croot,
        {"name", "cache", "threads", "scenes", "patterns", "spp", "seeds", "reference", "crop", "baseline", "checks",
         "renderer", "perceptual"},
        "the matrix");

    Matrix m;
    m.path = path;
    m.text = text;
    const fs::path base = fs::path(path).parent_path();
    auto resolve = [&](const std::string& p) { return (base / p).lexically_normal().string(); };

    m.name = croot["name"] ? P.name(croot["name"], "name") : fs::path(path).stem().string();
    if (croot["cache"]) m.cacheDir = resolve(P.get<std::string>(croot["cache"], "cache"));
    if (croot["threads"]) {
        m.threads = P.get<int>(croot["threads"], "threads");
        if (m.threads < 0 || m.threads > render::limits::kMaxThreads)
            P.fail(croot["threads"], "threads must be in [0, " + std::to_string(render::limits::kMaxThreads) +
                                         "] (0: all hardware threads), got " + croot["threads"].Scalar());
    }

    parseScenes(P, croot, base, m);
    parsePatterns(P, croot, m);
    parseSpp(P, croot, m);
    parseSeeds(P, croot, m);
    parseReference(P, croot, m);
    parseCrop(P, croot, m);
    parseBaseline(P, croot, m);
    parseChecks(P, croot, m);
    parsePerceptual(P, croot, m);
    return m;
}

Matrix loadMatrix(const std::string& path, const MatrixVocabulary& vocabulary) {
    std::string text;
    try {
        text = render::readFileBounded(path, render::limits::kMaxYamlFileBytes, "matrix file");
    } catch (const render::InputLimitError& e) {
        throw MatrixError(e.what());
    }
    return parseMatrix(text, path, vocabulary);
}

} // namespace stipple::validation
