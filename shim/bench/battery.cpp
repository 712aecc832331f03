// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// battery.cpp — every pattern on the standard integrand battery (battery_integrands.h), through the C ABI as a
// host sees it (stipple-link: shared).
//
//   shim_battery [-o DIR] [--pointsets FILE] [--sets R (400)] [--boot B (300)] [--threads T] [--quick]
//                [--patterns a,b,...] [--no-blue] [--sections battery,nested,prefix,grown] [--grown-file F]
//
// battery: per pattern (with and without the blue-noise flag) x arity 1..3 x N = 16 .. 4096 (powers of two and
//   24, 100, 1000, 3000), R randomisations (pixels (67 i, 67 j): each in its own 64 x 64 blue-noise tile, so the
//   replicates are independent for every variant): the normalised squared error (estimate - I)^2 / Var f of every
//   integrand (an independent set has normalised MSE 1/N). MSE with a 95% bootstrap interval; the slope of
//   log MSE against log N over N = 64 .. 4096 (powers of two) with a bootstrap interval; the MSE ratio to
//   stratified. Per class (smooth, kink, edge, zone plate) the geometric mean over the class's integrands.
// nested: 12 N Var(mean of frac(N x)) (1 for a nested uniform scramble) for N = 16 .. 65536, on 32 dimensions
//   of arity 1 and both axes of 32 dimensions of arity 2.
// prefix: MSE of the first 4N samples of an N-sample sampler (stream_fill past N) over the MSE of a fresh set of
//   4N points, per pattern, arity and integrand.
//
// grown (not in the default sections): the grown 2D battery (battery_grown.h: checkerboards, gratings |k| <= 2 sqrt(N),
//   thin stripes, axis and near-axis steps, edges at 16 orientations, opposite bumps across a stratum face) at
//   N = 16, 64, 256, R pixels per cell (fill_pixel, one 2D dimension): per pattern and family, the MSE ratio to
//   stratified, geometric mean over the family [95% bootstrap] and the worst member. Written to its own file,
//   --grown-file F (default DIR/battery-grown.md; shim/docs/tables/grown.md is
//   `shim_battery --sections grown --no-blue --grown-file shim/docs/tables/grown.md`).
// Writes DIR/battery.md (all tables) and DIR/battery.csv (every cell); with --pointsets, replaces the part of
// FILE between "<!-- battery:begin -->" and "<!-- battery:end -->" with the summary tables (written to a
// temporary file and renamed over FILE, so a failed run never leaves half a file).
//
// stipple-link: shared
#include "battery_grown.h"
#include "battery_integrands.h"

#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

constexpr uint64_t kSeed = 0xba77e12ull;

struct Options {
    fs::path outDir = "battery";
    fs::path pointsets;
    int sets = 400;
    int boot = 300;
    int threads = std::max(1u, std::thread::hardware_concurrency());
    bool quick = false;
    bool blue = true;
    std::vector<std::string> patterns; // default: every pattern the library lists
    std::vector<std::string> sections = {"battery", "nested", "prefix"};
    fs::path grownFile;
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "shim_battery: " << message << "\n";
    std::exit(2);
}

void check(stipple_status s, const char* what) {
    if (s != STIPPLE_OK) fail(std::string(what) + ": " + stipple_last_error_message());
}

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

struct Variant {
    std::string pattern;
    uint32_t id;
    bool blue;
    std::string label() const { return blue ? pattern + " +bn" : pattern; }
};

// A sampler through the kit (stipple.hpp); the measured calls use its handle.
stipple::Sampler makeSampler(const Variant& v, uint32_t n, std::vector<uint32_t> arities, uint64_t seed) {
    std::vector<stipple::LayoutDimension> layout;
    for (uint32_t arity : arities) layout.push_back({arity, 1, ""});
    stipple::Sampler s;
    const stipple::Status status =
        stipple::Sampler::create(s, v.pattern, n, seed, layout, v.blue ? STIPPLE_SAMPLER_FLAG_BLUE_NOISE : 0);
    if (!status.ok()) fail("creating a " + v.label() + " sampler: " + status.message());
    return s;
}

// Replicate r's pixel: 67 apart, so every replicate lies in its own 64 x 64 blue-noise tile.
inline void replicatePixel(int r, uint32_t& x, uint32_t& y) {
    x = 67u * uint32_t(r % 64);
    y = 67u * uint32_t(r / 64);
}

// Runs job(i) for i in [0, count) on `threads` threads, largest-first order given by the caller.
template <class Job> void parallelFor(int threads, size_t count, Job&& job) {
    std::atomic<size_t> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (size_t i; (i = next.fetch_add(1)) < count;) job(i);
        });
    for (auto& th : pool) th.join();
}

// ---- statistics ------------------------------------------------------------------------------------------------

struct Interval {
    double value, lo, hi;
};

