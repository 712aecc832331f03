#include "results.h"

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

#include <yaml-cpp/yaml.h>

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
        return std::make_tuple(indexOf(scenes, r.scene), r.scene, indexOf(matrix.patterns, r.pattern), r.pattern,
                               r.spp, seedIndex, r.seed);
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
        std::vector<double> rms, rmsMeasured, mse, mseCorrected, render, sampler;
        for (size_t k = i; k < j; ++k) {
            const auto& r = rows[k];
            rms.push_back(r.rmsCorrected);
            rmsMeasured.push_back(r.rms);
            mse.push_back(r.mse);
            mseCorrected.push_back(r.mseCorrected);
            render.push_back(r.renderSeconds);
            sampler.push_back(r.samplerSeconds);
            c.floorLimitedSeeds += r.floorLimited;
            c.nonFinitePixels += r.nonFinitePixels;
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
            for (const auto& r : rows) {
                if (r.scene != scene.name || r.pattern != pattern) continue;
                if (!(r.rmsCorrected > 0) || !std::isfinite(r.rmsCorrected)) {
                    ++f.excluded;
                    continue;
                }
                x.push_back(std::log(double(r.spp)));
                y.push_back(std::log(r.rmsCorrected));
            }
            if (x.empty() && f.excluded == 0) continue;
            f.fit = fitLine(x, y);
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

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (unsigned char ch : s) {
        switch (ch) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default:
            if (ch < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", ch);
                out += buf;
            } else out += char(ch);
        }
    }
    return out + "\"";
}

std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

void writeTextFile(const std::string& path, const std::string& text) {
    std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw std::runtime_error("cannot write " + tmp);
        out << text;
        if (!out) throw std::runtime_error("error writing " + tmp);
    }
    std::filesystem::rename(tmp, path);
}

void writeResultsCsv(const std::string& path, const std::vector<ResultRow>& rows) {
    // Times come last, so a comparison that ignores them can cut the columns before.
    std::ostringstream o;
    o << "scene,pattern,spp,seed,width,height,rms,mse,rms_corrected,mse_corrected,floor_limited,"
         "non_finite_pixels,non_finite_samples,render_seconds,sampler_seconds\n";
    char buf[512];
    for (const auto& r : rows) {
        std::snprintf(buf, sizeof buf, "%s,%s,%u,%llu,%d,%d,%.9g,%.9g,%.9g,%.9g,%d,%llu,%llu,%.6f,%.6f\n",
                      r.scene.c_str(), r.pattern.c_str(), r.spp, (unsigned long long)r.seed, r.width, r.height, r.rms,
                      r.mse, r.rmsCorrected, r.mseCorrected, int(r.floorLimited),
                      (unsigned long long)r.nonFinitePixels, (unsigned long long)r.nonFiniteSamples, r.renderSeconds,
                      r.samplerSeconds);
        o << buf;
    }
    writeTextFile(path, o.str());
}

void writeCellsCsv(const std::string& path, const std::vector<CellAggregate>& cells) {
    std::ostringstream o;
    o << "scene,pattern,spp,seeds,mean_rms,rms_ci95,mean_rms_measured,mean_mse_corrected,floor_limited_seeds,"
         "non_finite_pixels,efficiency,median_render_seconds,median_sampler_seconds\n";
    char buf[512];
    for (const auto& c : cells) {
        std::snprintf(buf, sizeof buf, "%s,%s,%u,%zu,%.9g,%.9g,%.9g,%.9g,%d,%llu,%.6g,%.6f,%.6f\n", c.scene.c_str(),
                      c.pattern.c_str(), c.spp, c.seeds, c.rms.mean, c.rms.halfWidth, c.meanRmsMeasured,
                      c.meanMseCorrected, c.floorLimitedSeeds, (unsigned long long)c.nonFinitePixels, c.efficiency,
                      c.medianRenderSeconds, c.medianSamplerSeconds);
        o << buf;
    }
    writeTextFile(path, o.str());
}

