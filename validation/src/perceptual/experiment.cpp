// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "perceptual/experiment.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>

#include <stipple/render/image_io.h>

#include "metrics/regions.h"
#include "base/file_names.h"
#include "metrics/statistics.h"
#include "base/text.h"
#include "perceptual/study_key.h"
#include "perceptual/study_page.h"

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

uint64_t fnv1a(const void* data, size_t size, uint64_t h = 1469598103934665603ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

// An id from the crop's pixels and its cell: unique, stable for the same renders, and no pattern name in it.
std::string cropId(const render::Image& crop, const std::string& cell) {
    uint64_t h = fnv1a(crop.rgb.data(), crop.rgb.size() * sizeof(float));
    h = fnv1a(cell.data(), cell.size(), h);
    return fmt("%012llx", (unsigned long long)(h >> 16));
}

int regionIndex(const MatrixScene& scene, const std::string& region) {
    for (size_t i = 0; i < scene.regions.size(); ++i)
        if (scene.regions[i].name == region) return int(i);
    return -1;
}

} // namespace

bool writeStudyExperiment(const std::string& reportDir, const Matrix& m, const Results& results) {
    const PerceptualPlan& plan = m.perceptual;
    if (plan.sets.empty()) return true;
    const fs::path dir = fs::path(reportDir) / kStudyFolder;
    fs::create_directories(dir / "crops");
    StudyKey key;
    key.matrix = m.name;
    key.trials = plan.trials;
    key.repeats = plan.repeats;
    key.controls = plan.controls;
    key.controlSpp = plan.controlSpp;
    key.margin = plan.margin;
    std::string ids;
    for (const auto& ps : plan.sets) {
        const MatrixScene* scene = m.findScene(ps.scene);
        const int ri = regionIndex(*scene, ps.region);
        StudySet set;
        set.scene = ps.scene;
        set.region = ps.region;
        set.spp = ps.spp;
        set.name = ps.scene + " / " + ps.region;
        auto crop = [&](const std::string& pattern, uint32_t spp) -> std::optional<StudyCrop> {
            const fs::path exr = fs::path(reportDir) / cellExrFile(ps.scene, pattern, spp, m.seeds.front());
            if (!fs::exists(exr)) {
                std::cerr << "stipple-validate: perceptual experiment not written: " << exr.string()
                          << " is missing (the experiment is made by a run, from its renders)\n";
                return std::nullopt;
            }
            const render::Image image = render::readImage(exr.string());
            const render::Image region = regionImage(image, scene->regions[size_t(ri)], 1);
            StudyCrop c;
            c.pattern = pattern;
            c.spp = spp;
            c.width = region.width;
            c.height = region.height;
            c.id = cropId(region, ps.scene + "|" + ps.region + "|" + pattern + "|" + std::to_string(spp));
            render::writePng((dir / "crops" / (c.id + ".png")).string(), region);
            std::vector<double> flip, mse;
            for (const auto& r : results.rows) {
                if (r.scene != ps.scene || r.pattern != pattern || r.spp != spp) continue;
                if (size_t(ri) < r.regionFlip.size() && std::isfinite(r.regionFlip[size_t(ri)]))
                    flip.push_back(r.regionFlip[size_t(ri)]);
                if (size_t(ri) < r.regionMse.size() && std::isfinite(r.regionMse[size_t(ri)]))
                    mse.push_back(r.regionMse[size_t(ri)]);
            }
            const Interval f = meanInterval(flip);
            c.flip = flip.empty() ? NAN : f.mean;
            c.flipHalfWidth = flip.empty() ? NAN : f.halfWidth;
            c.rms = mse.empty() ? NAN : std::sqrt(mean(mse));
            ids += c.id;
            return c;
        };
        for (const auto& pattern : ps.patterns) {
            auto c = crop(pattern, ps.spp);
            if (!c) return false;
            set.crops.push_back(*c);
        }
        auto control = crop(ps.patterns.front(), plan.controlSpp);
        if (!control) return false;
        set.control = *control;
        key.sets.push_back(std::move(set));
    }
    key.study = fmt("%016llx", (unsigned long long)fnv1a(ids.data(), ids.size()));
    writeTextFile((dir / kStudyKeyFile).string(), studyKeyJson(key));
    std::string page = kStudyPageTemplate;
    const size_t at = page.find("@PLAN@");
    page.replace(at, std::strlen("@PLAN@"), studyPlanJson(key));
    writeTextFile((dir / "index.html").string(), page);
    return true;
}

} // namespace stipple::validation