double percentile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    const double pos = q * (v.size() - 1);
    const size_t i = static_cast<size_t>(pos);
    return i + 1 < v.size() ? v[i] + (pos - i) * (v[i + 1] - v[i]) : v[i];
}

Interval fromBoot(double value, const std::vector<double>& boot) {
    return {value, percentile(boot, 0.025), percentile(boot, 0.975)};
}

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
    double mx = 0, my = 0;
    for (size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
    mx /= x.size(), my /= y.size();
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    return sxy / sxx;
}

// The normalised squared errors of one (variant, arity, N): err[integrand][replicate], and B bootstrap means of
// each integrand (the same resampled replicates for every integrand, which share the point sets).
struct Cell {
    std::vector<std::vector<double>> err;
    std::vector<double> mse;
    std::vector<std::vector<double>> boot; // [integrand][b]
    double seconds = 0;
};

void bootstrap(Cell& cell, int B, uint64_t seed) {
    const size_t I = cell.err.size(), R = cell.err[0].size();
    cell.mse.assign(I, 0);
    for (size_t i = 0; i < I; ++i) {
        for (double e : cell.err[i]) cell.mse[i] += e;
        cell.mse[i] /= R;
    }
    cell.boot.assign(I, std::vector<double>(B));
    detail::ParameterRng rng{seed};
    std::vector<uint32_t> idx(R);
    for (int b = 0; b < B; ++b) {
        for (auto& j : idx) j = static_cast<uint32_t>(rng.next() * R);
        for (size_t i = 0; i < I; ++i) {
            const double* e = cell.err[i].data();
            double sum = 0;
            for (uint32_t j : idx) sum += e[j];
            cell.boot[i][b] = sum / R;
        }
    }
}

// ---- the battery -------------------------------------------------------------------------------------------------

struct BatteryResult {
    std::vector<Variant> variants;
    std::vector<uint32_t> ns;
    std::vector<std::vector<Integrand>> integrands; // [arity - 1]
    // cells[v][a][n]
    std::vector<std::vector<std::vector<Cell>>> cells;
};

void runBattery(const Options& opt, BatteryResult& res) {
    for (int a = 1; a <= 3; ++a) res.integrands.push_back(makeBattery(a));
    res.ns = opt.quick ? std::vector<uint32_t>{16, 64, 256, 1024, 4096}
                       : std::vector<uint32_t>{16, 24, 32, 64, 100, 128, 256, 512, 1000, 1024, 2048, 3000, 4096};
    const size_t V = res.variants.size(), NN = res.ns.size();
    res.cells.assign(V, std::vector<std::vector<Cell>>(3, std::vector<Cell>(NN)));
    struct Task {
        size_t v, a, n;
        int r0, r1;
    };
    std::vector<Task> tasks;
    const int chunk = 64;
    for (size_t n = NN; n-- > 0;) // large N first: better balance
        for (size_t v = 0; v < V; ++v)
            for (size_t a = 0; a < 3; ++a)
                for (int r = 0; r < opt.sets; r += chunk) tasks.push_back({v, a, n, r, std::min(opt.sets, r + chunk)});
    for (size_t v = 0; v < V; ++v)
        for (size_t a = 0; a < 3; ++a)
            for (size_t n = 0; n < NN; ++n)
                res.cells[v][a][n].err.assign(res.integrands[a].size(), std::vector<double>(opt.sets));
    std::vector<std::atomic<int64_t>> nanos(V * 3 * NN);
    parallelFor(opt.threads, tasks.size(), [&](size_t t) {
        const Task& task = tasks[t];
        const uint32_t N = res.ns[task.n], arity = uint32_t(task.a + 1);
        const std::vector<Integrand>& battery = res.integrands[task.a];
        const stipple::Sampler sampler = makeSampler(res.variants[task.v], N, {arity}, kSeed);
        const stipple_sampler s = sampler.handle();
        std::vector<float> pts(size_t(N) * arity);
        Cell& cell = res.cells[task.v][task.a][task.n];
        int64_t spent = 0;
        for (int r = task.r0; r < task.r1; ++r) {
            uint32_t x, y;
            replicatePixel(r, x, y);
            const auto t0 = std::chrono::steady_clock::now();
            check(stipple_sampler_fill_pixel(s, x, y, 0, pts.data(), pts.size()), "fill_pixel");
            spent += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
            for (size_t i = 0; i < battery.size(); ++i) {
                const Integrand& f = battery[i];
                const int inst = r % f.instances;
                double sum = 0;
                for (uint32_t k = 0; k < N; ++k) sum += f(inst, &pts[size_t(k) * arity]);
                const double e = sum / N - f.exact[inst];
                cell.err[i][r] = e * e / f.variance[inst];
            }
        }
        nanos[(task.v * 3 + task.a) * NN + task.n] += spent;
    });
    std::vector<size_t> cellIds;
    for (size_t c = 0; c < V * 3 * NN; ++c) cellIds.push_back(c);
    parallelFor(opt.threads, cellIds.size(), [&](size_t c) {
        const size_t v = c / (3 * NN), a = (c / NN) % 3, n = c % NN;
        Cell& cell = res.cells[v][a][n];
        cell.seconds = nanos[c] * 1e-9;
        bootstrap(cell, opt.boot, 0xb0075ull ^ (c * 0x9e3779b97f4a7c15ull));
    });
}

