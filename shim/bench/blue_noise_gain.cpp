// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// blue_noise_gain.cpp — what STIPPLE_SAMPLER_FLAG_BLUE_NOISE does to the error image, per pattern and per 2D
// integrand of the battery (battery_integrands.h: smooth, kink, edge and zone-plate classes), through the C ABI.
//
//   shim_blue_noise_gain [-o DIR (blue_noise_gain)] [--images I (12)] [--size S (128)] [--ns 16,64,256]
//                        [--patterns a,b,...] [--boot B (400)] [--threads T] [--grown [--confirm I]]
//
// For each pattern x N, I images of S x S pixels are rendered with the flag and I without (image i uses seed
// kSeed + i; one 2D dimension, one value per sample), and every integrand is estimated at every pixel. Per image
// and integrand: the per-pixel MSE and the low-quarter band energy of the error image (|f| < 1/8 cycle per pixel,
// DC excluded: the mean periodogram value over the band, which for white noise equals the per-pixel MSE).
// Reported, each with a 95% bootstrap interval over images (images resampled independently for each side):
// - low-frequency gain = band energy without the flag / band energy with it (> 1: the flag removed low-frequency
//   error; < 1: it added some). Without the flag the pixels are independent, so this is white / measured;
// - per-pixel MSE ratio flag / plain.
// A pattern the library refuses the flag for is reported as refused.
//
// Writes DIR/blue_noise_gain.md (per pattern: the table, integrand x N) and DIR/blue_noise_gain.csv.
// --grown: the grown battery instead (battery_grown.h: checkerboards, gratings |k| <= 2 sqrt(N), thin stripes, axis
// and near-axis steps, edges, opposite bumps; it depends on N). Writes DIR/blue_noise_grown.md (per pattern and N,
// per family: the least gain with its interval, how many integrands have an interval wholly below 1, the median
// gain) and DIR/blue_noise_grown.csv (every integrand). --confirm I adds a confirmation stage: per N, every integrand
// whose gain is below 1 in that screen, and its 3 least gains, are rendered again on I fresh images per side (seeds
// kSeed + 2^20 + i, disjoint from the screen's kSeed + i), since the least of many screened gains is biased low; each
// confirmed gain is given with a 95% percentile bootstrap interval (20000 resamplings) and, over the whole confirmed
// set of a pattern (m integrands), the one-sided Sidak decision "below 1" at family-wise confidence 95% (the upper
// 1 - alpha bootstrap quantile below 1, alpha = 1 - 0.95^(1/m)). shim/docs/tables/blue-noise-grown.md is this file
// for --patterns stratified,independent --images 8 --confirm 32.
//
// stipple-link: shared
#include "battery_grown.h"
#include "battery_integrands.h"

#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using namespace stipple::battery;

namespace {

constexpr uint64_t kSeed = 0xb1e5ca1eull;

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "shim_blue_noise_gain: " << message << "\n";
    std::exit(2);
}

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

// A sampler through the kit (stipple.hpp): empty, with the library's message in status(), when the library
// refuses the combination.
stipple::Sampler makeSampler(const std::string& pattern, uint32_t n, uint64_t seed, bool blue) {
    stipple::Sampler s;
    (void)stipple::Sampler::create(s, pattern, n, seed, {{2, 1, ""}}, blue ? STIPPLE_SAMPLER_FLAG_BLUE_NOISE : 0);
    return s;
}

