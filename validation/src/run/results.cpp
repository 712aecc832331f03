// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/results.h"
#include "base/fields.h"
#include "metrics/image_metrics.h"
#include "metrics/regions.h"

#include <stipple/render/input_limits.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <stipple/render/temp_files.h>

namespace stipple::validation {

namespace {
size_t indexOf(const std::vector<std::string>& list, const std::string& s) {
    auto it = std::find(list.begin(), list.end(), s);
    return size_t(it - list.begin());
}
std::vector<std::string> sceneNames(const Matrix& m) {
    std::vector<std::string> names;
    for (const auto& s : m.scenes) names.push_back(s.name);
    return names;
}
} // namespace

void sortRows(std::vector<ResultRow>& rows, const Matrix& matrix) {
    const auto scenes = sceneNames(matrix);
    auto key = [&](const ResultRow& r) {
        size_t seedIndex = size_t(std::find(matrix.seeds.begin(), matrix.seeds.end(), r.seed) - matrix.seeds.begin());
        return std::make_tuple(indexOf(scenes, r.scene), r.scene, indexOf(matrix.patterns, r.pattern), r.pattern, r.spp,
                               seedIndex, r.seed);
    };
    std::stable_sort(rows.begin(), rows.end(), [&](const ResultRow& a, const ResultRow& b) { return key(a) < key(b); });
}

std::vector<CellAggregate> aggregate(const std::vector<ResultRow>& rows) {
    std::vector<CellAggregate> cells;
    size_t i = 0;
    while (i < rows.size()) {
        size_t j = i;
        while (j < rows.size() && rows[j].scene == rows[i].scene && rows[j].pattern == rows[i].pattern &&
               rows[j].spp == rows[i].spp)
            ++j;
        CellAggregate c;
        c.scene = rows[i].scene;
        c.pattern = rows[i].pattern;
        c.spp = rows[i].spp;
        std::vector<double> rms, rmsMeasured, mse, mseCorrected, render, sampler, cpu;
        for (size_t k = i; k < j; ++k) {
            const auto& r = rows[k];
            rms.push_back(r.rmsCorrected);
            rmsMeasured.push_back(r.rms);
            mse.push_back(r.mse);
            mseCorrected.push_back(r.mseCorrected);
            render.push_back(r.renderSeconds);
            sampler.push_back(r.samplerSeconds);
            cpu.push_back(r.cpuSeconds);
            c.floorLimitedSeeds += r.floorLimited;
            c.nonFinitePixels += r.nonFinitePixels;
            c.unmeasuredSeeds += !std::isfinite(r.mse) || !std::isfinite(r.mseCorrected) ||
                                 !std::isfinite(r.rms) || !std::isfinite(r.rmsCorrected);
        }
        c.seeds = j - i;
        c.rms = meanInterval(rms);
        auto logsOfPositive = [](const std::vector<double>& values) {
            std::vector<double> logs;
            for (double x : values)
                if (x > 0) logs.push_back(std::log(x));
            return summarize(logs);
        };
        c.logRms = logsOfPositive(rms);
        c.logRmsMeasured = logsOfPositive(rmsMeasured);
        c.meanRmsMeasured = mean(rmsMeasured);
        c.meanMse = mean(mse);
        c.meanMseCorrected = mean(mseCorrected);
        c.medianRenderSeconds = median(render);
        c.medianSamplerSeconds = median(sampler);
        c.medianCpuSeconds = median(cpu);
        double denom = c.meanMseCorrected * c.medianRenderSeconds;
        c.efficiency = denom > 0 ? 1.0 / denom : std::numeric_limits<double>::infinity();
        cells.push_back(c);
        i = j;
    }
    return cells;
}

std::vector<SlopeFit> fitSlopes(const std::vector<ResultRow>& rows, const Matrix& matrix) {
    std::vector<SlopeFit> fits;
    for (const auto& scene : matrix.scenes)
        for (const auto& pattern : matrix.patterns) {
            SlopeFit f;
            f.scene = scene.name;
            f.pattern = pattern;
            std::vector<double> x, y;
            bool unmeasured = false;
            for (const auto& r : rows) {
                if (r.scene != scene.name || r.pattern != pattern) continue;
                // A point with no finite error makes the fit unmeasured, never a fit of the other points.
                if (!std::isfinite(r.rmsCorrected) || !std::isfinite(r.rms)) {
                    unmeasured = true;
                    continue;
                }
                if (!(r.rmsCorrected > 0)) {
                    ++f.excluded;
                    continue;
                }
                x.push_back(std::log(double(r.spp)));
                y.push_back(std::log(r.rmsCorrected));
            }
            if (x.empty() && f.excluded == 0 && !unmeasured) continue;
            f.fit = fitLine(x, y);
            if (unmeasured) f.fit.slope = f.fit.intercept = f.fit.slopeHalfWidth = std::nan("");
            fits.push_back(f);
        }
    return fits;
}

const CellAggregate* findCell(const std::vector<CellAggregate>& cells, const std::string& scene,
                              const std::string& pattern, uint32_t spp) {
    for (const auto& c : cells)
        if (c.scene == scene && c.pattern == pattern && c.spp == spp) return &c;
    return nullptr;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

void writeTextFile(const std::string& path, const std::string& text) {
    render::TempPath tmp(path);
    render::SignalHold hold; // written and renamed before a signal's cleanup, or not at all
    {
        std::ofstream out(tmp.path(), std::ios::binary);
        if (!out) throw std::runtime_error("cannot write " + tmp.path());
        out << text;
        if (!out) throw std::runtime_error("error writing " + tmp.path());
    }
    std::filesystem::rename(tmp.path(), path);
    tmp.release();
}

// ---- the field lists: JSON (both ways) and CSV come from these -------------------------------------------------

const Fields<ResultRow>& resultRowFields() {
    // Times come last, so a comparison that ignores them can cut the columns before.
    static const Fields<ResultRow> fields = {
        field("scene", &ResultRow::scene, "", true),
        field("pattern", &ResultRow::pattern, "", true),
        field("spp", &ResultRow::spp, "", true),
        field("seed", &ResultRow::seed, "", true),
        field("width", &ResultRow::width),
        field("height", &ResultRow::height),
        field("rms", &ResultRow::rms),
        field("mse", &ResultRow::mse),
        field("rms_corrected", &ResultRow::rmsCorrected),
        field("mse_corrected", &ResultRow::mseCorrected),
        field("floor_limited", &ResultRow::floorLimited),
        field("non_finite_pixels", &ResultRow::nonFinitePixels),
        field("non_finite_samples", &ResultRow::nonFiniteSamples),
        field("flip", &ResultRow::flip),
        field("spectrum_ratio", &ResultRow::spectrumRatio),
        doublesField("region_mse", &ResultRow::regionMse),
        doublesField("region_mse_corrected", &ResultRow::regionMseCorrected),
        doublesField("region_flip", &ResultRow::regionFlip),
        doublesField("region_spectrum_ratio", &ResultRow::regionSpectrumRatio),
        jsonOnlyDoublesField("block_sse", &ResultRow::blockSse),
        jsonOnlyDoublesField("block_flip", &ResultRow::blockFlip),
        jsonOnlyDoublesField("region_block_sse", &ResultRow::regionBlockSse),
        jsonOnlyDoublesField("region_block_flip", &ResultRow::regionBlockFlip),
        jsonOnlyDoublesField("block_rse", &ResultRow::blockRse),
        jsonOnlyDoublesField("region_block_rse", &ResultRow::regionBlockRse),
        field("rse_floor", &ResultRow::rseFloor),
        jsonOnlyDoublesField("region_rse_floor", &ResultRow::regionRseFloor),
        field("render_seconds", &ResultRow::renderSeconds, "%.6f"),
        field("sampler_seconds", &ResultRow::samplerSeconds, "%.6f"),
        field("cpu_seconds", &ResultRow::cpuSeconds, "%.6f"),
    };
    return fields;
}

const Fields<SceneInfo>& sceneInfoFields() {
    static const Fields<SceneInfo> fields = {
        field("name", &SceneInfo::name, "", true),
        field("file", &SceneInfo::file),
        field("content_hash", &SceneInfo::contentHash),
        field("integrator", &SceneInfo::integrator),
        field("width", &SceneInfo::width),
        field("height", &SceneInfo::height),
        field("triangles", &SceneInfo::triangles),
        field("load_seconds", &SceneInfo::loadSeconds),
        field("build_seconds", &SceneInfo::buildSeconds),
        field("warmup_seconds", &SceneInfo::warmupSeconds),
        field("reference_key", &SceneInfo::referenceKey),
        field("reference_spp", &SceneInfo::referenceSpp),
        field("reference_seconds", &SceneInfo::referenceSeconds),
        field("noise_floor", &SceneInfo::noiseFloor),
    };
    return fields;
}

const Fields<SkippedScene>& skippedSceneFields() {
    static const Fields<SkippedScene> fields = {field("name", &SkippedScene::name),
                                                field("error", &SkippedScene::error)};
    return fields;
}

const Fields<CellAggregate>& cellFields() {
    using C = CellAggregate;
    static const Fields<C> fields = {
        field("scene", &C::scene),
        field("pattern", &C::pattern),
        field("spp", &C::spp),
        field("seeds", &C::seeds),
        field<C>("mean_rms", [](C& c) -> double& { return c.rms.mean; }),
        field<C>("rms_ci95", [](C& c) -> double& { return c.rms.halfWidth; }),
        field("mean_rms_measured", &C::meanRmsMeasured),
        field("mean_mse_corrected", &C::meanMseCorrected),
        field("floor_limited_seeds", &C::floorLimitedSeeds),
        field("non_finite_pixels", &C::nonFinitePixels),
        field("efficiency", &C::efficiency, "%.6g"),
        field("median_render_seconds", &C::medianRenderSeconds, "%.6f"),
        field("median_sampler_seconds", &C::medianSamplerSeconds, "%.6f"),
        field("median_cpu_seconds", &C::medianCpuSeconds, "%.6f"),
    };
    return fields;
}

const Fields<SlopeFit>& slopeFields() {
    using S = SlopeFit;
    static const Fields<S> fields = {
        field("scene", &S::scene),
        field("pattern", &S::pattern),
        field<S>("slope", [](S& s) -> double& { return s.fit.slope; }),
        field<S>("ci95", [](S& s) -> double& { return s.fit.slopeHalfWidth; }),
        field<S>("points", [](S& s) -> size_t& { return s.fit.count; }),
        field("excluded", &S::excluded),
    };
    return fields;
}

// ---- writers and the reader ---------------------------------------------------------------------------------------

void writeResultsCsv(const std::string& path, const std::vector<ResultRow>& rows) {
    writeTextFile(path, csvTable(rows, resultRowFields()));
}

void writeCellsCsv(const std::string& path, const std::vector<CellAggregate>& cells) {
    writeTextFile(path, csvTable(cells, cellFields()));
}

namespace {

constexpr const char* kResultsFormat = "stipple-validate results 1";

template <class Record>
Json toJsonArray(const std::vector<Record>& records, const Fields<Record>& fields) {
    Json a = Json::array();
    for (const auto& r : records) a.push_back(toJson(r, fields));
    return a;
}

template <class Record>
std::vector<Record> fromJsonArray(const Json& root, const char* key, const Fields<Record>& fields,
                                  const std::string& path) {
    std::vector<Record> records;
    auto it = root.find(key);
    if (it == root.end() || it->is_null()) return records; // e.g. skipped_scenes, absent in older files
    if (!it->is_array()) throw std::runtime_error(path + ": malformed results.json: '" + key + "' is not an array");
    for (size_t i = 0; i < it->size(); ++i)
        records.push_back(
            fromJson((*it)[i], fields, path + ": malformed results.json: " + key + "[" + std::to_string(i) + "]"));
    return records;
}

} // namespace

void writeResultsJson(const std::string& path, const Results& results, const std::vector<CellAggregate>& cells,
                      const std::vector<SlopeFit>& slopes, const Json& checks) {
    Json root = Json::object();
    root["format"] = kResultsFormat;
    root["matrix"] = results.matrixName;
    root["renderer_version"] = results.rendererVersion;
    if (!results.fingerprint.empty()) root["fingerprint"] = Json::parse(fingerprintJson(results.fingerprint));
    root["scenes"] = toJsonArray(results.scenes, sceneInfoFields());
    root["skipped_scenes"] = toJsonArray(results.skipped, skippedSceneFields());
    root["rows"] = toJsonArray(results.rows, resultRowFields());
    root["cells"] = toJsonArray(cells, cellFields());
    root["slopes"] = toJsonArray(slopes, slopeFields());
    root["checks"] = checks.is_null() ? Json::array() : checks;
    writeTextFile(path, root.dump(2) + "\n");
}

uint64_t resultsFileByteLimit(const Matrix& m) {
    // As writeResultsJson lays a row out (dump(2)): a list value is a line of 8 spaces, at most 24 characters of a
    // double and ",\n" (34 bytes; 48 allowed); the row's ~30 scalars and two names fit in 8 KiB; a region adds six
    // values outside the block lists. Each row holds three lists (SSE, relative SE, FLIP) of its image's and its
    // regions' blocks.
    constexpr double kBytesPerValue = 48, kBytesPerRow = 8192, kBytesPerRegion = 6 * kBytesPerValue;
    // A render's most blocks: ceil(w/8) ceil(h/8) <= w h / 64 + (w + h) / 8 + 1 with w h <= kMaxPixels.
    constexpr double kMaxBlocks = double(render::limits::kMaxPixels) / (kErrorBlockSize * kErrorBlockSize) +
                                  2.0 * render::limits::kMaxImageSide / kErrorBlockSize + 1;
    // Scenes, cells, slopes, checks and the fingerprint: within the limit every other input file has.
    double bytes = double(render::limits::kMaxYamlFileBytes);
    const double rowsPerScene = double(m.patterns.size()) * double(m.spp.size()) * double(m.seeds.size());
    for (const MatrixScene& s : m.scenes) {
        double blocks = 0;
        if (s.width > 0 && s.height > 0) {
            blocks = blockCount(s.width, s.height);
            for (const Region& r : s.regions) {
                const PixelRect px = pixelRect(r, s.width, s.height);
                blocks += blockCount(px.w, px.h);
            }
        } else {
            blocks = double(1 + s.regions.size()) * kMaxBlocks; // the scene's own size, not known before loading it
        }
        bytes += rowsPerScene * (kBytesPerRow + double(s.regions.size()) * kBytesPerRegion + 3 * blocks * kBytesPerValue);
    }
    return uint64_t(std::min(bytes, double(kMaxResultsFileBytes)));
}

Results readResultsJson(const std::string& path, uint64_t maxBytes) {
    std::string text;
    try {
        text = render::readFileBounded(path, maxBytes, "results file");
    } catch (const render::InputLimitError& e) {
        throw std::runtime_error(e.what());
    }
    Json root;
    try {
        root = Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        // file:line:column of the byte where parsing stopped, as every other reader of the project names it.
        const size_t at = std::min<size_t>(e.byte ? e.byte - 1 : 0, text.size());
        const size_t line = 1 + std::count(text.begin(), text.begin() + at, '\n');
        const size_t lineStart = text.rfind('\n', at ? at - 1 : 0);
        const size_t column = at - (lineStart == std::string::npos || at == 0 ? 0 : lineStart + 1) + 1;
        throw std::runtime_error(path + ":" + std::to_string(line) + ":" + std::to_string(column) +
                                 ": not valid JSON: " + e.what());
    }
    if (!root.is_object() || !root.contains("format") || root["format"] != kResultsFormat)
        throw std::runtime_error(path + ": not a stipple-validate results.json (no format \"" +
                                 std::string(kResultsFormat) + "\")");
    Results r;
    try {
        r.matrixName = root.value("matrix", "");
        r.rendererVersion = root.value("renderer_version", "");
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path + ": malformed results.json: " + e.what());
    }
    r.fingerprint = parseFingerprint(text, path);
    r.scenes = fromJsonArray(root, "scenes", sceneInfoFields(), path);
    r.skipped = fromJsonArray(root, "skipped_scenes", skippedSceneFields(), path);
    r.rows = fromJsonArray(root, "rows", resultRowFields(), path);
    return r;
}

} // namespace stipple::validation
