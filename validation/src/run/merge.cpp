// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/merge.h"

#include "metrics/image_metrics.h"
#include "metrics/regions.h"
#include "base/file_names.h"
#include "run/shard_fingerprint.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <tuple>

#include <stipple/render/temp_files.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {
bool isMatrixCell(const Matrix& m, const ResultRow& row) {
    auto has = [](const auto& list, const auto& v) { return std::find(list.begin(), list.end(), v) != list.end(); };
    return m.findScene(row.scene) && has(m.patterns, row.pattern) && has(m.spp, row.spp) && has(m.seeds, row.seed);
}

// What a measured row can hold: the shard's results.json is input like any other, so a row is checked against
// what measureRow could have produced before it is averaged. Empty when the row is plausible.
std::string rowProblem(const ResultRow& r, const MatrixScene& ms, const SceneInfo* scene, const Fingerprint& print) {
    auto bad = [](double v) { return !std::isfinite(v) || v < 0; };
    auto num = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, "%.6g", v);
        return std::string(b);
    };
    if (!scene) return "no scene entry for '" + r.scene + "' in the shard's scenes";
    // The size the fingerprint (which --merge compared across shards) gives the scene, else its scene entry's.
    auto side = [&](const char* key, int fallback) {
        const FingerprintField* f = print.find("scene." + r.scene + "." + key);
        return f ? f->value : std::to_string(fallback);
    };
    const std::string w = side("width", scene->width), h = side("height", scene->height);
    if (std::to_string(r.width) != w || std::to_string(r.height) != h || scene->width != r.width ||
        scene->height != r.height)
        return "size " + std::to_string(r.width) + "x" + std::to_string(r.height) + " is not the scene's " + w +
               "x" + h + " of the fingerprint";
    for (auto [what, v] : {std::pair{"mse", r.mse}, {"rms", r.rms}, {"mse_corrected", r.mseCorrected},
                           {"rms_corrected", r.rmsCorrected}})
        if (bad(v)) return std::string(what) + " " + num(v) + " is not a finite value ≥ 0";
    // rms is sqrt(mse) as measured: a row claiming otherwise (or a huge value beyond double's square) is not one.
    for (auto [rms, mse] : {std::pair{r.rms, r.mse}, {r.rmsCorrected, r.mseCorrected}})
        if (std::fabs(rms * rms - mse) > 1e-9 * std::max(mse, 1e-300) + 1e-300)
            return "rms " + num(rms) + " is not the square root of mse " + num(mse);
    if (r.mseCorrected > r.mse) return "mse_corrected " + num(r.mseCorrected) + " exceeds mse " + num(r.mse);
    for (auto [what, v] : {std::pair{"render_seconds", r.renderSeconds}, {"sampler_seconds", r.samplerSeconds},
                           {"cpu_seconds", r.cpuSeconds}})
        if (bad(v) || v > 1e7) return std::string(what) + " " + num(v) + " is not a time in [0, 1e7] s";
    if (r.nonFinitePixels > uint64_t(r.width) * uint64_t(r.height))
        return "non_finite_pixels " + std::to_string(r.nonFinitePixels) + " exceeds the image's pixels";
    const size_t regions = ms.regions.size();
    if (r.regionMse.size() != regions || r.regionMseCorrected.size() != regions)
        return "region values for " + std::to_string(r.regionMse.size()) + " regions; the scene has " +
               std::to_string(regions);
    for (double v : r.regionMse)
        if (bad(v)) return "a region mse " + num(v) + " is not a finite value ≥ 0";
    for (double v : r.regionMseCorrected)
        if (bad(v)) return "a region mse_corrected " + num(v) + " is not a finite value ≥ 0";
    // The per-block errors (what the compare claims' intervals are made of) must be the row's own: one value per
    // block of the image and of each region, finite and ≥ 0, and the image's squared errors summing to its mse
    // times the pixels compared.
    const size_t blocks = size_t(blockCount(r.width, r.height));
    size_t regionBlocks = 0;
    for (const Region& region : ms.regions) {
        const PixelRect px = pixelRect(region, r.width, r.height);
        regionBlocks += size_t(blockCount(px.w, px.h));
    }
    for (auto [what, list, count] :
         {std::tuple{"block_sse", &r.blockSse, blocks}, {"block_rse", &r.blockRse, blocks},
          {"block_flip", &r.blockFlip, blocks}, {"region_block_sse", &r.regionBlockSse, regionBlocks},
          {"region_block_rse", &r.regionBlockRse, regionBlocks}, {"region_block_flip", &r.regionBlockFlip, regionBlocks}}) {
        if (list->size() != count)
            return std::string(what) + " has " + std::to_string(list->size()) + " values; the image (or its regions) has " +
                   std::to_string(count) + " blocks";
        for (double v : *list)
            if (bad(v)) return std::string("a ") + what + " value " + num(v) + " is not a finite value ≥ 0";
    }
    double sse = 0;
    for (double v : r.blockSse) sse += v;
    const double compared = double(uint64_t(r.width) * uint64_t(r.height) - r.nonFinitePixels);
    if (std::fabs(sse - r.mse * compared) > 1e-6 * std::max(sse, r.mse * compared) + 1e-12)
        return "block_sse sums to " + num(sse) + ", not mse × pixels compared = " + num(r.mse * compared);
    return {};
}

