// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// spectrum.cpp — the field's measures of a pattern's served sets (Lagae & Dutre 2008; Heck et al. 2013), through
// the C ABI exactly as a host gets them (one dimension of the given arity, pixel after pixel).
//
//   shim_spectrum [--patterns a,b,...] [--arities 1,2,3] [--ns 16,64,...] [--pixels M] [--raps]
//                 [--dart] [--dart-rhos r1,r2,...]
//
// For each pattern x arity x N, over M pixels (default: 64 up to N = 1024, 24 above): the averaged periodogram at
// integer frequencies 0 < |k| <= K = 2 N^(1/arity) (2 sqrt(N) in 2D; white noise = 1), its largest value ("peak"),
// the median over annuli of the anisotropy 10 log10(var / mean^2) (dB; white noise averaged over M sets sits
// near -10 log10(M); none in 1D), rho_min and rho_mean (minimum toroidal distance over the densest packing's, the
// least and the mean over the pixels), and in 1D the pixels whose set has one point in each cell [c/N, (c+1)/N).
// --raps adds the radially averaged power spectrum per annulus.
//
// --dart adds rows "dart rho R (fresh)": plain dart throwing on the torus at radius R d_max (dart_reference.h: not
// the library; a fresh set per pixel from its own RNG), at poisson's own radius (0.76 in 2D, 0.72 in 3D: the
// process its stored sets come from; in 1D, where poisson is one point per cell, 0.20, its minimum distance) and at
// each --dart-rhos value (default 0.52, 0.65: the study's dart throwing and between). A last table sets poisson over
// each dart row and over each other pattern but independent, at the same arity, N and pixel count: the peak ratio,
// the RAPS peak ratio and the anisotropy difference, each with a 95% percentile bootstrap interval over pixels
// (1000 resamplings; each row's pixels resampled on their own, from fixed seeds; the periodograms are kept set by
// set, set_spectra.h, so a resampling costs no new transform). A resampled average holds fewer distinct sets than
// the average it resamples, which raises its peak and anisotropy on both sides of a ratio alike: the intervals are,
// if anything, wide. They tell what of poisson's peak is the process at its radius and what is the serving (stored
// sets under torus symmetries and shifts). shim/docs/tables/spectra-dart.md is `shim_spectrum --dart` (1D, 2D, 3D
// at N = 16, 64, 256, 1024, 4096).
//
// Defaults: poisson, poisson-seed and independent (white noise) at N = 16, 64, 256, 1024, 4096 in 1D, 2D, 3D: the
// table of shim/POINTSETS.md ("Spectra"), written by `shim_spectrum > shim/POINTSETS-spectra.md`.
//
// stipple-link: shared
#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include "dart_reference.h"
#include "pointsets/pointsets.h"
#include "pointsets/spectrum.h"
#include "set_spectra.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using stipple::detail::pointsets::PowerSpectrum;
using stipple::detail::pointsets::relativeRadius;
using stipple::bench::SetSpectra;

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "shim_spectrum: %s\n", message.c_str());
    std::exit(2);
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

uint32_t parseCount(const std::string& text, const char* what, uint32_t limit) {
    char* end = nullptr;
    const unsigned long value = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value == 0 || value > limit)
        fail(std::string("bad ") + what + " \"" + text + "\" (a whole number in 1.." + std::to_string(limit) + ")");
    return uint32_t(value);
}

// A one-dimension sampler through the kit (stipple.hpp).
stipple::Sampler makeSampler(uint32_t pattern, uint32_t arity, uint32_t n) {
    const char* name = "";
    stipple_pattern_name(pattern, &name);
    stipple::Sampler sampler;
    const stipple::Status status = stipple::Sampler::create(sampler, name, n, 0x5bec7, {{arity, 1, ""}});
    if (!status.ok()) fail("creating a sampler: " + status.message());
    return sampler;
}

struct Measures {
    double peak, peakRadius, raps, anisotropy, rhoMin, rhoMean;
    uint32_t cellPixels; // 1D: pixels with one point per cell
    std::vector<PowerSpectrum::Annulus> annuli;
};