// Mean periodogram value over the band 0 < |f| < 1/8 cycle per pixel of an S x S image (white noise of variance
// v gives v): a DFT over the band's frequencies only, rows first. A real image's periodogram is even (P(-k) = P(k)),
// so the half-plane kx > 0, or kx = 0 and ky > 0, has the band's mean.
double lowBandEnergy(const std::vector<double>& image, int size) {
    const int kMax = size / 8;
    const double tau = 2 * 3.14159265358979323846;
    std::vector<double> cosine(static_cast<size_t>(size)), sine(static_cast<size_t>(size));
    for (int i = 0; i < size; ++i) {
        cosine[size_t(i)] = std::cos(tau * i / size);
        sine[size_t(i)] = -std::sin(tau * i / size);
    }
    std::vector<std::complex<double>> rows(size_t(size) * size_t(kMax)); // [y][kx], 0 <= kx < kMax
    for (int y = 0; y < size; ++y)
        for (int kx = 0; kx < kMax; ++kx) {
            double re = 0, im = 0;
            const double* row = &image[size_t(y) * size];
            for (int x = 0, index = 0; x < size; ++x, index = index + kx < size ? index + kx : index + kx - size) {
                re += row[x] * cosine[size_t(index)];
                im += row[x] * sine[size_t(index)];
            }
            rows[size_t(y) * kMax + kx] = {re, im};
        }
    double band = 0;
    int bins = 0;
    for (int ky = -kMax + 1; ky < kMax; ++ky)
        for (int kx = 0; kx < kMax; ++kx) {
            if ((kx == 0 && ky <= 0) || kx * kx + ky * ky >= kMax * kMax) continue;
            std::complex<double> acc = 0;
            const int step = (ky % size + size) % size;
            for (int y = 0, index = 0; y < size; ++y, index = index + step < size ? index + step : index + step - size)
                acc += rows[size_t(y) * kMax + kx] * std::complex<double>(cosine[size_t(index)], sine[size_t(index)]);
            band += std::norm(acc) / (double(size) * size);
            ++bins;
        }
    return band / bins;
}

struct ImageStats {
    std::vector<double> mse, band; // per integrand, normalised by Var f
};

// Per integrand, the per-pixel MSE and the low-band energy of an error image (error[integrand][pixel]).
ImageStats imageStats(const std::vector<std::vector<double>>& error, int size) {
    ImageStats st;
    for (const std::vector<double>& image : error) {
        double sq = 0;
        for (double e : image) sq += e * e;
        st.mse.push_back(sq / image.size());
        st.band.push_back(lowBandEnergy(image, size));
    }
    return st;
}

ImageStats renderImage(stipple_sampler s, uint32_t n, int size, const std::vector<Integrand>& battery) {
    std::vector<std::vector<double>> error(battery.size(), std::vector<double>(size_t(size) * size));
    std::vector<float> points(size_t(n) * 2);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (stipple_sampler_fill_pixel(s, uint32_t(x), uint32_t(y), 0, points.data(), points.size()) != STIPPLE_OK)
                fail(std::string("stipple_sampler_fill_pixel: ") + stipple_last_error_message());
            for (size_t g = 0; g < battery.size(); ++g) {
                double sum = 0;
                for (uint32_t p = 0; p < n; ++p) sum += battery[g](0, &points[2 * size_t(p)]);
                error[g][size_t(y) * size + x] = (sum / n - battery[g].exact[0]) / std::sqrt(battery[g].variance[0]);
            }
        }
    return imageStats(error, size);
}

