// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "claims/comparison_claims.h"
#include "base/text.h"

#include <cmath>
#include <map>

#include "claims/efficiency_claims.h"
#include "metrics/image_metrics.h"
#include "metrics/regions.h"

namespace stipple::validation {

bool pixelsIndependent(const std::string& pattern) { return pattern.find("blue-noise") == std::string::npos; }

namespace {

// Independent units of a rectangle's blocks: each block, or (blue noise) the shim's tiles on the whole image, or
// one unit for a region (not aligned with the tiles).
std::vector<int> unitsOf(const std::string& pattern, int x, int y, int w, int h, bool wholeImage) {
    if (pixelsIndependent(pattern)) return {};
    const int columns = blockColumns(w), count = blockCount(w, h);
    std::vector<int> units(size_t(count), 0);
    if (!wholeImage) return units;
    const int tilesX = (x + w + kBlueNoiseTilePixels - 1) / kBlueNoiseTilePixels;
    for (int b = 0; b < count; ++b) {
        const int px = x + (b % columns) * kErrorBlockSize, py = y + (b / columns) * kErrorBlockSize;
        units[size_t(b)] = (py / kBlueNoiseTilePixels) * tilesX + px / kBlueNoiseTilePixels;
    }
    // Renumber densely.
    std::map<int, int> dense;
    for (int& u : units) u = dense.emplace(u, int(dense.size())).first->second;
    return units;
}

} // namespace

ErrorEstimate patternError(const std::vector<ResultRow>& rows, const MatrixScene& scene, const std::string& pattern,
                           uint32_t spp, int region, bool flip, double floor, bool relative) {
    std::vector<std::vector<double>> perSeed;
    PixelRect rect;
    for (const auto& r : rows) {
        if (r.scene != scene.name || r.pattern != pattern || r.spp != spp) continue;
        const std::vector<double>& all = region < 0 ? (flip       ? r.blockFlip
                                                       : relative ? r.blockRse
                                                                  : r.blockSse)
                                                    : (flip       ? r.regionBlockFlip
                                                       : relative ? r.regionBlockRse
                                                                  : r.regionBlockSse);
        rect = region < 0 ? PixelRect{0, 0, r.width, r.height} : PixelRect{};
        size_t offset = 0;
        if (region >= 0) {
            if (size_t(region) >= scene.regions.size()) return {};
            for (int i = 0; i <= region; ++i) {
                rect = pixelRect(scene.regions[size_t(i)], r.width, r.height);
                if (i < region) offset += size_t(blockCount(rect.w, rect.h));
            }
        }
        const size_t n = size_t(blockCount(rect.w, rect.h));
        if (rect.w <= 0 || offset + n > all.size()) return {}; // no block lists (an older results.json)
        perSeed.emplace_back(all.begin() + long(offset), all.begin() + long(offset + n));
    }
    if (perSeed.empty()) return {};
    return estimateFromBlocks(perSeed, unitsOf(pattern, rect.x, rect.y, rect.w, rect.h, region < 0),
                              double(rect.w) * rect.h, flip ? 0.0 : floor);
}

double errorFloor(const std::vector<ResultRow>& rows, const std::string& scene, int region, bool flip, bool relative) {
    if (flip) return 0.0;
    if (!relative) return floorFromRows(rows, scene, region);
    double floor = 0;
    for (const auto& r : rows)
        if (r.scene == scene)
            floor = std::max(floor, region < 0                                 ? r.rseFloor
                                    : size_t(region) < r.regionRseFloor.size() ? r.regionRseFloor[size_t(region)]
                                                                               : 0.0);
    return floor;
}

LogShift cpuTimeShift(const std::vector<ResultRow>& rows, const std::string& scene, const std::string& a,
                      const std::string& b, uint32_t spp) {
    std::map<uint64_t, std::pair<double, double>> bySeed;
    for (const auto& r : rows) {
        if (r.scene != scene || r.spp != spp) continue;
        const double s = r.cpuSeconds > 0 ? r.cpuSeconds : r.renderSeconds;
        if (r.pattern == a) bySeed[r.seed].first = s;
        if (r.pattern == b) bySeed[r.seed].second = s;
    }
    std::vector<double> ta, tb;
    for (const auto& [seed, t] : bySeed) {
        ta.push_back(t.first);
        tb.push_back(t.second);
    }
    return pairedLogRatio(ta, tb);
}

Comparison comparePatterns(const std::vector<ResultRow>& rows, const MatrixScene& scene, const std::string& a,
                           const std::string& b, uint32_t spp, int region, bool flip, bool equalTime,
                           const Margin& margin, bool relative) {
    const double floor = errorFloor(rows, scene.name, region, flip, relative);
    const ErrorEstimate ea = patternError(rows, scene, a, spp, region, flip, floor, relative);
    const ErrorEstimate eb = patternError(rows, scene, b, spp, region, flip, floor, relative);
    return compareErrors(ea, eb, margin, equalTime ? cpuTimeShift(rows, scene.name, a, b, spp) : LogShift{});
}

CheckStatus statusFor(Expectation expect, const Comparison& c) {
    const Verdict v = c.verdict;
    if (v == Verdict::Unmeasured) return CheckStatus::Fail;
    const bool better = c.hi95 < 1, worse = c.lo95 > 1;
    switch (expect) {
    case Expectation::Any: return v == Verdict::NotSeparated ? CheckStatus::NotSeparated : CheckStatus::Pass;
    case Expectation::Equivalent:
        return c.equivalent ? CheckStatus::Pass : c.separated ? CheckStatus::Fail : CheckStatus::NotSeparated;
    // "Better" needs the 95% interval below 1 (an equivalent but separated gain counts); an equivalence inside the
    // margin that is not separated refutes a gain worth the margin.
    case Expectation::Better:
        return better ? CheckStatus::Pass : (worse || c.equivalent) ? CheckStatus::Fail : CheckStatus::NotSeparated;
    case Expectation::Worse:
        return worse ? CheckStatus::Pass : (better || c.equivalent) ? CheckStatus::Fail : CheckStatus::NotSeparated;
    }
    return CheckStatus::Fail;
}

Verdict decidingVerdict(Expectation expect, const Comparison& c) {
    if (c.verdict == Verdict::Unmeasured) return c.verdict;
    if (expect == Expectation::Better && c.hi95 < 1) return Verdict::Better;
    if (expect == Expectation::Worse && c.lo95 > 1) return Verdict::Worse;
    return c.verdict;
}

const char* expectationName(Expectation e) {
    switch (e) {
    case Expectation::Any: return "any";
    case Expectation::Equivalent: return "equivalent";
    case Expectation::Better: return "better";
    case Expectation::Worse: return "worse";
    }
    return "?";
}

Json verdictsJson(const std::vector<VerdictRow>& verdicts) {
    Json a = Json::array();
    auto num = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
    for (const auto& v : verdicts)
        a.push_back(Json{{"scene", v.scene},
                         {"region", v.region},
                         {"a", v.a},
                         {"b", v.b},
                         {"spp", v.spp},
                         {"basis", v.equalTime ? "time" : "samples"},
                         {"metric", v.flip ? "flip" : "mse"},
                         {"ratio", num(v.comparison.ratio)},
                         {"lo95", num(v.comparison.lo95)},
                         {"hi95", num(v.comparison.hi95)},
                         {"lo90", num(v.comparison.lo90)},
                         {"hi90", num(v.comparison.hi90)},
                         {"dof", num(v.comparison.dof)},
                         {"verdict", verdictName(v.comparison.verdict)},
                         {"status", checkStatusName(v.status)}});
    return a;
}

} // namespace stipple::validation