// Geometric mean over the integrands in `which` of mse (or of boot b).
double geoMean(const Cell& cell, const std::vector<size_t>& which, int b) {
    double s = 0;
    for (size_t i : which) s += std::log(b < 0 ? cell.mse[i] : cell.boot[i][b]);
    return std::exp(s / which.size());
}

std::string fmt(double v, int prec = 2) {
    char buf[64];
    if (std::abs(v) >= 100)
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else if (std::abs(v) >= 10)
        std::snprintf(buf, sizeof buf, "%.1f", v);
    else if (v != 0 && std::abs(v) < 0.095)
        std::snprintf(buf, sizeof buf, "%.2g", v);
    else
        std::snprintf(buf, sizeof buf, "%.*f", prec, v);
    return buf;
}
std::string fmtInterval(const Interval& i, int prec = 2) {
    return fmt(i.value, prec) + " [" + fmt(i.lo, prec) + ", " + fmt(i.hi, prec) + "]";
}

// The rate theory predicts for (pattern, class, dimension), MSE exponent.
std::string theoryRate(const std::string& pattern, IntegrandClass cls, int d) {
    if (pattern == "independent") return "-1";
    char buf[32];
    if (pattern == "sobol" || pattern == "pmj02") {
        if (cls == IntegrandClass::Edge) return std::snprintf(buf, sizeof buf, "%.2f", -1 - 1.0 / d), buf;
        if (pattern == "pmj02" && d == 3) return std::snprintf(buf, sizeof buf, "%.2f", -1 - 2.0 / d), buf;
        return "-3 (logs)";
    }
    if (pattern == "lattice" || pattern == "halton") { // randomised QMC without the Owen rate on non-periodic f
        if (cls == IntegrandClass::Edge) return std::snprintf(buf, sizeof buf, "%.2f", -1 - 1.0 / d), buf;
        return "-2 (logs)";
    }
    if (pattern == "stratified") {
        if (cls == IntegrandClass::Edge) return std::snprintf(buf, sizeof buf, "%.2f", -1 - 1.0 / d), buf;
        return std::snprintf(buf, sizeof buf, "%.2f", -1 - 2.0 / d), buf;
    }
    return "-1 (asymptotic)";
}

struct Summary {
    std::string table;  // POINTSETS.md's battery table
    std::string detail; // per integrand
    std::string csv;
};