// The grown battery's per-pixel errors: gratings all at once, sum_p cos(2 pi (kx x_p + ky y_p)) from per-point
// tables of cos and sin of 2 pi k x_p and 2 pi k y_p (k >= 0; the gratings have kx >= 0), the other integrands one by
// one.
ImageStats renderGrownImage(stipple_sampler s, uint32_t n, int size, const std::vector<GrownIntegrand>& battery) {
    std::vector<std::vector<double>> error(battery.size(), std::vector<double>(size_t(size) * size));
    std::vector<float> points(size_t(n) * 2);
    int radius = 0;
    for (const GrownIntegrand& g : battery) radius = std::max({radius, std::abs(g.k[0]), std::abs(g.k[1])});
    // [axis][cos / sin][k][p]
    std::vector<double> table(size_t(4) * size_t(radius + 1) * n);
    auto at = [&](int axis, int part, int k) { return &table[((size_t(axis) * 2 + size_t(part)) * size_t(radius + 1) + size_t(k)) * n]; };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (stipple_sampler_fill_pixel(s, uint32_t(x), uint32_t(y), 0, points.data(), points.size()) != STIPPLE_OK)
                fail(std::string("stipple_sampler_fill_pixel: ") + stipple_last_error_message());
            for (int axis = 0; axis < 2; ++axis)
                for (uint32_t p = 0; p < n; ++p) {
                    const std::complex<double> w = std::polar(1.0, 2 * 3.14159265358979323846 * points[2 * p + axis]);
                    std::complex<double> e = 1;
                    for (int k = 0; k <= radius; ++k, e *= w) {
                        at(axis, 0, k)[p] = e.real();
                        at(axis, 1, k)[p] = e.imag();
                    }
                }
            for (size_t g = 0; g < battery.size(); ++g) {
                const Integrand& in = battery[g].integrand;
                double sum = 0;
                if (battery[g].family == "grating") {
                    const int kx = battery[g].k[0], ky = std::abs(battery[g].k[1]);
                    const double sign = battery[g].k[1] < 0 ? -1.0 : 1.0;
                    const double *cx = at(0, 0, kx), *sx = at(0, 1, kx), *cy = at(1, 0, ky), *sy = at(1, 1, ky);
                    double cc = 0, ss = 0;
                    for (uint32_t p = 0; p < n; ++p) {
                        cc += cx[p] * cy[p];
                        ss += sx[p] * sy[p];
                    }
                    sum = cc - sign * ss;
                } else
                    for (uint32_t p = 0; p < n; ++p) sum += in(0, &points[2 * size_t(p)]);
                error[g][size_t(y) * size + x] = (sum / n - in.exact[0]) / std::sqrt(in.variance[0]);
            }
        }
    return imageStats(error, size);
}

struct Interval {
    double value, lo, hi;
};

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / v.size();
}

// mean(a) / mean(b) over `boot` bootstrap resamplings, a and b resampled independently; sorted.
std::vector<double> bootstrapRatios(const std::vector<double>& a, const std::vector<double>& b, int boot,
                                    uint64_t seed) {
    uint64_t state = seed;
    auto next = [&] {
        state += 0x9e3779b97f4a7c15ull;
        uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    };
    auto resampledMean = [&](const std::vector<double>& v) {
        double s = 0;
        for (size_t i = 0; i < v.size(); ++i) s += v[next() % v.size()];
        return s / v.size();
    };
    std::vector<double> r;
    for (int i = 0; i < boot; ++i) r.push_back(resampledMean(a) / resampledMean(b));
    std::sort(r.begin(), r.end());
    return r;
}

// mean(a) / mean(b) with a 95% percentile bootstrap interval, a and b resampled independently.
Interval ratioOfMeans(const std::vector<double>& a, const std::vector<double>& b, int boot, uint64_t seed) {
    const std::vector<double> r = bootstrapRatios(a, b, boot, seed);
    return {mean(a) / mean(b), r[size_t(0.025 * (boot - 1))], r[size_t(0.975 * (boot - 1))]};
}

std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, v >= 100 ? "%.0f" : v >= 10 ? "%.1f" : "%.2f", v);
    return buf;
}

std::string cell(const Interval& i) { return fmt(i.value) + " [" + fmt(i.lo) + ", " + fmt(i.hi) + "]"; }

std::string patternName(uint32_t id) {
    const char* name = nullptr;
    if (stipple_pattern_name(id, &name) != STIPPLE_OK) fail("stipple_pattern_name");
    return name;
}

