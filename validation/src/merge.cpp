#include "merge.h"

#include "shard_fingerprint.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <tuple>

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {
bool isMatrixCell(const Matrix& m, const ResultRow& row) {
    auto has = [](const auto& list, const auto& v) { return std::find(list.begin(), list.end(), v) != list.end(); };
    return m.findScene(row.scene) && has(m.patterns, row.pattern) && has(m.spp, row.spp) && has(m.seeds, row.seed);
}
} // namespace

Results mergeShards(const Matrix& m, const std::vector<std::string>& dirs, const std::string& out) {
    // Shards of different matrices or builds would average renders that cannot be compared: refuse them first.
    checkShardFingerprints(m, dirs);
    Results merged;
    merged.matrixName = m.name;
    std::set<std::tuple<std::string, std::string, uint32_t, uint64_t>> seen;
    for (const auto& dir : dirs) {
        Results r = readResultsJson((fs::path(dir) / "results.json").string());
        if (merged.fingerprint.empty()) merged.fingerprint = r.fingerprint;
        if (merged.rendererVersion.empty())
            merged.rendererVersion = r.rendererVersion;
        else if (r.rendererVersion != merged.rendererVersion)
            throw std::runtime_error(dir + ": renderer version '" + r.rendererVersion + "' differs from '" +
                                     merged.rendererVersion + "' of the other shards");
        for (const auto& k : r.skipped) merged.skipped.push_back({k.name, dir + ": " + k.error}); // stays reported
        for (const auto& s : r.scenes) {
            bool known = false;
            for (const auto& k : merged.scenes) known |= k.name == s.name;
            if (!known) merged.scenes.push_back(s);
        }
        for (const auto& row : r.rows) {
            if (!isMatrixCell(m, row))
                throw std::runtime_error(dir + ": " + row.scene + " " + row.pattern + " " + std::to_string(row.spp) +
                                         " spp seed " + std::to_string(row.seed) + " is not a cell × seed of " +
                                         m.path);
            if (!seen.insert({row.scene, row.pattern, row.spp, row.seed}).second)
                throw std::runtime_error(dir + ": " + row.scene + " " + row.pattern + " " + std::to_string(row.spp) +
                                         " spp seed " + std::to_string(row.seed) + " appears in two shards");
            merged.rows.push_back(row);
        }
        // Crops travel with the shard that rendered them.
        fs::path crops = fs::path(dir) / "crops";
        if (fs::is_directory(crops) && fs::absolute(crops) != fs::absolute(fs::path(out) / "crops")) {
            fs::create_directories(fs::path(out) / "crops");
            for (const auto& e : fs::directory_iterator(crops))
                fs::copy_file(e.path(), fs::path(out) / "crops" / e.path().filename(),
                              fs::copy_options::overwrite_existing);
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