// True if some grid of n cells of width 1/n (shifted by any s, wrapping round the torus) has one point in each cell:
// with the points sorted, every x_(i) n - i lies in one interval [s, s + 1) (the point of the cell that wraps, if it
// sorts first, has x n in [0, s) and fits the same interval shifted down by one, as do all the others).
bool onePointPerCell(std::vector<float> x) {
    std::sort(x.begin(), x.end());
    double lo = 1e300, hi = -1e300;
    for (size_t i = 0; i < x.size(); ++i) {
        const double t = double(x[i]) * double(x.size()) - double(i);
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    return hi - lo < 1.0;
}

int maxFrequency(uint32_t arity, uint32_t n) {
    return std::max(1, int(std::floor(2.0 * std::pow(double(n), 1.0 / arity) + 1e-9)));
}

// 1D annuli n / 32 frequencies wide (at least 1): the radial spectrum of 1D sets is otherwise one noisy value per |k|.
int annulusWidth(uint32_t arity, uint32_t n) { return arity == 1 ? int(std::max(1u, n / 32)) : 1; }

// One row's sets: their spectrum (the library's PowerSpectrum, for the table and --raps) and, with --dart, each set's
// periodogram kept for the bootstrap.
struct Row {
    Measures m;
    std::vector<SetSpectra::Measures> replicates; // --dart: the measures of kBootstrap resamplings of the pixels
};

// Percentile bootstrap over pixels: replicate b averages the sets with multinomial weights (M draws of M pixels) from
// an RNG seeded by the row's seed and b. Two rows compared are resampled independently (their pixels are independent
// sets), so the interval of a ratio is the 2.5 and 97.5 percentiles of the replicates' ratios.
constexpr uint32_t kBootstrap = 1000;

std::vector<SetSpectra::Measures> bootstrap(const SetSpectra& sets, uint64_t seed) {
    std::vector<SetSpectra::Measures> out;
    const size_t m = sets.sets();
    std::vector<uint32_t> weights(m);
    for (uint32_t b = 0; b < kBootstrap; ++b) {
        std::mt19937_64 rng(seed * 0x9e3779b97f4a7c15ull + b);
        std::uniform_int_distribution<size_t> pick(0, m - 1);
        std::fill(weights.begin(), weights.end(), 0u);
        for (size_t i = 0; i < m; ++i) ++weights[pick(rng)];
        out.push_back(sets.measures(weights));
    }
    return out;
}

// Takes the point sets of one row pixel after pixel: source(p, values) fills pixel p's set.
template <class Source>
Row measureSets(uint32_t arity, uint32_t n, uint32_t pixels, bool keep, uint64_t bootSeed, Source source) {
    const int K = maxFrequency(arity, n);
    PowerSpectrum spectrum(int(arity), K, annulusWidth(arity, n));
    SetSpectra sets(int(arity), K, annulusWidth(arity, n));
    std::vector<float> values(size_t(n) * arity);
    Row row{{0, 0, 0, 0, 1e9, 0, 0, {}}, {}};
    Measures& m = row.m;
    for (uint32_t p = 0; p < pixels; ++p) {
        source(p, values);
        if (keep) sets.add(values.data(), n);
        else spectrum.add(values.data(), n);
        const double rho = relativeRadius(int(arity), values.data(), n);
        m.rhoMin = std::min(m.rhoMin, rho);
        m.rhoMean += rho / pixels;
        if (arity == 1) m.cellPixels += onePointPerCell(values);
    }
    if (keep) {
        // The same measures as PowerSpectrum's (set_spectra.h), from the kept sets.
        const SetSpectra::Measures all = sets.measures();
        m.peak = all.peak, m.peakRadius = all.peakRadius, m.raps = all.raps, m.anisotropy = all.anisotropy;
        row.replicates = bootstrap(sets, bootSeed);
    } else {
        m.peak = spectrum.largestPeak();
        m.peakRadius = spectrum.largestPeakRadius();
        m.raps = spectrum.rapsPeak();
        m.anisotropy = spectrum.medianAnisotropy();
        m.annuli = spectrum.annuli();
    }
    return row;
}

Row measure(uint32_t pattern, uint32_t arity, uint32_t n, uint32_t pixels, bool keep) {
    const stipple::Sampler owner = makeSampler(pattern, arity, n);
    const stipple_sampler sampler = owner.handle();
    return measureSets(arity, n, pixels, keep, 0xb0075ull + pattern, [&](uint32_t p, std::vector<float>& values) {
        if (stipple_sampler_fill_pixel(sampler, 67 * (p % 64), 67 * (p / 64), 0, values.data(), values.size()) !=
            STIPPLE_OK)
            fail(std::string("stipple_sampler_fill_pixel: ") + stipple_last_error_message());
    });
}

// The same measures of fresh dart-throwing sets at radius rho d_max, one per pixel (seeded by the pixel).
Row measureDart(double rho, uint32_t arity, uint32_t n, uint32_t pixels) {
    const double r = rho * stipple::detail::pointsets::maxPackingDistance(int(arity), n);
    return measureSets(arity, n, pixels, true, 0xda27b007ull + uint64_t(std::lround(rho * 1000)),
                       [&](uint32_t p, std::vector<float>& values) {
                           const uint64_t seed = 0xda27ull * 1000003ull + p;
                           values = arity == 1   ? stipple::bench::dartThrowing<1>(n, r, seed)
                                    : arity == 2 ? stipple::bench::dartThrowing<2>(n, r, seed)
                                                 : stipple::bench::dartThrowing<3>(n, r, seed);
                           if (values.empty()) {
                               char text[160];
                               std::snprintf(text, sizeof text,
                                             "--dart-rhos %.2f: dart throwing jammed 64 times in a row before %u "
                                             "points in %uD (beyond the jamming radius)", rho, n, arity);
                               fail(text);
                           }
                       });
}

// "x [lo, hi]": the estimate and the 2.5 and 97.5 percentiles of the replicates' values.
std::string withInterval(double estimate, std::vector<double> replicates, const char* format) {
    std::sort(replicates.begin(), replicates.end());
    const auto at = [&](double q) { return replicates[size_t(std::lround(q * double(replicates.size() - 1)))]; };
    char text[96], f[48];
    std::snprintf(f, sizeof f, "%s [%s, %s]", format, format, format);
    std::snprintf(text, sizeof text, f, estimate, at(0.025), at(0.975));
    return text;
}

// One line of the comparison table: row a (poisson) over row b.
std::string compare(uint32_t arity, uint32_t n, uint32_t pixels, const std::string& over, const Row& a, const Row& b) {
    std::vector<double> peak, raps, anisotropy;
    for (uint32_t i = 0; i < kBootstrap; ++i) {
        peak.push_back(a.replicates[i].peak / b.replicates[i].peak);
        raps.push_back(a.replicates[i].raps / b.replicates[i].raps);
        anisotropy.push_back(a.replicates[i].anisotropy - b.replicates[i].anisotropy);
    }
    const std::string anis = arity == 1 ? "-" : withInterval(a.m.anisotropy - b.m.anisotropy, anisotropy, "%.1f");
    return "| " + std::to_string(arity) + " | " + std::to_string(n) + " | " + std::to_string(pixels) + " | " + over +
           " | " + withInterval(a.m.peak / b.m.peak, peak, "%.2f") + " | " +
           withInterval(a.m.raps / b.m.raps, raps, "%.2f") + " | " + anis + " |";
}

void printRow(uint32_t arity, uint32_t n, uint32_t m, const std::string& name, const Measures& r, bool raps) {
    const int K = std::max(1, int(std::floor(2.0 * std::pow(double(n), 1.0 / arity) + 1e-9)));
    char anisotropy[32] = "-", cells[32] = "-";
    if (!std::isnan(r.anisotropy)) std::snprintf(anisotropy, sizeof anisotropy, "%.1f", r.anisotropy);
    if (arity == 1) std::snprintf(cells, sizeof cells, "%u/%u", r.cellPixels, m);
    std::printf("| %u | %u | %u | %d | %s | %.2f (%.0f) | %.2f | %s | %.3f | %.3f | %s |\n", arity, n, m, K, name.c_str(),
                r.peak, r.peakRadius, r.raps, anisotropy, r.rhoMin, r.rhoMean, cells);
    if (raps) {
        std::printf("|   |   |   |   | RAPS | |");
        for (const auto& a : r.annuli) std::printf(" %d:%.2f", a.radius, a.mean);
        std::printf(" |   |   |   |   |\n");
    }
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> patterns = {"poisson", "poisson-seed", "independent"};
    std::vector<uint32_t> arities = {1, 2, 3}, ns = {16, 64, 256, 1024, 4096};
    uint32_t pixels = 0;
    bool raps = false, dart = false;
    std::vector<double> dartRhos = {0.52, 0.65};
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail("missing value after " + arg);
            return argv[++i];
        };
        if (arg == "--patterns") patterns = splitList(value());
        else if (arg == "--arities") {
            arities.clear();
            for (const std::string& a : splitList(value())) arities.push_back(parseCount(a, "arity", 3));
        } else if (arg == "--ns") {
            ns.clear();
            for (const std::string& a : splitList(value())) ns.push_back(parseCount(a, "N", 1u << 16));
        } else if (arg == "--pixels") pixels = parseCount(value(), "pixel count", 4096);
        else if (arg == "--raps") raps = true;
        else if (arg == "--dart") dart = true;
        else if (arg == "--dart-rhos") {
            dartRhos.clear();
            for (const std::string& a : splitList(value())) {
                char* end = nullptr;
                const double rho = std::strtod(a.c_str(), &end);
                if (*end != '\0' || !(rho > 0 && rho < 0.9)) fail("bad rho \"" + a + "\" (a number in (0, 0.9))");
                dartRhos.push_back(rho);
            }
        }
        else fail("unknown argument \"" + arg + "\" (see the comment at the top of bench/spectrum.cpp)");
    }
    if (raps && dart) fail("--raps and --dart do not combine (the --dart rows keep each set's periodogram instead)");
    std::string command = "shim_spectrum";
    for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
    std::printf("# poisson beside dart throwing and white noise: spectra of served sets\n\n"
                "Generated by `%s` (source `bench/spectrum.cpp`; the header of that file defines every column); do "
                "not edit by hand. Read with POINTSETS.md, \"Spectra\".%s\n\n",
                command.c_str(),
                dart ? " Rows \"dart rho R (fresh)\": plain dart throwing at R d_max, a fresh set per pixel from an RNG "
                       "of its own (not the library), at poisson's own radius (1D: its minimum distance), at the "
                       "study's (0.52) and between."
                     : "");
    std::printf("| arity | N | pixels | K | pattern | peak (at abs k) | RAPS peak | anisotropy (dB) | rho_min | rho_mean | one point per cell |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::vector<std::string> comparisons;
    for (uint32_t arity : arities)
        for (uint32_t n : ns) {
            const uint32_t m = pixels ? pixels : n <= 1024 ? 64 : 24;
            std::vector<std::pair<std::string, Row>> rows; // with --dart: what poisson is set beside
            const Row* served = nullptr;
            Row poissonRow;
            for (const std::string& name : patterns) {
                uint32_t pattern = 0;
                if (stipple_pattern_from_name(name.c_str(), &pattern) != STIPPLE_OK)
                    fail("unknown pattern \"" + name + "\"");
                Row r = measure(pattern, arity, n, m, dart);
                printRow(arity, n, m, name, r.m, raps);
                if (!dart) continue;
                if (name == "poisson") poissonRow = std::move(r), served = &poissonRow;
                else if (name != "independent") rows.emplace_back(name + " (served)", std::move(r));
            }
            if (dart) {
                // poisson's own radius (pointsets/poisson.cpp; 1D: its minimum distance, cell_set_1d.cpp)
                std::vector<double> rhos = {arity == 1 ? 0.20 : arity == 2 ? 0.76 : 0.72};
                for (double rho : dartRhos)
                    if (std::find(rhos.begin(), rhos.end(), rho) == rhos.end()) rhos.push_back(rho);
                for (double rho : rhos) {
                    char name[48];
                    std::snprintf(name, sizeof name, "dart rho %.2f (fresh)", rho);
                    Row r = measureDart(rho, arity, n, m);
                    printRow(arity, n, m, name, r.m, raps);
                    rows.emplace_back(name, std::move(r));
                }
                // poisson over dart throwing first (its own radius, then the others), then over the served patterns
                std::stable_partition(rows.begin(), rows.end(),
                                      [](const auto& r) { return r.first.rfind("dart", 0) == 0; });
                if (served)
                    for (const auto& [name, row] : rows) comparisons.push_back(compare(arity, n, m, name, *served, row));
            }
        }
    if (!comparisons.empty()) {
        std::printf("\npoisson over each reference at the same N and pixel count, with 95%% percentile bootstrap "
                    "intervals (%u resamplings of the pixels of each row, independently; fixed seeds). Over dart "
                    "throwing at poisson's own radius (2D, 3D: the process the stored sets come from), ratios near 1 "
                    "and a difference near 0 dB say the stored sets, served under torus symmetries and shifts, "
                    "average like fresh sets; over the study's dart throwing (0.52) and poisson-seed, what the larger "
                    "radius costs in peak. In 1D poisson is not dart throwing (one point per cell): its row over "
                    "dart throwing at 0.20 sets it beside dart throwing with the same minimum distance.\n\n"
                    "| arity | N | pixels | poisson over | peak ratio | RAPS peak ratio | anisotropy difference (dB) |"
                    "\n|---|---|---|---|---|---|---|\n",
                    kBootstrap);
        for (const std::string& row : comparisons) std::printf("%s\n", row.c_str());
    }
    return 0;
}