// Renders images x {plain, flag} of one pattern and N with `render`, in parallel.
template <class Render>
void renderPairs(uint32_t id, uint32_t n, int images, int threads, std::vector<ImageStats> (&stats)[2], Render render,
                 uint64_t firstSeed = kSeed) {
    stats[0].assign(size_t(images), {});
    stats[1].assign(size_t(images), {});
    std::atomic<int> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (int job; (job = next.fetch_add(1)) < 2 * images;) {
                const bool blue = job % 2 == 1;
                const int image = job / 2;
                const stipple::Sampler s = makeSampler(patternName(id), n, firstSeed + uint64_t(image), blue);
                if (!s) fail("stipple_sampler_create: " + s.status().message());
                stats[blue][size_t(image)] = render(s.handle());
            }
        });
    for (auto& th : pool) th.join();
}

// The confirmation stage of --grown (--confirm I): images of seeds disjoint from the screen's, and the bootstrap
// resamplings of a confirmed gain (enough that the Sidak-corrected tail holds many of them).
constexpr uint64_t kConfirmSeed = kSeed + (uint64_t(1) << 20);
constexpr int kConfirmBoot = 20000;
constexpr int kConfirmLowest = 3;

struct Confirmed {
    uint32_t n;
    std::string name;
    Interval screen, gain;
    std::vector<double> replicates; // sorted bootstrap gains
};

// The confirmation table of one pattern: each confirmed gain with its 95% interval and, over the whole set (m
// integrands), the one-sided Sidak decision: gain below 1 at family-wise confidence 95% when the replicates' upper
// 1 - alpha quantile is below 1, alpha = 1 - 0.95^(1/m).
void writeConfirmation(std::ostream& md, const std::vector<Confirmed>& rows, int images, int screenImages) {
    const size_t m = rows.size();
    if (m == 0) return;
    const double alpha = 1.0 - std::pow(0.95, 1.0 / double(m));
    char level[64];
    std::snprintf(level, sizeof level, "%.4f", alpha);
    md << "Confirmation: every integrand whose screen gain is below 1, and the " << kConfirmLowest
       << " least gains per N, remeasured on " << images << " fresh images per side (seeds disjoint from the "
       << "screen's " << screenImages << "; " << kConfirmBoot << " bootstrap resamplings). Below 1 at family-wise "
       << "confidence 95% over these " << m << " integrands (Sidak: one-sided level " << level
       << " each) when the bootstrap's upper " << level << " tail lies below 1.\n\n"
       << "| N | integrand | screen gain [95%] | confirmed gain [95%] | upper bound (Sidak) | below 1 |\n"
       << "|---|---|---|---|---|---|\n";
    int below = 0;
    for (const Confirmed& c : rows) {
        const size_t B = c.replicates.size();
        const double upper = c.replicates[std::min(B - 1, size_t(std::ceil((1.0 - alpha) * double(B - 1))))];
        below += upper < 1;
        md << "| " << c.n << " | " << c.name << " | " << cell(c.screen) << " | " << cell(c.gain) << " | "
           << fmt(upper) << " | " << (upper < 1 ? "yes" : "no") << " |\n";
    }
    md << "\nFamily-wise (95%): " << below << " of " << m << " confirmed below 1.\n\n";
}