// Copies a regular file, never following a symlink at `from` and never writing through one at `to`.
void copyRegularFile(const fs::path& from, const fs::path& to) {
    const int in = ::open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (in < 0) throw std::runtime_error("cannot read " + from.string() + ": " + std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() {
            if (fd >= 0) ::close(fd);
        }
    } inCloser{in}, outCloser{-1};
    struct stat st {};
    if (::fstat(in, &st) != 0 || !S_ISREG(st.st_mode))
        throw std::runtime_error(from.string() + ": not a regular file");
    outCloser.fd = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (outCloser.fd < 0) throw std::runtime_error("cannot write " + to.string() + ": " + std::strerror(errno));
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(in, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw std::runtime_error("cannot read " + from.string() + ": " + std::strerror(errno));
        if (n == 0) break;
        for (ssize_t done = 0; done < n;) {
            const ssize_t w = ::write(outCloser.fd, buf + done, size_t(n - done));
            if (w < 0 && errno == EINTR) continue;
            if (w < 0) throw std::runtime_error("cannot write " + to.string() + ": " + std::strerror(errno));
            done += w;
        }
    }
}

// The crops the report shows for the scenes and patterns of `rows`: file names inside crops/.
std::set<std::string> cropsNamedBy(const Matrix& m, const std::vector<ResultRow>& rows) {
    std::set<std::string> names;
    for (const ResultRow& r : rows) {
        const MatrixScene* ms = m.findScene(r.scene);
        if (!ms) continue;
        names.insert(safeName(ms->name) + "-reference-full.png");
        for (const std::string& column : {std::string("reference"), r.pattern}) {
            names.insert(fs::path(cropFile(ms->name, column)).filename().string());
            for (const Region& region : ms->regions)
                names.insert(fs::path(regionCropFile(ms->name, region.name, column)).filename().string());
        }
    }
    return names;
}
} // namespace