void summariseBattery(const Options& opt, const BatteryResult& res, Summary& out) {
    const size_t V = res.variants.size(), NN = res.ns.size();
    size_t strat = V;
    for (size_t v = 0; v < V; ++v)
        if (res.variants[v].pattern == "stratified" && !res.variants[v].blue) strat = v;
    auto nIndex = [&](uint32_t N) {
        for (size_t n = 0; n < NN; ++n)
            if (res.ns[n] == N) return int(n);
        return -1;
    };
    std::vector<size_t> slopeNs;
    std::vector<double> logN;
    for (size_t n = 0; n < NN; ++n)
        if (res.ns[n] >= 64 && std::has_single_bit(res.ns[n])) slopeNs.push_back(n), logN.push_back(std::log(res.ns[n]));
    const uint32_t ratioNs[3] = {64, 1024, 4096};
    const int B = opt.boot;

    std::ostringstream t, d, csv;
    t << "| pattern | class | d | slope [95%] | theory | MSE / stratified N=64 | N=1024 | N=4096 | worst integrand "
         "/ stratified (N=64, 1024, 4096) |\n|---|---|---|---|---|---|---|---|---|\n";
    csv << "pattern,blue_noise,arity,integrand,class,N,mse,mse_lo,mse_hi,ratio_to_stratified,ratio_lo,ratio_hi,"
           "fill_ns_per_value\n";
    for (size_t v = 0; v < V; ++v)
        for (size_t a = 0; a < 3; ++a) {
            const auto& battery = res.integrands[a];
            for (IntegrandClass cls :
                 {IntegrandClass::Smooth, IntegrandClass::Kink, IntegrandClass::Edge, IntegrandClass::ZonePlate}) {
                std::vector<size_t> which;
                for (size_t i = 0; i < battery.size(); ++i)
                    if (battery[i].cls == cls) which.push_back(i);
                if (which.empty()) continue;
                auto classSlope = [&](int b) {
                    std::vector<double> y;
                    for (size_t n : slopeNs) y.push_back(std::log(geoMean(res.cells[v][a][n], which, b)));
                    return slope(logN, y);
                };
                std::vector<double> bootSlope(B);
                for (int b = 0; b < B; ++b) bootSlope[b] = classSlope(b);
                const Interval sl = fromBoot(classSlope(-1), bootSlope);
                t << "| " << res.variants[v].label() << " | " << className(cls) << " | " << a + 1 << " | "
                  << fmtInterval(sl) << " | " << theoryRate(res.variants[v].pattern, cls, int(a + 1)) << " | ";
                std::string worst;
                for (uint32_t N : ratioNs) {
                    const int n = nIndex(N);
                    if (n < 0 || strat == V) {
                        t << "– | ";
                        continue;
                    }
                    const Cell& c = res.cells[v][a][n];
                    const Cell& s = res.cells[strat][a][n];
                    std::vector<double> bootRatio(B);
                    for (int b = 0; b < B; ++b) bootRatio[b] = geoMean(c, which, b) / geoMean(s, which, b);
                    t << fmtInterval(fromBoot(geoMean(c, which, -1) / geoMean(s, which, -1), bootRatio)) << " | ";
                    size_t wi = which[0];
                    for (size_t i : which)
                        if (c.mse[i] / s.mse[i] > c.mse[wi] / s.mse[wi]) wi = i;
                    worst += (worst.empty() ? "" : ", ") + fmt(c.mse[wi] / s.mse[wi]) + " " + battery[wi].name;
                }
                t << worst << " |\n";
            }
        }

    // Per integrand: MSE ratios to stratified at every N with intervals, and the slope.
    for (size_t a = 0; a < 3; ++a) {
        const auto& battery = res.integrands[a];
        d << "\n### " << a + 1 << "D: normalised MSE x N (independent = 1) and MSE / stratified [95%], slope over N = "
          << "64..4096\n\n";
        for (size_t i = 0; i < battery.size(); ++i) {
            d << "\n#### " << battery[i].name << " (" << className(battery[i].cls) << ")\n\n| pattern | slope |";
            for (uint32_t N : res.ns) d << " N=" << N << " |";
            d << "\n|---|---|";
            for (size_t n = 0; n < NN; ++n) d << "---|";
            d << "\n";
            for (size_t v = 0; v < V; ++v) {
                std::vector<double> y;
                for (size_t n : slopeNs) y.push_back(std::log(res.cells[v][a][n].mse[i]));
                std::vector<double> bs(B);
                for (int b = 0; b < B; ++b) {
                    std::vector<double> yb;
                    for (size_t n : slopeNs) yb.push_back(std::log(res.cells[v][a][n].boot[i][b]));
                    bs[b] = slope(logN, yb);
                }
                d << "| " << res.variants[v].label() << " | " << fmtInterval(fromBoot(slope(logN, y), bs)) << " |";
                for (size_t n = 0; n < NN; ++n) {
                    const Cell& c = res.cells[v][a][n];
                    const Cell& s = res.cells[strat == V ? v : strat][a][n];
                    std::vector<double> br(B), bm(B);
                    for (int b = 0; b < B; ++b) br[b] = c.boot[i][b] / s.boot[i][b], bm[b] = c.boot[i][b];
                    const Interval ratio = fromBoot(c.mse[i] / s.mse[i], br);
                    const Interval mse = fromBoot(c.mse[i], bm);
                    d << " " << fmt(c.mse[i] * res.ns[n], 3) << "; " << fmtInterval(ratio) << " |";
                    const double perValue = c.seconds * 1e9 / (double(opt.sets) * res.ns[n] * (a + 1));
                    csv << res.variants[v].pattern << "," << res.variants[v].blue << "," << a + 1 << ",\""
                        << battery[i].name << "\"," << className(battery[i].cls) << "," << res.ns[n] << "," << mse.value
                        << "," << mse.lo << "," << mse.hi << "," << ratio.value << "," << ratio.lo << "," << ratio.hi
                        << "," << perValue << "\n";
                }
                d << "\n";
            }
        }
    }
    out.table += t.str();
    out.detail += d.str();
    out.csv += csv.str();
}

// ---- nested uniformity -------------------------------------------------------------------------------------------