void writeResultsJson(const std::string& path, const Results& results, const std::vector<CellAggregate>& cells,
                      const std::vector<SlopeFit>& slopes, const std::string& checksJson) {
    std::ostringstream o;
    o << "{\n  \"format\": \"stipple-validate results 1\",\n";
    o << "  \"matrix\": " << jsonString(results.matrixName) << ",\n";
    o << "  \"renderer_version\": " << jsonString(results.rendererVersion) << ",\n";
    o << "  \"scenes\": [";
    for (size_t i = 0; i < results.scenes.size(); ++i) {
        const auto& s = results.scenes[i];
        o << (i ? ",\n" : "\n") << "    {\"name\": " << jsonString(s.name) << ", \"file\": " << jsonString(s.file)
          << ", \"content_hash\": " << jsonString(s.contentHash) << ", \"integrator\": " << jsonString(s.integrator)
          << ", \"width\": " << s.width << ", \"height\": " << s.height << ", \"triangles\": " << s.triangles
          << ", \"load_seconds\": " << jsonNumber(s.loadSeconds) << ", \"build_seconds\": " << jsonNumber(s.buildSeconds)
          << ", \"warmup_seconds\": " << jsonNumber(s.warmupSeconds)
          << ", \"reference_key\": " << jsonString(s.referenceKey) << ", \"reference_spp\": " << s.referenceSpp
          << ", \"reference_seconds\": " << jsonNumber(s.referenceSeconds)
          << ", \"noise_floor\": " << jsonNumber(s.noiseFloor) << "}";
    }
    o << "\n  ],\n  \"skipped_scenes\": [";
    for (size_t i = 0; i < results.skipped.size(); ++i)
        o << (i ? ",\n" : "\n") << "    {\"name\": " << jsonString(results.skipped[i].name)
          << ", \"error\": " << jsonString(results.skipped[i].error) << "}";
    o << "\n  ],\n  \"rows\": [";
    for (size_t i = 0; i < results.rows.size(); ++i) {
        const auto& r = results.rows[i];
        o << (i ? ",\n" : "\n") << "    {\"scene\": " << jsonString(r.scene) << ", \"pattern\": " << jsonString(r.pattern)
          << ", \"spp\": " << r.spp << ", \"seed\": " << r.seed << ", \"width\": " << r.width
          << ", \"height\": " << r.height << ", \"rms\": " << jsonNumber(r.rms) << ", \"mse\": " << jsonNumber(r.mse)
          << ", \"rms_corrected\": " << jsonNumber(r.rmsCorrected)
          << ", \"mse_corrected\": " << jsonNumber(r.mseCorrected)
          << ", \"floor_limited\": " << (r.floorLimited ? "true" : "false")
          << ", \"non_finite_pixels\": " << r.nonFinitePixels << ", \"non_finite_samples\": " << r.nonFiniteSamples
          << ", \"render_seconds\": " << jsonNumber(r.renderSeconds)
          << ", \"sampler_seconds\": " << jsonNumber(r.samplerSeconds) << "}";
    }
    o << "\n  ],\n  \"cells\": [";
    for (size_t i = 0; i < cells.size(); ++i) {
        const auto& c = cells[i];
        o << (i ? ",\n" : "\n") << "    {\"scene\": " << jsonString(c.scene) << ", \"pattern\": " << jsonString(c.pattern)
          << ", \"spp\": " << c.spp << ", \"seeds\": " << c.seeds << ", \"mean_rms\": " << jsonNumber(c.rms.mean)
          << ", \"rms_ci95\": " << jsonNumber(c.rms.halfWidth)
          << ", \"mean_rms_measured\": " << jsonNumber(c.meanRmsMeasured)
          << ", \"mean_mse_corrected\": " << jsonNumber(c.meanMseCorrected)
          << ", \"median_render_seconds\": " << jsonNumber(c.medianRenderSeconds)
          << ", \"median_sampler_seconds\": " << jsonNumber(c.medianSamplerSeconds)
          << ", \"efficiency\": " << jsonNumber(c.efficiency) << ", \"floor_limited_seeds\": " << c.floorLimitedSeeds
          << ", \"non_finite_pixels\": " << c.nonFinitePixels << "}";
    }
    o << "\n  ],\n  \"slopes\": [";
    for (size_t i = 0; i < slopes.size(); ++i) {
        const auto& s = slopes[i];
        o << (i ? ",\n" : "\n") << "    {\"scene\": " << jsonString(s.scene) << ", \"pattern\": " << jsonString(s.pattern)
          << ", \"slope\": " << jsonNumber(s.fit.slope) << ", \"ci95\": " << jsonNumber(s.fit.slopeHalfWidth)
          << ", \"points\": " << s.fit.count << ", \"excluded\": " << s.excluded << "}";
    }
    o << "\n  ],\n  \"checks\": " << (checksJson.empty() ? "[]" : checksJson) << "\n}\n";
    writeTextFile(path, o.str());
}

