// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "matrix/matrix.h"
#include "matrix/check_kind.h"
#include "matrix/external_command.h"
#include "matrix/matrix_reader.h"

#include "base/file_names.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace stipple::validation {

namespace fs = std::filesystem;

const MatrixScene* Matrix::findScene(const std::string& name) const {
    for (const auto& s : scenes)
        if (s.name == name) return &s;
    return nullptr;
}

namespace {


// ---- the sections of a matrix, each read into m ------------------------------------------------------------------

void parseScenes(const MatrixReader& P, const yaml::Node& croot, const fs::path& base, Matrix& m) {
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

void parsePatterns(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
    const yaml::Node patterns = P.required(croot, "patterns", "the matrix");
    if (!patterns.IsSequence() || patterns.size() == 0) P.fail(patterns, "patterns must be a non-empty list");
    for (const auto& p : patterns) {
        auto name = P.pattern(p);
        if (std::find(m.patterns.begin(), m.patterns.end(), name) != m.patterns.end())
            P.fail(p, "pattern '" + name + "' listed twice");
        m.patterns.push_back(name);
    }
}

void parseSpp(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
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
void parseSeeds(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
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
void parseReference(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
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

void parseCrop(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
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

void parseBaseline(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
    if (const yaml::Node b = croot["baseline"]) {
        P.expectMap(b, "baseline");
        P.onlyKeys(b, {"time_factor"}, "baseline");
        if (b["time_factor"]) m.baselineTimeFactor = P.positive(b["time_factor"], "time_factor");
    }
}

// checks: a list of claims, each read by its kind (check_kind.h).
void parseChecks(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
    const yaml::Node checks = croot["checks"];
    if (!checks) return;
    if (!checks.IsSequence()) P.fail(checks, "checks must be a list");
    const CheckReader reader(P, m);
    for (const auto& c : checks) m.checks.push_back(readCheck(reader, c));
}

} // namespace
// perceptual: { trials, repeats, controls, control_spp, margin, sets: [{ scene, region, patterns, spp }] }
void parsePerceptual(const MatrixReader& P, const yaml::Node& croot, Matrix& m) {
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
    MatrixReader P{yaml::StrictYaml(path), vocabulary};
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