std::string runNested(const Options& opt) {
    std::vector<std::string> patterns;
    for (const char* p : {"independent", "stratified", "sobol", "pmj02"})
        if (std::find(opt.patterns.begin(), opt.patterns.end(), p) != opt.patterns.end()) patterns.push_back(p);
    std::vector<uint32_t> ns;
    for (uint32_t N = 16; N <= (opt.quick ? 4096u : 65536u); N *= 4) ns.push_back(N);
    const int R = opt.sets;
    constexpr int kDims = 32;
    struct Row {
        double mean1 = 0, max1 = 0, mean2 = 0, max2 = 0;
    };
    std::vector<std::vector<Row>> rows(patterns.size(), std::vector<Row>(ns.size()));
    struct Task {
        size_t p, n;
    };
    std::vector<Task> tasks;
    for (size_t n = ns.size(); n-- > 0;)
        for (size_t p = 0; p < patterns.size(); ++p) tasks.push_back({p, n});
    parallelFor(opt.threads, tasks.size(), [&](size_t t) {
        const auto [p, n] = tasks[t];
        const uint32_t N = ns[n];
        uint32_t id;
        check(stipple_pattern_from_name(patterns[p].c_str(), &id), "pattern");
        std::vector<uint32_t> arities(kDims, 1);
        arities.insert(arities.end(), kDims, 2);
        const stipple::Sampler sampler = makeSampler({patterns[p], id, false}, N, arities, kSeed ^ 0x4e57ull);
        const stipple_sampler s = sampler.handle();
        std::vector<float> pts(size_t(N) * 2);
        // sum of (mean - 1/2)^2 per statistic: the mean of frac(N x) is exactly 1/2 for uniform points
        std::vector<double> sq(3 * kDims, 0.0);
        for (int r = 0; r < R; ++r) {
            uint32_t x, y;
            replicatePixel(r, x, y);
            for (uint32_t d = 0; d < 2 * kDims; ++d) {
                const uint32_t arity = d < kDims ? 1 : 2;
                check(stipple_sampler_fill_pixel(s, x, y, d, pts.data(), pts.size()), "fill_pixel");
                for (uint32_t c = 0; c < arity; ++c) {
                    double sum = 0;
                    for (uint32_t k = 0; k < N; ++k) {
                        // The centre of the float's 2^-24 cell: its corner would bias frac by 2^-25 N.
                        const double u = (double(pts[size_t(k) * arity + c]) + 0x1p-25) * N;
                        sum += u - std::floor(u);
                    }
                    const double m = sum / N - 0.5;
                    sq[d < kDims ? d : kDims + 2 * (d - kDims) + c] += m * m;
                }
            }
        }
        Row& row = rows[p][n];
        for (int i = 0; i < 3 * kDims; ++i) {
            const double stat = 12.0 * N * sq[i] / R;
            if (i < kDims)
                row.mean1 += stat / kDims, row.max1 = std::max(row.max1, stat);
            else
                row.mean2 += stat / (2 * kDims), row.max2 = std::max(row.max2, stat);
        }
    });
    std::ostringstream o;
    o << "12 N Var(mean of frac(N x)) over " << R << " pixels (1 for a nested uniform scramble; its standard error "
      << "is about " << fmt(std::sqrt(2.0 / R) * 100, 1) << " % per statistic, so the largest of 32 (64) "
      << "statistics of an exact scramble is about 1 + 2.0 (2.4) x " << fmt(std::sqrt(2.0 / R), 3)
      << "): mean and largest over the first 32 dimensions of arity 1, and over both axes of the next 32 of arity "
         "2.\n\n| pattern |";
    for (uint32_t N : ns) o << " N=" << N << " |";
    o << "\n|---|";
    for (size_t n = 0; n < ns.size(); ++n) o << "---|";
    o << "\n";
    for (size_t p = 0; p < patterns.size(); ++p) {
        o << "| " << patterns[p] << " 1D mean / max |";
        for (size_t n = 0; n < ns.size(); ++n) o << " " << fmt(rows[p][n].mean1) << " / " << fmt(rows[p][n].max1) << " |";
        o << "\n| " << patterns[p] << " 2D mean / max |";
        for (size_t n = 0; n < ns.size(); ++n) o << " " << fmt(rows[p][n].mean2) << " / " << fmt(rows[p][n].max2) << " |";
        o << "\n";
    }
    return o.str();
}

// ---- progressive prefixes: 4N samples of an N sampler against a fresh 4N set ---------------------------------------

