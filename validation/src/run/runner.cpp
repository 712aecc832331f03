// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/runner.h"
#include "base/text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <stdlib.h>

#include <stipple/render/renderer.h>

#include "metrics/image_metrics.h"
#include "run/progress.h"
#include "run/cell_renderer.h"
#include "run/reference_cache.h"
#include "metrics/regions.h"
#include "metrics/error_spectrum.h"
#include "metrics/flip.h"
#include "base/file_names.h"
#include "run/run_fingerprint.h"

namespace stipple::validation {

namespace fs = std::filesystem;

std::vector<CellGroup> shardGroups(const Matrix& m, int shardIndex, int shardCount) {
    std::vector<CellGroup> groups;
    size_t g = 0;
    for (size_t s = 0; s < m.scenes.size(); ++s)
        for (uint32_t spp : m.spp)
            for (uint64_t seed : m.seeds) {
                if (g % size_t(shardCount) == size_t(shardIndex - 1)) groups.push_back({s, spp, seed});
                ++g;
            }
    return groups;
}

namespace {

void writeCrop(const std::string& reportDir, const std::string& scene, const std::string& column,
               const render::Image& image, const CropSettings& crop) {
    int size = std::min({crop.size, image.width, image.height});
    int x = int(crop.x * image.width) - size / 2, y = int(crop.y * image.height) - size / 2;
    fs::create_directory(fs::path(reportDir) / "crops"); // never its parent: see writeReport
    render::writePng((fs::path(reportDir) / cropFile(scene, column)).string(),
                     cropImage(image, x, y, size, size, crop.scale));
}

// One cell × seed: its render against the reference, the reference's noise floor removed.
ResultRow measureRow(const std::string& scene, const render::RenderOptions& o, const render::RenderResult& r,
                     const Reference& ref, double noiseFloor) {
    const ImageError e = compareImages(ref.image, r.image);
    // No verdict from a broken image: the cell is an error, never an error of 0 or of a few pixels.
    if (const std::string why = unmeasurableWhy(e); !why.empty())
        throw std::runtime_error("scene " + scene + ", " + o.pattern + ", " + std::to_string(o.spp) + " spp, seed " +
                                 std::to_string(o.seed) + ": the image cannot be measured: " + why);
    ResultRow row;
    row.scene = scene;
    row.pattern = o.pattern;
    row.spp = o.spp;
    row.seed = o.seed;
    row.width = r.image.width;
    row.height = r.image.height;
    row.mse = e.mse;
    row.rms = e.rms;
    row.mseCorrected = correctedMse(e.mse, noiseFloor);
    row.rmsCorrected = std::sqrt(row.mseCorrected);
    row.floorLimited = floorLimited(row.mseCorrected, noiseFloor);
    row.nonFinitePixels = e.nonFinitePixels;
    row.nonFiniteSamples = r.nonFiniteSamples;
    row.renderSeconds = r.renderSeconds;
    row.samplerSeconds = r.samplerSeconds;
    row.cpuSeconds = r.cpuSeconds;
    return row;
}

// The study's Table 1 at a size a person can judge: each region magnified to ≥ 128 px on its short side.
void writeRegionCrops(const std::string& reportDir, const MatrixScene& scene, const std::string& column,
                      const render::Image& image) {
    for (const Region& region : scene.regions) {
        const int scale = regionCropScale(pixelRect(region, image.width, image.height));
        fs::create_directory(fs::path(reportDir) / "crops"); // never its parent: see writeReport
        render::writePng((fs::path(reportDir) / regionCropFile(scene.name, region.name, column)).string(),
                         regionImage(image, region, scale));
    }
}

// One seed's render of each cell as EXR, for viewers outside the report.
void writeCellExr(const std::string& reportDir, const std::string& scene, const render::RenderOptions& o,
                  const render::Image& image) {
    fs::create_directory(fs::path(reportDir) / "exr"); // never its parent: see writeReport
    render::writeExr((fs::path(reportDir) / cellExrFile(scene, o.pattern, o.spp, o.seed)).string(), image,
                     {{"scene", scene}, {"pattern", o.pattern}, {"spp", std::to_string(o.spp)},
                      {"seed", std::to_string(o.seed)}});
}

// Per region, a false-colour error map of each pattern's crop render, all on one scale: the largest 99th
// percentile of the per-pixel error over the patterns (a few fireflies do not wash the maps out).
void writeRegionErrorMaps(const std::string& reportDir, const MatrixScene& scene, const render::Image& reference,
                          const std::vector<std::pair<std::string, render::Image>>& renders) {
    if (renders.empty()) return;
    fs::create_directory(fs::path(reportDir) / "crops"); // never its parent: see writeReport
    render::writePng((fs::path(reportDir) / kErrorBarFile).string(), errorColourBar(256, 12));
    for (const Region& region : scene.regions) {
        const PixelRect px = pixelRect(region, reference.width, reference.height);
        double scale = 0;
        for (const auto& [pattern, image] : renders)
            scale = std::max(scale, errorQuantile(reference, image, px.x, px.y, px.w, px.h, 0.99));
        for (const auto& [pattern, image] : renders)
            render::writePng((fs::path(reportDir) / regionErrorMapFile(scene.name, region.name, pattern)).string(),
                             errorMap(reference, image, px.x, px.y, px.w, px.h, scale, regionCropScale(px)));
        writeTextFile((fs::path(reportDir) / (regionErrorMapFile(scene.name, region.name, "scale") + ".txt")).string(),
                      fmt("%.6g\n", scale));
    }
}

// Perceptual error and the error's spectrum, after the timed render, and the error per region. FLIP is computed
// on the whole image (its filters see a region's surroundings) and averaged per region.
void addImageMetrics(ResultRow& row, const Reference& ref, const render::Image& image, const MatrixScene& ms,
                     const std::vector<double>& regionFloors) {
    const FlipMaps flip = ldrFlipLinear(ref.image, image);
    row.flip = flip.mean();
    row.blockSse = blockSquaredErrors(ref.image, image, 0, 0, image.width, image.height);
    const std::vector<float> weights = relativeErrorWeights(ref.image, ref.variance);
    row.blockRse = blockRelativeSquaredErrors(ref.image, image, weights, 0, 0, image.width, image.height);
    row.rseFloor = relativeNoiseFloor(ref.variance, weights, 0, 0, image.width, image.height);
    row.blockFlip = blockSums(flip.flip, flip.width, 0, 0, image.width, image.height);
    row.spectrumRatio = errorSpectrum(ref.image, image).highOverLow;
    for (size_t ri = 0; ri < ms.regions.size(); ++ri) {
        const Region& region = ms.regions[ri];
        const PixelRect px = pixelRect(region, image.width, image.height);
        double sum = 0;
        for (int y = px.y; y < px.y + px.h; ++y)
            for (int x = px.x; x < px.x + px.w; ++x) sum += flip.flip[size_t(y) * flip.width + x];
        row.regionFlip.push_back(sum / double(px.w * px.h));
        row.regionSpectrumRatio.push_back(
            errorSpectrum(regionImage(ref.image, region), regionImage(image, region)).highOverLow);
        const double mse = regionError(ref.image, image, region).mse;
        row.regionMse.push_back(mse);
        row.regionMseCorrected.push_back(correctedMse(mse, regionFloors[ri]));
        for (double v : blockSquaredErrors(ref.image, image, px.x, px.y, px.w, px.h)) row.regionBlockSse.push_back(v);
        for (double v : blockRelativeSquaredErrors(ref.image, image, weights, px.x, px.y, px.w, px.h))
            row.regionBlockRse.push_back(v);
        row.regionRseFloor.push_back(relativeNoiseFloor(ref.variance, weights, px.x, px.y, px.w, px.h));
        for (double v : blockSums(flip.flip, flip.width, px.x, px.y, px.w, px.h)) row.regionBlockFlip.push_back(v);
    }
}

} // namespace

Results runMatrix(const Matrix& m, const RunOptions& opt) {
    Results results;
    results.matrixName = m.name;
    results.rendererVersion = render::rendererVersion();
    const auto groups = shardGroups(m, opt.shardIndex, opt.shardCount);
    const int threads = opt.threads ? opt.threads : m.threads;
    const uint32_t cropSpp = m.crop.spp ? m.crop.spp : m.spp.back();

    // Work in spp: every cell × seed, and every scene's reference (taken off again when it comes from the cache).
    double work = 0;
    std::vector<bool> sceneRuns(m.scenes.size(), false);
    for (const auto& g : groups) {
        if (!opt.referencesOnly) work += double(g.spp) * double(m.patterns.size());
        sceneRuns[g.scene] = true;
    }
    for (size_t si = 0; si < m.scenes.size(); ++si)
        if (sceneRuns[si]) work += m.scenes[si].referenceSpp ? m.scenes[si].referenceSpp : m.reference.spp;
    Progress progress(opt.referencesOnly ? 0 : groups.size() * m.patterns.size(), work);
    std::vector<std::optional<SceneFingerprint>> fingerprinted(m.scenes.size());
    for (size_t si = 0; si < m.scenes.size(); ++si) {
        const MatrixScene& ms = m.scenes[si];
        std::vector<CellGroup> mine;
        for (const auto& g : groups)
            if (g.scene == si) mine.push_back(g);
        if (mine.empty()) continue;

        // A scene that fails does not take the others down: its error is recorded, its rows dropped, and the
        // run ends with a non-zero status after writing the report of the rest.
        try {
            progress.pause();
            progress.note("loading " + ms.path);
            // The scene in-process (stipple-render's library) or through its external renderer.
            const std::unique_ptr<CellRenderer> scene =
                makeCellRenderer(ms, m, opt.unloadable, opt.renderer, opt.cacheDir);
            const render::RenderOptions base = scene->options(threads);
            SceneInfo info = scene->info(base);

            render::RenderOptions refOptions = base;
            refOptions.pattern = m.reference.pattern;
            refOptions.spp = ms.referenceSpp ? ms.referenceSpp : m.reference.spp;
            refOptions.seed = m.reference.seed;
            fingerprinted[si] = scene->fingerprint(base, refOptions.spp);
            progress.note(fmt("reference for %s: %s %u spp seed %llu at %dx%d%s", ms.name.c_str(),
                              refOptions.pattern.c_str(), refOptions.spp, (unsigned long long)refOptions.seed,
                              base.width, base.height, scene->referenceSource(refOptions).c_str()));
            progress.resume();
            progress.beginTask("reference for " + ms.name, refOptions.spp);
            Reference ref = scene->reference(refOptions, m.seeds, opt.cacheDir);
            progress.endTask(!ref.fromCache);
            if (!ref.cacheProblem.empty())
                progress.note("  cached entry " + ref.key + " did not verify (" + ref.cacheProblem +
                              "): rendered again");
            info.referenceKey = ref.key;
            info.referenceSpp = refOptions.spp;
            info.referenceSeconds = ref.renderSeconds;
            info.noiseFloor = noiseFloor(ref.variance);
            progress.note(fmt("  %s: %s, noise floor %.4g (MSE)", ref.fromCache ? "cached" : "rendered",
                              ref.fromCache ? ref.imagePath.c_str() : fmt("%.1f s", ref.renderSeconds).c_str(),
                              info.noiseFloor));
            progress.resume();
            if (opt.referencesOnly) {
                results.scenes.push_back(info);
                continue;
            }
            writeCrop(opt.reportDir, ms.name, "reference", ref.image, m.crop);
            writeRegionCrops(opt.reportDir, ms, "reference", ref.image);
            render::writePng((fs::path(opt.reportDir) / "crops" / (safeName(ms.name) + "-reference-full.png")).string(),
                             ref.image);
            std::vector<double> regionFloors;
            for (const Region& region : ms.regions) regionFloors.push_back(regionNoiseFloor(ref.variance, region));

            info.warmupSeconds = scene->warmUp(base, m);

            std::vector<std::pair<std::string, render::Image>> cropRenders; // the crop group's, for error maps
            for (size_t gi = 0; gi < mine.size(); ++gi) {
                const CellGroup& g = mine[gi];
                for (size_t k = 0; k < m.patterns.size(); ++k) {
                    // Rotate the pattern order per group: no pattern always runs first (cold caches) or last.
                    const std::string& pattern = m.patterns[(k + gi) % m.patterns.size()];
                    render::RenderOptions o = base;
                    o.pattern = pattern;
                    o.spp = g.spp;
                    o.seed = g.seed;
                    render::RenderResult r = scene->render(o);
                    ResultRow row = measureRow(ms.name, o, r, ref, info.noiseFloor);
                    addImageMetrics(row, ref, r.image, ms, regionFloors);
                    results.rows.push_back(row);
                    if (g.seed == m.seeds.front()) writeCellExr(opt.reportDir, ms.name, o, r.image);
                    if (g.spp == cropSpp && g.seed == m.seeds.front()) {
                        writeCrop(opt.reportDir, ms.name, pattern, r.image, m.crop);
                        writeRegionCrops(opt.reportDir, ms, pattern, r.image);
                        cropRenders.emplace_back(pattern, std::move(r.image));
                    }
                    progress.step(fmt("%s %s %u spp seed %llu: RMS %.4g, %.3f s (sampler %.3f s)%s", ms.name.c_str(),
                                      pattern.c_str(), g.spp, (unsigned long long)g.seed, row.rmsCorrected,
                                      row.renderSeconds, row.samplerSeconds,
                                      row.floorLimited ? ", floor-limited" : ""),
                                  g.spp);
                }
            }
            writeRegionErrorMaps(opt.reportDir, ms, ref.image, cropRenders);
            results.scenes.push_back(info);
        } catch (const std::exception& e) {
            progress.endTask(false);
            progress.resume();
            // std::bad_alloc's own text names an internal type: say what it means.
            const bool oom = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
            std::string what = ms.path + ": " + (oom ? std::string("out of memory") : std::string(e.what()));
            progress.note("ERROR: " + what + " (skipping scene " + ms.name + ")");
            results.skipped.push_back({ms.name, what});
            std::erase_if(results.rows, [&](const ResultRow& r) { return r.scene == ms.name; });
        }
    }
    progress.finish();
    if (!opt.referencesOnly) results.fingerprint = fingerprintRun(m, std::move(fingerprinted), "");
    sortRows(results.rows, m);
    return results;
}

} // namespace stipple::validation
