// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// spectrum.cpp — the field's measures of a pattern's served sets (Lagae & Dutre 2008; Heck et al. 2013), through
// the C ABI exactly as a host gets them (one dimension of the given arity, pixel after pixel).
//
//   shim_spectrum [--patterns a,b,...] [--arities 1,2,3] [--ns 16,64,...] [--pixels M] [--raps]
//
// For each pattern x arity x N, over M pixels (default: 64 up to N = 1024, 24 above): the averaged periodogram at
// integer frequencies 0 < |k| <= K = 2 N^(1/arity) (2 sqrt(N) in 2D; white noise = 1), its largest value ("peak"),
// the median over annuli of the anisotropy 10 log10(var / mean^2) (dB; white noise averaged over M sets sits
// near -10 log10(M); none in 1D), rho_min and rho_mean (minimum toroidal distance over the densest packing's, the
// least and the mean over the pixels), and in 1D the pixels whose set has one point in each cell [c/N, (c+1)/N).
// --raps adds the radially averaged power spectrum per annulus. Defaults: poisson, poisson-seed and independent
// (white noise) at N = 16, 64, 256, 1024, 4096 in 1D, 2D, 3D: the table of shim/POINTSETS.md ("Spectra"),
// written by `shim_spectrum > shim/POINTSETS-spectra.md`.
//
// stipple-link: shared
#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include "pointsets/pointsets.h"
#include "pointsets/spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

using stipple::detail::pointsets::PowerSpectrum;
using stipple::detail::pointsets::relativeRadius;

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

// 1D annuli n / 32 frequencies wide (at least 1): the radial spectrum of 1D sets is otherwise one noisy value per |k|.
int annulusWidth(uint32_t arity, uint32_t n) { return arity == 1 ? int(std::max(1u, n / 32)) : 1; }

Measures measure(uint32_t pattern, uint32_t arity, uint32_t n, uint32_t pixels) {
    const int K = std::max(1, int(std::floor(2.0 * std::pow(double(n), 1.0 / arity) + 1e-9)));
    PowerSpectrum spectrum(int(arity), K, annulusWidth(arity, n));
    const stipple::Sampler owner = makeSampler(pattern, arity, n);
    const stipple_sampler sampler = owner.handle();
    std::vector<float> values(size_t(n) * arity);
    Measures m{0, 0, 0, 0, 1e9, 0, 0, {}};
    for (uint32_t p = 0; p < pixels; ++p) {
        if (stipple_sampler_fill_pixel(sampler, 67 * (p % 64), 67 * (p / 64), 0, values.data(), values.size()) !=
            STIPPLE_OK)
            fail(std::string("stipple_sampler_fill_pixel: ") + stipple_last_error_message());
        spectrum.add(values.data(), n);
        const double rho = relativeRadius(int(arity), values.data(), n);
        m.rhoMin = std::min(m.rhoMin, rho);
        m.rhoMean += rho / pixels;
        if (arity == 1) m.cellPixels += onePointPerCell(values);
    }
    m.peak = spectrum.largestPeak();
    m.peakRadius = spectrum.largestPeakRadius();
    m.raps = spectrum.rapsPeak();
    m.anisotropy = spectrum.medianAnisotropy();
    m.annuli = spectrum.annuli();
    return m;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> patterns = {"poisson", "poisson-seed", "independent"};
    std::vector<uint32_t> arities = {1, 2, 3}, ns = {16, 64, 256, 1024, 4096};
    uint32_t pixels = 0;
    bool raps = false;
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
        else fail("unknown argument \"" + arg + "\" (see the comment at the top of bench/spectrum.cpp)");
    }
    std::printf("| arity | N | pixels | K | pattern | peak (at abs k) | RAPS peak | anisotropy (dB) | rho_min | rho_mean | one point per cell |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (uint32_t arity : arities)
        for (uint32_t n : ns) {
            const uint32_t m = pixels ? pixels : n <= 1024 ? 64 : 24;
            for (const std::string& name : patterns) {
                uint32_t pattern = 0;
                if (stipple_pattern_from_name(name.c_str(), &pattern) != STIPPLE_OK)
                    fail("unknown pattern \"" + name + "\"");
                const Measures r = measure(pattern, arity, n, m);
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
        }
    return 0;
}