namespace {
// JSON is read through yaml-cpp (JSON is YAML's flow style); null numbers come back as NaN.
double number(const YAML::Node& n) {
    if (!n || n.IsNull()) return std::numeric_limits<double>::quiet_NaN();
    return n.as<double>();
}
} // namespace

Results readResultsJson(const std::string& path) {
    YAML::Node root;
    try {
        root = YAML::Load(render::readFileBounded(path, render::limits::kMaxYamlFileBytes, "results file"));
    } catch (const YAML::BadFile&) {
        throw std::runtime_error(path + ": cannot open results file");
    } catch (const YAML::ParserException& e) {
        throw std::runtime_error(path + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                                 ": " + e.msg);
    }
    Results r;
    const YAML::Node& c = root;
    try {
        if (!c.IsMap() || !c["format"] || c["format"].as<std::string>() != "stipple-validate results 1")
            throw std::runtime_error(path + ": not a stipple-validate results.json (no format \"stipple-validate results 1\")");
        r.matrixName = c["matrix"].as<std::string>("");
        r.rendererVersion = c["renderer_version"].as<std::string>("");
        for (const auto& s : c["scenes"]) {
            SceneInfo i;
            i.name = s["name"].as<std::string>();
            i.file = s["file"].as<std::string>("");
            i.contentHash = s["content_hash"].as<std::string>("");
            i.integrator = s["integrator"].as<std::string>("");
            i.width = s["width"].as<int>(0);
            i.height = s["height"].as<int>(0);
            i.triangles = s["triangles"].as<uint64_t>(0);
            i.loadSeconds = number(s["load_seconds"]);
            i.buildSeconds = number(s["build_seconds"]);
            i.warmupSeconds = number(s["warmup_seconds"]);
            i.referenceKey = s["reference_key"].as<std::string>("");
            i.referenceSpp = s["reference_spp"].as<uint32_t>(0);
            i.referenceSeconds = number(s["reference_seconds"]);
            i.noiseFloor = number(s["noise_floor"]);
            r.scenes.push_back(i);
        }
        for (const auto& s : c["skipped_scenes"]) {  // absent in files of older versions
            r.skipped.push_back({s["name"].as<std::string>(""), s["error"].as<std::string>("")});
        }
        for (const auto& n : c["rows"]) {
            ResultRow row;
            row.scene = n["scene"].as<std::string>();
            row.pattern = n["pattern"].as<std::string>();
            row.spp = n["spp"].as<uint32_t>();
            row.seed = n["seed"].as<uint64_t>();
            row.width = n["width"].as<int>(0);
            row.height = n["height"].as<int>(0);
            row.rms = number(n["rms"]);
            row.mse = number(n["mse"]);
            row.rmsCorrected = number(n["rms_corrected"]);
            row.mseCorrected = number(n["mse_corrected"]);
            row.floorLimited = n["floor_limited"].as<bool>(false);
            row.nonFinitePixels = n["non_finite_pixels"].as<uint64_t>(0);
            row.nonFiniteSamples = n["non_finite_samples"].as<uint64_t>(0);
            row.renderSeconds = number(n["render_seconds"]);
            row.samplerSeconds = number(n["sampler_seconds"]);
            r.rows.push_back(row);
        }
    } catch (const YAML::Exception& e) {
        std::string where = e.mark.line >= 0 ? ":" + std::to_string(e.mark.line + 1) + ":" +
                                                   std::to_string(e.mark.column + 1)
                                             : "";
        throw std::runtime_error(path + where + ": malformed results.json: " + e.msg);
    }
    return r;
}

} // namespace stipple::validation