std::string runPrefix(const Options& opt, const std::vector<Variant>& variants) {
    const std::vector<uint32_t> ns = opt.quick ? std::vector<uint32_t>{16, 256} : std::vector<uint32_t>{16, 64, 256, 1024};
    std::vector<std::vector<Integrand>> integrands;
    for (int a = 1; a <= 3; ++a) integrands.push_back(makeBattery(a));
    const int R = opt.sets;
    // err[v][a][n][fresh?][integrand][r]
    struct Cell2 {
        Cell past, fresh;
    };
    const size_t V = variants.size();
    std::vector<Cell2> cells(V * 3 * ns.size());
    parallelFor(opt.threads, cells.size() * 2, [&](size_t t) {
        const size_t c = t / 2;
        const bool fresh = t % 2;
        const size_t v = c / (3 * ns.size()), a = (c / ns.size()) % 3, n = c % ns.size();
        const uint32_t N = ns[n], arity = uint32_t(a + 1), M = 4 * N;
        const auto& battery = integrands[a];
        const stipple::Sampler sampler = makeSampler(variants[v], fresh ? M : N, {}, kSeed ^ 0x9e3ull);
        const stipple_sampler s = sampler.handle();
        Cell& cell = fresh ? cells[c].fresh : cells[c].past;
        cell.err.assign(battery.size(), std::vector<double>(R));
        std::vector<float> pts(size_t(M) * arity);
        for (int r = 0; r < R; ++r) {
            uint32_t x, y;
            replicatePixel(r, x, y);
            check(stipple_sampler_stream_fill(s, x, y, 0, M, 0, arity, pts.data(), pts.size()), "stream_fill");
            for (size_t i = 0; i < battery.size(); ++i) {
                const int inst = r % battery[i].instances;
                double sum = 0;
                for (uint32_t k = 0; k < M; ++k) sum += battery[i](inst, &pts[size_t(k) * arity]);
                const double e = sum / M - battery[i].exact[inst];
                cell.err[i][r] = e * e / battery[i].variance[inst];
            }
        }
        bootstrap(cell, opt.boot, 0x9f3ull + t);
    });
    std::ostringstream o;
    o << "MSE of samples 0 .. 4N-1 of an N-sample sampler (stream_fill past N) / MSE of a fresh 4N-sample set, "
      << R << " pixels: geometric mean over the arity's integrands [95% bootstrap] and the largest single "
         "integrand's ratio.\n\n| pattern | d |";
    for (uint32_t N : ns) o << " N=" << N << " -> " << 4 * N << " |";
    o << "\n|---|---|";
    for (size_t n = 0; n < ns.size(); ++n) o << "---|";
    o << "\n";
    for (size_t v = 0; v < V; ++v)
        for (size_t a = 0; a < 3; ++a) {
            o << "| " << variants[v].label() << " | " << a + 1 << " |";
            for (size_t n = 0; n < ns.size(); ++n) {
                const Cell2& c = cells[(v * 3 + a) * ns.size() + n];
                std::vector<size_t> all(integrands[a].size());
                for (size_t i = 0; i < all.size(); ++i) all[i] = i;
                std::vector<double> br(opt.boot);
                for (int b = 0; b < opt.boot; ++b) br[b] = geoMean(c.past, all, b) / geoMean(c.fresh, all, b);
                size_t wi = 0;
                for (size_t i : all)
                    if (c.past.mse[i] / c.fresh.mse[i] > c.past.mse[wi] / c.fresh.mse[wi]) wi = i;
                o << " " << fmtInterval(fromBoot(geoMean(c.past, all, -1) / geoMean(c.fresh, all, -1), br))
                  << "; max " << fmt(c.past.mse[wi] / c.fresh.mse[wi]) << " " << integrands[a][wi].name << " |";
            }
            o << "\n";
        }
    return o.str();
}

// ---- the grown battery: MSE against stratified per family, N = 16, 64, 256 ----------------------------------------

// Normalised squared errors err[integrand][pixel] of one variant at N over the grown battery; gratings all at once
// from per-point powers of exp(2 pi i x) and exp(2 pi i y).
std::vector<std::vector<double>> grownErrors(const Variant& v, uint32_t n, const std::vector<GrownIntegrand>& battery,
                                             int R) {
    const stipple::Sampler sampler = makeSampler(v, n, {2}, kSeed ^ 0x6e0ull);
    const stipple_sampler s = sampler.handle();
    std::vector<std::vector<double>> err(battery.size(), std::vector<double>(size_t(R)));
    int radius = 0;
    for (const GrownIntegrand& g : battery) radius = std::max({radius, std::abs(g.k[0]), std::abs(g.k[1])});
    const size_t span = size_t(2 * radius + 1);
    std::vector<std::complex<double>> ex(size_t(n) * span), ey(size_t(n) * span);
    std::vector<float> pts(size_t(n) * 2);
    for (int r = 0; r < R; ++r) {
        uint32_t x, y;
        replicatePixel(r, x, y);
        check(stipple_sampler_fill_pixel(s, x, y, 0, pts.data(), pts.size()), "fill_pixel");
        for (uint32_t p = 0; p < n; ++p)
            for (int axis = 0; axis < 2; ++axis) {
                std::complex<double>* e = (axis == 0 ? ex.data() : ey.data()) + p * span;
                const std::complex<double> w = std::polar(1.0, 2 * detail::kPi * pts[2 * p + axis]);
                e[radius] = 1;
                for (int k = 1; k <= radius; ++k) {
                    e[radius + k] = e[radius + k - 1] * w;
                    e[radius - k] = std::conj(e[radius + k]);
                }
            }
        for (size_t g = 0; g < battery.size(); ++g) {
            const Integrand& in = battery[g].integrand;
            double sum = 0;
            if (battery[g].family == "grating") {
                const size_t ix = size_t(battery[g].k[0] + radius), iy = size_t(battery[g].k[1] + radius);
                for (uint32_t p = 0; p < n; ++p) sum += (ex[p * span + ix] * ey[p * span + iy]).real();
            } else
                for (uint32_t p = 0; p < n; ++p) sum += in(0, &pts[2 * size_t(p)]);
            const double e = sum / n - in.exact[0];
            err[g][size_t(r)] = e * e / in.variance[0];
        }
    }
    return err;
}

