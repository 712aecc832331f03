// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/preflight.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <stipple/render/renderer.h>
#include <stipple/render/temp_files.h>

#include "run/results.h"

namespace stipple::validation {

namespace fs = std::filesystem;

std::map<std::string, std::string> preflight(const PreflightInputs& in) {
    if (!in.baselinePath.empty()) {
        Results base;
        try {
            base = readResultsJson(in.baselinePath, in.resultsMaxBytes);
        } catch (const std::exception& e) {
            throw PreflightError(std::string("--baseline: ") + e.what());
        }
        if (base.rows.empty())
            throw PreflightError("--baseline " + in.baselinePath +
                                 ": no result rows (not a results.json of stipple-validate)");
    }

    std::error_code ec;
    if (!in.reportDir.empty() && !in.cacheDir.empty()) {
        const fs::path cache = fs::weakly_canonical(in.cacheDir, ec), report = fs::weakly_canonical(in.reportDir, ec);
        const auto [r, c] = std::mismatch(report.begin(), report.end(), cache.begin(), cache.end());
        if (r == report.end())
            throw PreflightError("cache folder " + in.cacheDir + " is inside the report folder " + in.reportDir +
                                 ", which is replaced whole by each run");
    }

    // Publishing the merged report replaces its folder whole: never onto, into or around a shard it reads.
    if (!in.reportDir.empty())
        for (const std::string& shard : in.mergeDirs) {
            const fs::path a = fs::weakly_canonical(fs::absolute(in.reportDir), ec),
                           b = fs::weakly_canonical(fs::absolute(shard), ec);
            const auto inside = [](const fs::path& x, const fs::path& y) {
                return std::mismatch(y.begin(), y.end(), x.begin(), x.end()).first == y.end();
            };
            if (inside(a, b) || inside(b, a))
                throw PreflightError("-o " + in.reportDir + ": overlaps the shard folder " + shard +
                                     " that --merge reads; choose another report folder");
        }

    if (!in.cacheDir.empty()) {
        fs::create_directories(in.cacheDir, ec);
        if (ec) throw PreflightError("cache folder " + in.cacheDir + ": cannot create it: " + ec.message());
        render::sweepStaleTemps(in.cacheDir);
        {
            render::TempPath probe((fs::path(in.cacheDir) / "write-probe").string());
            render::SignalHold hold;
            std::ofstream out(probe.path());
            out << "probe\n";
            out.close();
            if (!out) throw PreflightError("cache folder " + in.cacheDir + ": not writable");
        }
    }

    std::map<std::string, std::string> failed;
    if (!in.matrix) return failed;
    for (const MatrixScene& s : in.matrix->scenes) {
        if (!s.renderer.empty()) continue; // an external renderer's scene file is in its own format
        try {
            render::checkSceneFile(s.path);
        } catch (const std::bad_alloc&) {
            failed[s.name] = s.path + ": out of memory while loading the scene";
        } catch (const std::exception& e) {
            failed[s.name] = e.what();
        }
    }
    return failed;
}

} // namespace stipple::validation