Results mergeShards(const Matrix& m, const std::vector<std::string>& dirs, const std::string& out) {
    // Shards of different matrices or builds would average renders that cannot be compared: refuse them first.
    checkShardFingerprints(m, dirs);
    Results merged;
    merged.matrixName = m.name;
    std::set<std::tuple<std::string, std::string, uint32_t, uint64_t>> seen;
    for (const auto& dir : dirs) {
        Results r = readResultsJson((fs::path(dir) / "results.json").string(), resultsFileByteLimit(m));
        if (merged.fingerprint.empty()) merged.fingerprint = r.fingerprint;
        if (merged.rendererVersion.empty())
            merged.rendererVersion = r.rendererVersion;
        else if (r.rendererVersion != merged.rendererVersion)
            throw std::runtime_error(dir + ": renderer version '" + r.rendererVersion + "' differs from '" +
                                     merged.rendererVersion + "' of the other shards");
        for (const auto& k : r.skipped) merged.skipped.push_back({k.name, dir + ": " + k.error}); // stays reported
        // One scene, one content: shards rendered by different programs or from different scene files (an
        // external renderer's hash covers its program's bytes) are not one run.
        for (const auto& s : r.scenes) {
            bool known = false;
            for (const auto& k : merged.scenes) {
                if (k.name != s.name) continue;
                known = true;
                if (k.contentHash != s.contentHash || k.integrator != s.integrator)
                    throw std::runtime_error(dir + ": scene " + s.name + " was rendered from other content (" +
                                             s.integrator + ", content hash " + s.contentHash + ") than in the other "
                                             "shards (" + k.integrator + ", " + k.contentHash + ")");
            }
            if (!known) merged.scenes.push_back(s);
        }
        for (const auto& row : r.rows) {
            if (!isMatrixCell(m, row))
                throw std::runtime_error(dir + ": " + row.scene + " " + row.pattern + " " + std::to_string(row.spp) +
                                         " spp seed " + std::to_string(row.seed) + " is not a cell × seed of " +
                                         m.path);
            const SceneInfo* info = nullptr;
            for (const auto& k : r.scenes)
                if (k.name == row.scene) info = &k;
            if (std::string why = rowProblem(row, *m.findScene(row.scene), info, r.fingerprint); !why.empty())
                throw std::runtime_error(dir + "/results.json: " + row.scene + " " + row.pattern + " " +
                                         std::to_string(row.spp) + " spp seed " + std::to_string(row.seed) + ": " +
                                         why);
            if (!seen.insert({row.scene, row.pattern, row.spp, row.seed}).second)
                throw std::runtime_error(dir + ": " + row.scene + " " + row.pattern + " " + std::to_string(row.spp) +
                                         " spp seed " + std::to_string(row.seed) + " appears in two shards");
            merged.rows.push_back(row);
        }
        // Crops travel with the shard that rendered them: only those its rows name, regular files only, never
        // through a symlink (a link to a private file must not become a readable copy in the report).
        const fs::path crops = fs::path(dir) / "crops";
        std::error_code ec;
        if (fs::is_directory(fs::symlink_status(crops, ec))) {
            fs::create_directories(fs::path(out) / "crops");
            for (const std::string& name : cropsNamedBy(m, r.rows)) {
                const fs::file_status st = fs::symlink_status(crops / name, ec);
                if (!fs::exists(st)) continue;
                if (!fs::is_regular_file(st)) {
                    render::warnLeftAlone((crops / name).string(), "not a regular file; not copied into the report");
                    continue;
                }
                fs::remove(fs::path(out) / "crops" / name, ec); // a crop of an earlier shard (same name)
                copyRegularFile(crops / name, fs::path(out) / "crops" / name);
            }
        } else if (fs::exists(fs::symlink_status(crops, ec))) {
            render::warnLeftAlone(crops.string(), "not a folder; its crops are not copied into the report");
        }
    }
    size_t missing = 0;
    std::string example;
    for (const auto& s : m.scenes) {
        if (std::any_of(merged.skipped.begin(), merged.skipped.end(),
                        [&](const SkippedScene& k) { return k.name == s.name; }))
            continue; // its rows are missing because it failed, which the merged run reports as an error
        for (const auto& p : m.patterns)
            for (uint32_t spp : m.spp)
                for (uint64_t seed : m.seeds)
                    if (!seen.count({s.name, p, spp, seed}) && missing++ == 0)
                        example = s.name + " " + p + " " + std::to_string(spp) + " spp seed " + std::to_string(seed);
    }
    if (missing)
        throw std::runtime_error("merge: " + std::to_string(missing) + " cell × seed rows of " + m.path +
                                 " are in none of the folders (e.g. " + example + "): did every shard finish?");
    std::vector<SceneInfo> ordered;
    for (const auto& s : m.scenes)
        for (const auto& k : merged.scenes)
            if (k.name == s.name) ordered.push_back(k);
    merged.scenes = ordered;
    sortRows(merged.rows, m);
    return merged;
}

} // namespace stipple::validation