std::string runGrown(const Options& opt, const std::vector<Variant>& variants) {
    const std::vector<uint32_t> ns = {16, 64, 256};
    const int R = opt.sets, B = opt.boot;
    size_t reference = variants.size();
    for (size_t v = 0; v < variants.size(); ++v)
        if (variants[v].pattern == "stratified" && !variants[v].blue) reference = v;
    if (reference == variants.size()) fail("--sections grown needs stratified among --patterns (the reference)");
    std::vector<std::vector<GrownIntegrand>> batteries;
    for (uint32_t n : ns) batteries.push_back(makeGrownBattery(n));
    // cells[v * ns + n]: per integrand the MSE and B bootstrap means (pixels resampled, the same for all integrands).
    std::vector<Cell> cells(variants.size() * ns.size());
    parallelFor(opt.threads, cells.size(), [&](size_t c) {
        const size_t v = c / ns.size(), n = c % ns.size();
        cells[c].err = grownErrors(variants[v], ns[n], batteries[n], R);
        bootstrap(cells[c], B, 0x6e1ull + c);
        cells[c].err.clear();
    });
    std::ostringstream o;
    o << "# The grown battery: MSE against stratified\n\n"
      << "Generated by `shim_battery --sections grown" << (opt.blue ? "" : " --no-blue") << " --sets " << R
      << " --grown-file <this file>`; do not edit by hand. Normalised MSE of every integrand of the grown 2D battery "
         "(bench/battery_grown.h; it depends on N: gratings cos(2 pi k.x) at every |k| <= 2 sqrt(N), thin stripes a "
         "quarter stratum wide, steps off the stratum faces, bumps a quarter stratum wide), "
      << R << " pixels per cell (each its own randomisation; seed 0x" << std::hex << (kSeed ^ 0x6e0ull) << std::dec
      << "), one 2D dimension through fill_pixel. Per family: the MSE ratio to stratified, geometric mean over the "
         "family's integrands [95% bootstrap, " << B << " resamples of the pixels] and the worst integrand's ratio. "
         "Integrands stratified integrates exactly (a checkerboard aligned with its strata) are left out of the "
         "ratios.\n\n";
    for (size_t n = 0; n < ns.size(); ++n) {
        const std::vector<GrownIntegrand>& battery = batteries[n];
        std::vector<std::string> families;
        for (const GrownIntegrand& g : battery)
            if (std::find(families.begin(), families.end(), g.family) == families.end()) families.push_back(g.family);
        o << "### N = " << ns[n] << "\n\n| pattern |";
        for (const std::string& f : families) o << " " << f << " |";
        o << "\n|---|";
        for (size_t f = 0; f < families.size(); ++f) o << "---|";
        o << "\n";
        const Cell& ref = cells[reference * ns.size() + n];
        for (size_t v = 0; v < variants.size(); ++v) {
            if (v == reference) continue;
            const Cell& cell = cells[v * ns.size() + n];
            o << "| " << variants[v].label() << " |";
            for (const std::string& family : families) {
                std::vector<size_t> members;
                for (size_t g = 0; g < battery.size(); ++g)
                    if (battery[g].family == family && ref.mse[g] > 1e-30) members.push_back(g);
                if (members.empty()) {
                    o << " - |";
                    continue;
                }
                auto geo = [&](int b) {
                    double s = 0;
                    for (size_t g : members)
                        s += std::log((b < 0 ? cell.mse[g] : cell.boot[g][size_t(b)]) /
                                      (b < 0 ? ref.mse[g] : ref.boot[g][size_t(b)]));
                    return std::exp(s / double(members.size()));
                };
                std::vector<double> resampled(static_cast<size_t>(B));
                for (int b = 0; b < B; ++b) resampled[size_t(b)] = geo(b);
                size_t worst = members[0];
                for (size_t g : members)
                    if (cell.mse[g] / ref.mse[g] > cell.mse[worst] / ref.mse[worst]) worst = g;
                o << " " << fmtInterval(fromBoot(geo(-1), resampled)) << "; max " << fmt(cell.mse[worst] / ref.mse[worst])
                  << " " << battery[worst].integrand.name << " |";
            }
            o << "\n";
        }
        o << "\n";
    }
    return o.str();
}