int runGrown(const fs::path& outDir, const std::vector<std::string>& patterns, const std::vector<uint32_t>& ns,
             int images, int size, int boot, int threads, int confirmImages) {
    const fs::path mdPath = outDir / "blue_noise_grown.md", csvPath = outDir / "blue_noise_grown.csv";
    std::ofstream md(mdPath.string() + ".tmp"), csv(csvPath.string() + ".tmp");
    csv << "pattern,family,integrand,N,gain,gain_lo,gain_hi,mse_ratio,mse_ratio_lo,mse_ratio_hi\n";
    md << "# The blue-noise flag on the grown battery\n\n"
          "Generated by `shim_blue_noise_gain --grown --patterns "
       << [&] {
              std::string list;
              for (const std::string& p : patterns) list += (list.empty() ? "" : ",") + p;
              return list;
          }()
       << " --images " << images << " --size " << size
       << (confirmImages ? " --confirm " + std::to_string(confirmImages) : std::string()) << "`; do not edit by hand.\n\n"
       << "Low-frequency gain = low-quarter error energy (|f| < 1/8 cycle per pixel, DC excluded) without the flag / "
          "with it: > 1, the flag removed low-frequency error; < 1, it added some. 95% bootstrap intervals over "
       << images << " images of " << size << " x " << size
       << " pixels per side (seeds fixed). Per family of the grown battery (battery_grown.h; gratings: every k with "
          "|k| <= 2 sqrt(N)): the least gain and its integrand, how many integrands have an interval wholly below 1 "
          "(the flag raised their low-frequency error), and the median gain. Per-pixel MSE flag / plain: the range of "
          "point estimates.\n\n";
    for (const std::string& name : patterns) {
        uint32_t id = 0;
        if (stipple_pattern_from_name(name.c_str(), &id) != STIPPLE_OK) fail("unknown pattern \"" + name + "\"");
        md << "## " << name << "\n\n";
        if (const stipple::Sampler probe = makeSampler(name, ns[0], kSeed, true); !probe) {
            const std::string refusal = probe.status().message();
            md << "Refused by the library: " << refusal << "\n\n";
            std::cerr << name << ": refused (" << refusal << ")\n";
            continue;
        }
        md << "| N | family | integrands | least gain [95%] | its integrand | intervals below 1 | median gain | MSE "
              "ratio |\n|---|---|---|---|---|---|---|---|\n";
        std::vector<Confirmed> confirmed;
        for (uint32_t n : ns) {
            const std::vector<GrownIntegrand> battery = makeGrownBattery(n);
            std::vector<ImageStats> stats[2];
            renderPairs(id, n, images, threads, stats, [&](stipple_sampler s) { return renderGrownImage(s, n, size, battery); });
            std::map<std::string, std::vector<size_t>> families;
            std::vector<std::string> order;
            for (size_t g = 0; g < battery.size(); ++g) {
                if (!families.count(battery[g].family)) order.push_back(battery[g].family);
                families[battery[g].family].push_back(g);
            }
            std::vector<Interval> gains(battery.size()), ratios(battery.size());
            for (size_t g = 0; g < battery.size(); ++g) {
                std::vector<double> band[2], mse[2];
                for (int b = 0; b < 2; ++b)
                    for (const ImageStats& st : stats[b]) {
                        band[b].push_back(st.band[g]);
                        mse[b].push_back(st.mse[g]);
                    }
                gains[g] = ratioOfMeans(band[0], band[1], boot, kSeed ^ (g * 131 + n));
                ratios[g] = ratioOfMeans(mse[1], mse[0], boot, kSeed ^ (g * 137 + n + 7));
                csv << name << "," << battery[g].family << ",\"" << battery[g].integrand.name << "\"," << n << ","
                    << gains[g].value << "," << gains[g].lo << "," << gains[g].hi << "," << ratios[g].value << ","
                    << ratios[g].lo << "," << ratios[g].hi << "\n";
            }
            for (const std::string& family : order) {
                const std::vector<size_t>& members = families[family];
                size_t worst = members[0];
                int below = 0;
                std::vector<double> values;
                double mseLo = 1e300, mseHi = 0;
                int exact = 0;
                for (size_t g : members) {
                    if (!std::isfinite(gains[g].value)) { // no error with or without the flag (aligned with the strata)
                        ++exact;
                        continue;
                    }
                    if (!std::isfinite(gains[worst].value) || gains[g].value < gains[worst].value) worst = g;
                    below += gains[g].hi < 1;
                    values.push_back(gains[g].value);
                    mseLo = std::min(mseLo, ratios[g].value);
                    mseHi = std::max(mseHi, ratios[g].value);
                }
                std::sort(values.begin(), values.end());
                if (values.empty()) continue;
                md << "| " << n << " | " << family << " | " << members.size() - exact << (exact ? " (+" + std::to_string(exact) + " exact)" : "") << " | " << cell(gains[worst]) << " | "
                   << battery[worst].integrand.name << " | " << below << " | " << fmt(values[values.size() / 2])
                   << " | " << fmt(mseLo) << "-" << fmt(mseHi) << " |\n";
            }
            if (confirmImages > 0) {
                // The screen's gains below 1 and its least few: remeasured on fresh images (the screen's least gain
                // is biased low by the selection; fresh images are not).
                std::vector<size_t> order(battery.size());
                for (size_t g = 0; g < order.size(); ++g) order[g] = g;
                order.erase(std::remove_if(order.begin(), order.end(),
                                           [&](size_t g) { return !std::isfinite(gains[g].value); }),
                            order.end());
                std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return gains[a].value < gains[b].value; });
                std::vector<size_t> chosen;
                for (size_t i = 0; i < order.size(); ++i)
                    if (i < size_t(kConfirmLowest) || gains[order[i]].value < 1) chosen.push_back(order[i]);
                std::vector<GrownIntegrand> subset;
                for (size_t g : chosen) subset.push_back(battery[g]);
                std::vector<ImageStats> fresh[2];
                renderPairs(id, n, confirmImages, threads, fresh,
                            [&](stipple_sampler s) { return renderGrownImage(s, n, size, subset); }, kConfirmSeed);
                for (size_t i = 0; i < chosen.size(); ++i) {
                    std::vector<double> band[2];
                    for (int b = 0; b < 2; ++b)
                        for (const ImageStats& st : fresh[b]) band[b].push_back(st.band[i]);
                    std::vector<double> r = bootstrapRatios(band[0], band[1], kConfirmBoot, kConfirmSeed ^ (chosen[i] * 139 + n));
                    const Interval gain{mean(band[0]) / mean(band[1]), r[size_t(0.025 * (kConfirmBoot - 1))],
                                        r[size_t(0.975 * (kConfirmBoot - 1))]};
                    confirmed.push_back({n, battery[chosen[i]].integrand.name, gains[chosen[i]], gain, std::move(r)});
                }
            }
            std::cerr << name << " N=" << n << " done\n";
        }
        md << "\n";
        writeConfirmation(md, confirmed, confirmImages, images);
    }
    md.close();
    csv.close();
    if (!md || !csv) fail("cannot write " + mdPath.string());
    fs::rename(mdPath.string() + ".tmp", mdPath);
    fs::rename(csvPath.string() + ".tmp", csvPath);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    fs::path outDir = "blue_noise_gain";
    int images = 12, size = 128, boot = 400;
    int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<uint32_t> ns = {16, 64, 256};
    std::vector<std::string> patterns; // default: every pattern the library lists
    bool grown = false;
    int confirmImages = 0; // --grown --confirm I: the confirmation stage on I fresh images per side
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail("missing value after " + a);
            return argv[++i];
        };
        if (a == "-o")
            outDir = value();
        else if (a == "--images")
            images = std::atoi(value().c_str());
        else if (a == "--size")
            size = std::atoi(value().c_str());
        else if (a == "--boot")
            boot = std::atoi(value().c_str());
        else if (a == "--threads")
            threads = std::atoi(value().c_str());
        else if (a == "--grown")
            grown = true;
        else if (a == "--confirm")
            confirmImages = std::atoi(value().c_str());
        else if (a == "--patterns")
            patterns = splitList(value());
        else if (a == "--ns") {
            ns.clear();
            for (const std::string& s : splitList(value())) ns.push_back(uint32_t(std::atoi(s.c_str())));
        } else
            fail("unknown argument \"" + a + "\" (see the comment at the top of blue_noise_gain.cpp)");
    }
    if (images < 2 || size < 16 || size % 8 != 0 || boot < 40 || threads < 1 || ns.empty())
        fail("need --images >= 2, --size a multiple of 8 >= 16, --boot >= 40, --threads >= 1, some --ns");
    fs::create_directories(outDir);
    if (patterns.empty() && !stipple::patternNames(patterns).ok()) fail("the library lists no patterns");
    if (confirmImages != 0 && (!grown || confirmImages < 2)) fail("--confirm needs --grown and at least 2 images");
    if (grown) return runGrown(outDir, patterns, ns, images, size, boot, threads, confirmImages);
    const std::vector<Integrand> battery = makeBattery(2);

    std::ofstream md(outDir / "blue_noise_gain.md"), csv(outDir / "blue_noise_gain.csv");
    csv << "pattern,integrand,class,N,gain,gain_lo,gain_hi,mse_ratio,mse_ratio_lo,mse_ratio_hi\n";
    md << "Low-frequency gain of the blue-noise flag = low-quarter error energy without / with the flag (> 1: the "
          "flag removed low-frequency error), and per-pixel MSE ratio flag / plain, each with a 95% bootstrap "
          "interval over "
       << images << " images of " << size << " x " << size << " pixels per side (shim_blue_noise_gain).\n\n";
    for (const std::string& name : patterns) {
        uint32_t id = 0;
        if (stipple_pattern_from_name(name.c_str(), &id) != STIPPLE_OK) fail("unknown pattern \"" + name + "\"");
        md << "### " << name << "\n\n";
        const stipple::Sampler probe = makeSampler(name, ns[0], kSeed, true);
        if (!probe) {
            const std::string refusal = probe.status().message();
            md << "Refused: " << refusal << "\n\n";
            std::cerr << name << ": refused (" << refusal << ")\n";
            continue;
        }
        md << "| integrand | class |";
        for (uint32_t n : ns) md << " gain N=" << n << " | MSE ratio N=" << n << " |";
        md << "\n|---|---|";
        for (size_t k = 0; k < ns.size(); ++k) md << "---|---|";
        md << "\n";
        std::vector<std::vector<std::string>> rows(battery.size());
        for (uint32_t n : ns) {
            std::vector<ImageStats> stats[2];
            stats[0].resize(size_t(images));
            stats[1].resize(size_t(images));
            std::atomic<int> next{0};
            std::vector<std::thread> pool;
            for (int t = 0; t < threads; ++t)
                pool.emplace_back([&] {
                    for (int job; (job = next.fetch_add(1)) < 2 * images;) {
                        const bool blue = job % 2 == 1;
                        const int image = job / 2;
                        const stipple::Sampler s = makeSampler(name, n, kSeed + uint64_t(image), blue);
                        if (!s) fail("creating a sampler: " + s.status().message());
                        stats[blue][size_t(image)] = renderImage(s.handle(), n, size, battery);
                    }
                });
            for (auto& th : pool) th.join();
            for (size_t g = 0; g < battery.size(); ++g) {
                std::vector<double> band[2], mse[2];
                for (int b = 0; b < 2; ++b)
                    for (const ImageStats& st : stats[b]) {
                        band[b].push_back(st.band[g]);
                        mse[b].push_back(st.mse[g]);
                    }
                const Interval gain = ratioOfMeans(band[0], band[1], boot, kSeed ^ (g * 131 + n));
                const Interval ratio = ratioOfMeans(mse[1], mse[0], boot, kSeed ^ (g * 137 + n + 7));
                rows[g].push_back(cell(gain) + " | " + cell(ratio));
                csv << name << ",\"" << battery[g].name << "\"," << className(battery[g].cls) << "," << n << ","
                    << gain.value << "," << gain.lo << "," << gain.hi << "," << ratio.value << "," << ratio.lo << ","
                    << ratio.hi << "\n";
            }
            std::cerr << name << " N=" << n << " done\n";
        }
        for (size_t g = 0; g < battery.size(); ++g) {
            md << "| " << battery[g].name << " | " << className(battery[g].cls) << " |";
            for (const std::string& c : rows[g]) md << " " << c << " |";
            md << "\n";
        }
        md << "\n";
    }
    return 0;
}