void replaceSection(const fs::path& file, const std::string& body) {
    std::ifstream in(file);
    if (!in) fail("cannot read " + file.string());
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    const std::string begin = "<!-- battery:begin -->", end = "<!-- battery:end -->";
    const size_t b = text.find(begin), e = text.find(end);
    if (b == std::string::npos || e == std::string::npos || e < b)
        fail(file.string() + ": no \"" + begin + "\" ... \"" + end + "\" section to replace");
    const std::string updated = text.substr(0, b + begin.size()) + "\n" + body + text.substr(e);
    const fs::path tmp = file.string() + ".tmp";
    {
        std::ofstream o(tmp);
        o << updated;
        if (!o) fail("cannot write " + tmp.string());
    }
    fs::rename(tmp, file);
}

} // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail("option " + a + " needs a value");
            return argv[++i];
        };
        auto number = [&](int lo) {
            const std::string v = value();
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (end == v.c_str() || *end != '\0' || n < lo || n > 1000000)
                fail("option " + a + ": expected an integer >= " + std::to_string(lo) + ", got \"" + v + "\"");
            return int(n);
        };
        if (a == "-o") opt.outDir = value();
        else if (a == "--pointsets") opt.pointsets = value();
        else if (a == "--sets") opt.sets = number(16);
        else if (a == "--boot") opt.boot = number(20);
        else if (a == "--threads") opt.threads = number(1);
        else if (a == "--quick") opt.quick = true;
        else if (a == "--no-blue") opt.blue = false;
        else if (a == "--patterns") opt.patterns = splitList(value());
        else if (a == "--sections") opt.sections = splitList(value());
        else if (a == "--grown-file") opt.grownFile = value();
        else fail("unknown argument \"" + a + "\" (see the comment at the top of battery.cpp)");
    }
    if (opt.patterns.empty() && !stipple::patternNames(opt.patterns).ok()) fail("the library lists no patterns");
    std::vector<Variant> variants;
    for (const std::string& p : opt.patterns) {
        uint32_t id;
        if (stipple_pattern_from_name(p.c_str(), &id) != STIPPLE_OK) fail("--patterns: unknown pattern \"" + p + "\"");
        variants.push_back({p, id, false});
    }
    if (opt.blue)
        for (const std::string& p : opt.patterns) {
            uint32_t id;
            stipple_pattern_from_name(p.c_str(), &id);
            // Only the patterns whose limits take the flag (the others refuse it at creation).
            stipple_pattern_limits limits{};
            if (stipple::patternLimits(p, limits).ok() && (limits.flags & STIPPLE_SAMPLER_FLAG_BLUE_NOISE))
                variants.push_back({p, id, true});
        }
    auto has = [&](const char* s) { return std::find(opt.sections.begin(), opt.sections.end(), s) != opt.sections.end(); };
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

    std::ostringstream summary, detail;
    Summary battery;
    if (has("battery")) {
        BatteryResult res;
        res.variants = variants;
        runBattery(opt, res);
        summariseBattery(opt, res, battery);
        std::cerr << "battery: " << fmt(elapsed(), 1) << " s\n";
        summary << "### The battery: slope and MSE against stratified per class\n\n"
                << "Normalised MSE (MSE / Var f) of every integrand of battery_integrands.h, " << opt.sets
                << " pixels per cell (each a separate randomisation; Genz instances cycle over the pixels), "
                << "seed 0x" << std::hex << kSeed << std::dec
                << ". Per class the geometric mean over its integrands; slope of log MSE over N = 64 .. 4096 "
                   "(powers of two), 95% bootstrap intervals (" << opt.boot << " resamples); theory: the MSE "
                   "exponent for the class (§ \"Rates\"); \"+bn\" is the blue-noise flag. The worst integrand is "
                   "the one with the largest MSE ratio to stratified at that N.\n\n"
                << battery.table << "\n";
    }
    if (has("nested")) {
        summary << "### Nested uniformity\n\n" << runNested(opt) << "\n";
        std::cerr << "nested: " << fmt(elapsed(), 1) << " s\n";
    }
    if (has("prefix")) {
        std::vector<Variant> pv;
        for (const Variant& v : variants)
            if (!v.blue && v.pattern != "poisson-seed") pv.push_back(v);
        summary << "### Past N: 4N samples of an N-sample sampler\n\n" << runPrefix(opt, pv) << "\n";
        std::cerr << "prefix: " << fmt(elapsed(), 1) << " s\n";
    }
    if (has("grown")) {
        const std::string table = runGrown(opt, variants);
        const fs::path file = opt.grownFile.empty() ? opt.outDir / "battery-grown.md" : opt.grownFile;
        if (file.has_parent_path()) fs::create_directories(file.parent_path());
        const fs::path tmp = file.string() + ".tmp";
        {
            std::ofstream o(tmp);
            o << table;
            if (!o) fail("cannot write " + tmp.string());
        }
        fs::rename(tmp, file);
        std::cerr << "grown: " << fmt(elapsed(), 1) << " s, " << file.string() << "\n";
    }
    summary << "(`shim_battery" << (opt.quick ? " --quick" : "") << " --sets " << opt.sets
            << "`, " << fmt(elapsed(), 0) << " s on " << opt.threads << " threads.)\n";

    fs::create_directories(opt.outDir);
    std::ofstream(opt.outDir / "battery.md") << "# Integrand battery\n\n" << summary.str() << "\n## Per integrand\n"
                                             << battery.detail;
    std::ofstream(opt.outDir / "battery.csv") << battery.csv;
    if (!opt.pointsets.empty()) replaceSection(opt.pointsets, summary.str());
    std::cout << summary.str();
    return 0;
}
