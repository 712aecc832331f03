// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pointsets_figure3.cpp — the study's Figure 3 (generation time vs N per pattern, 1D/2D/3D), redone, plus the
// quality tables and the isotropy figure of shim/POINTSETS.md. One command:
//
//     build/release/bin/shim_pointsets_figure3 -o report/figure3          (~2.5 min of CPU; more wall time on a loaded
//     machine) build/release/bin/shim_pointsets_figure3 -o report/figure3 --quick  (reduced: ~20 s, for a smoke test)
//
// Writes into the output directory:
//   timing.csv      pattern, dim, n, seconds per set (thread CPU time and wall), points/s
//   slopes.csv      least-squares slope of log t vs log N per pattern and dim (over all N, and over N >= 1024)
//   rho.csv/.md     min, mean rho and mean nearest-neighbour rho over --sets sets per N, both generators, 1D/2D/3D
//   spectrum.csv    radial power spectrum and anisotropy (dB) of 2D sets of 1024 points, per pattern
//   figure3.{png,svg}, rho.{png,svg}, spectrum.{png,svg} and the gnuplot scripts that drew them
//   summary.md      the tables, the slopes and the speed-ups at N = 4096 and 100 000
//
// Patterns timed: independent and stratified through the C API (one stipple_sampler_fill_pixel call = one fresh
// set of N points, new pixel every call); poisson-seed and poisson as fresh generation (pointsets::generate*);
// poisson-served through the C API from the warmed cache (what hosts pay per pixel; warm-up timed apart).
// Times are thread CPU time (the machine is shared; wall time is in the CSV too).
#include <stipple/stipple.hpp>
#include <stipple/version.h>

#include "pointsets/pointsets.h"
#include "pointsets/spectrum.h"
#include "poisson_cache.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace stipple::detail::pointsets;

namespace {

double threadSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
double wallSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Options {
    fs::path out = "report/figure3";
    int sets = 1000;        // for the rho table
    int spectrumSets = 100; // for the spectrum
    double minTime = 0.05;  // seconds of CPU per timing cell
    bool quick = false;
};

// A one-dimension layout (one value of `arity` per sample) through stipple.hpp; empty when the library refuses it
// (its message in sampler.status()).
struct LayoutSampler {
    stipple::Sampler sampler;
    LayoutSampler(uint32_t pattern, uint32_t arity, uint32_t n, uint64_t seed) {
        const char* name = "";
        stipple_pattern_name(pattern, &name);
        (void)stipple::Sampler::create(sampler, name, n, seed, {{arity, 1, ""}}); // a failure: sampler.status()
    }
    stipple_sampler handle() const { return sampler.handle(); }
};

struct Timing {
    double cpu = 0, wall = 0; // seconds per set
};

// Repeats `once` until minTime of CPU has passed (at least twice, or once if a single call exceeds 1 s).
Timing timeIt(const std::function<void(uint64_t)>& once, double minTime) {
    once(0); // warm caches and the allocator
    double c0 = threadSeconds(), w0 = wallSeconds();
    uint64_t reps = 0;
    double c = 0;
    do {
        once(++reps);
        c = threadSeconds() - c0;
    } while (c < minTime && !(c > 1.0));
    return {c / double(reps), (wallSeconds() - w0) / double(reps)};
}

const char* kPatterns[] = {"independent", "stratified", "poisson-seed", "poisson", "poisson-served"};

std::vector<uint32_t> timingSizes(bool quick) {
    if (quick) return {16, 256, 4096, 100000};
    return {16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384, 32768, 65536, 100000};
}

// Least-squares slope of log10 t against log10 N.
double slope(const std::vector<std::pair<double, double>>& nt) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (auto [n, t] : nt) {
        double x = std::log10(n), y = std::log10(t);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    double m = double(nt.size());
    return nt.size() < 2 ? 0.0 : (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

bool runGnuplot(const fs::path& script) {
    std::string cmd = "gnuplot '" + script.string() + "' 2>&1";
    int rc = std::system(cmd.c_str());
    if (rc != 0) std::cerr << "gnuplot failed (" << rc << ") on " << script << "; the CSV files are complete\n";
    return rc == 0;
}

void writeScript(const fs::path& path, const std::string& body) {
    std::ofstream f(path);
    f << body;
}

} // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&](const char* what) -> std::string {
            if (i + 1 >= argc) {
                std::cerr << "error: " << a << " needs " << what << "\n";
                std::exit(2);
            }
            return argv[++i];
        };
        auto number = [&](const char* what, int lo, int hi) {
            std::string v = value(what);
            char* end = nullptr;
            long x = std::strtol(v.c_str(), &end, 10);
            if (end == v.c_str() || *end != '\0' || x < lo || x > hi) {
                std::cerr << "error: " << a << " expects " << what << " in [" << lo << ", " << hi << "], got '" << v
                          << "'\n";
                std::exit(2);
            }
            return int(x);
        };
        if (a == "--version") {
            std::cout << stipple::versionLine("shim_pointsets_figure3") << "\n";
            return 0;
        } else if (a == "-o" || a == "--output")
            opt.out = value("a directory");
        else if (a == "--sets")
            opt.sets = number("a set count", 1, 100000);
        else if (a == "--spectrum-sets")
            opt.spectrumSets = number("a set count", 1, 10000);
        else if (a == "--quick")
            opt.quick = true;
        else if (a == "-h" || a == "--help") {
            std::cout << "usage: " << argv[0] << " [-o DIR] [--sets M (1000)] [--spectrum-sets S (100)] [--quick]\n";
            return 0;
        } else {
            std::cerr << "error: unknown argument '" << a << "' (try --help)\n";
            return 2;
        }
    }
    if (opt.quick) {
        opt.sets = std::min(opt.sets, 50);
        opt.spectrumSets = std::min(opt.spectrumSets, 10);
        opt.minTime = 0.01;
    }
    std::error_code ec;
    fs::create_directories(opt.out, ec);
    if (ec) {
        std::cerr << "error: cannot create output directory " << opt.out << ": " << ec.message() << "\n";
        return 1;
    }

    // ---- 1. timing ------------------------------------------------------------------------------------------
    std::ofstream timing(opt.out / "timing.csv");
    timing << "pattern,dim,n,cpu_seconds_per_set,wall_seconds_per_set,points_per_second\n";
    std::map<std::pair<std::string, int>, std::vector<std::pair<double, double>>> series;
    std::map<std::tuple<std::string, int, uint32_t>, double> cpuOf;
    std::ofstream warmup(opt.out / "poisson_warmup.csv");
    warmup << "dim,n,sets,cpu_seconds\n";
    for (int dim = 1; dim <= 3; ++dim)
        for (uint32_t n : timingSizes(opt.quick)) {
            std::vector<float> buffer(size_t(n) * dim);
            for (const char* pattern : kPatterns) {
                std::string p = pattern;
                Timing t;
                if (p == "poisson-seed" || p == "poisson") {
                    auto gen = p == "poisson" ? &generatePoisson : &generatePoissonSeed;
                    t = timeIt([&](uint64_t r) { buffer = gen(dim, n, 1000 + r); }, opt.minTime);
                } else {
                    uint32_t code = p == "independent"  ? STIPPLE_PATTERN_INDEPENDENT
                                    : p == "stratified" ? STIPPLE_PATTERN_STRATIFIED
                                                        : STIPPLE_PATTERN_POISSON;
                    LayoutSampler s(code, uint32_t(dim), n, 7);
                    if (!s.sampler) {
                        std::cerr << "error: sampler " << p << " dim " << dim << " n " << n << ": "
                                  << s.sampler.status().message() << "\n";
                        return 1;
                    }
                    if (code == STIPPLE_PATTERN_POISSON) { // warm the whole family first, timed apart
                        double c0 = threadSeconds();
                        auto family = stipple::detail::PoissonCache::global().acquire(uint32_t(dim), n);
                        for (uint32_t j = 0; j < family->setCount(); ++j) family->set(j);
                        warmup << dim << "," << n << "," << family->setCount() << "," << threadSeconds() - c0 << "\n";
                    }
                    t = timeIt(
                        [&](uint64_t r) {
                            stipple_sampler_fill_pixel(s.handle(), uint32_t(r % 4096), uint32_t(r / 4096), 0,
                                                       buffer.data(), buffer.size());
                        },
                        opt.minTime);
                }
                timing << p << "," << dim << "," << n << "," << t.cpu << "," << t.wall << "," << n / t.cpu << "\n";
                series[{p, dim}].push_back({double(n), t.cpu});
                cpuOf[{p, dim, n}] = t.cpu;
            }
            std::cerr << "timed dim " << dim << " n " << n << "\n";
        }
    timing.close();
    warmup.close();

    std::ofstream slopes(opt.out / "slopes.csv");
    slopes << "pattern,dim,slope_all_n,slope_n_ge_1024\n";
    std::ostringstream slopeTable;
    slopeTable << "| pattern | 1D | 2D | 3D |\n|---|---|---|---|\n";
    for (const char* pattern : kPatterns) {
        slopeTable << "| " << pattern;
        for (int dim = 1; dim <= 3; ++dim) {
            const auto& s = series[{pattern, dim}];
            std::vector<std::pair<double, double>> large;
            for (auto nt : s)
                if (nt.first >= 1024) large.push_back(nt);
            slopes << pattern << "," << dim << "," << slope(s) << "," << slope(large) << "\n";
            char cell[64];
            std::snprintf(cell, sizeof cell, " | %.2f (%.2f)", slope(s), slope(large));
            slopeTable << cell;
        }
        slopeTable << " |\n";
    }
    slopes.close();

    // ---- 2. rho over many sets ------------------------------------------------------------------------------
    struct RhoRow {
        std::string generator;
        int dim;
        uint32_t n;
        double min, mean, nn;
    };
    std::vector<RhoRow> rhoRows;
    std::ofstream rho(opt.out / "rho.csv");
    rho << "generator,dim,n,sets,rho_min,rho_mean,nn_rho_mean\n";
    std::ostringstream rhoTable;
    rhoTable << "| dim | N | poisson min | poisson mean | poisson NN mean | poisson-seed min | poisson-seed mean | "
                "poisson-seed NN mean |\n|---|---|---|---|---|---|---|---|\n";
    const std::vector<uint32_t> rhoSizes = opt.quick
                                               ? std::vector<uint32_t>{16, 256, 4096}
                                               : std::vector<uint32_t>{16, 32, 64, 128, 256, 512, 1024, 2048, 4096};
    for (int dim = 1; dim <= 3; ++dim)
        for (uint32_t n : rhoSizes) {
            double stats[2][3];
            for (int g = 0; g < 2; ++g) {
                double mn = 1e9, mean = 0, nn = 0;
                for (int s = 0; s < opt.sets; ++s) {
                    std::vector<float> pts =
                        g == 0 ? generatePoisson(dim, n, 0x5e7000 + s) : generatePoissonSeed(dim, n, 0x5e7000 + s);
                    double r = relativeRadius(dim, pts.data(), n);
                    mn = std::min(mn, r);
                    mean += r / opt.sets;
                    nn += meanNearestNeighbourRadius(dim, pts.data(), n) / opt.sets;
                }
                stats[g][0] = mn;
                stats[g][1] = mean;
                stats[g][2] = nn;
                rhoRows.push_back({g == 0 ? "poisson" : "poisson-seed", dim, n, mn, mean, nn});
                rho << (g == 0 ? "poisson" : "poisson-seed") << "," << dim << "," << n << "," << opt.sets << "," << mn
                    << "," << mean << "," << nn << "\n";
            }
            char line[256];
            std::snprintf(line, sizeof line, "| %d | %u | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", dim, n,
                          stats[0][0], stats[0][1], stats[0][2], stats[1][0], stats[1][1], stats[1][2]);
            rhoTable << line;
            std::cerr << "rho dim " << dim << " n " << n << "\n";
        }
    rho.close();
    {
        std::ofstream md(opt.out / "rho.md");
        md << "rho = d_min / d_max over " << opt.sets << " sets per N (d_max: 1/N, hexagonal, FCC).\n\n"
           << rhoTable.str();
    }

    // ---- 3. spectrum of 2D sets of 1024 points --------------------------------------------------------------
    const uint32_t sn = 1024;
    const int K = 2 * 32; // frequencies up to 2 sqrt(N)
    std::ofstream spec(opt.out / "spectrum.csv");
    spec << "pattern,f_over_sqrt_n,power,anisotropy_db,sets\n";
    for (const char* pattern : {"independent", "stratified", "poisson-seed", "poisson"}) {
        std::string p = pattern;
        PowerSpectrum spectrum(2, K);
        LayoutSampler independent(STIPPLE_PATTERN_INDEPENDENT, 2, sn, 11), stratified(STIPPLE_PATTERN_STRATIFIED, 2, sn, 11);
        std::vector<float> buffer(2 * sn);
        for (int s = 0; s < opt.spectrumSets; ++s) {
            if (p == "poisson")
                buffer = generatePoisson(2, sn, 0x5bec + s);
            else if (p == "poisson-seed")
                buffer = generatePoissonSeed(2, sn, 0x5bec + s);
            else
                stipple_sampler_fill_pixel(p == "independent" ? independent.handle() : stratified.handle(), uint32_t(s), 0,
                                           0, buffer.data(), buffer.size());
            spectrum.add(buffer.data(), sn);
        }
        for (const auto& ring : spectrum.annuli())
            spec << p << "," << double(ring.radius) / std::sqrt(double(sn)) << "," << ring.mean << "," << ring.anisotropy << ","
                 << opt.spectrumSets << "\n";
        std::cerr << "spectrum " << p << "\n";
    }
    spec.close();

    // ---- 4. plots -------------------------------------------------------------------------------------------
    // gnuplot draws lines within a data block: one block per (dim, pattern), selected with `index`.
    const std::string timingDat = (opt.out / "figure3.dat").string();
    {
        std::ofstream dat(timingDat);
        for (int dim = 1; dim <= 3; ++dim)
            for (const char* pattern : kPatterns) {
                dat << "# " << pattern << " " << dim << "D: n cpu_seconds\n";
                for (auto [n, t] : series[{pattern, dim}]) dat << n << " " << t << "\n";
                dat << "\n\n";
            }
    }
    std::ostringstream fig;
    fig << "set key top left font ',9'\nset logscale xy\nset format y '10^{%L}'\nset xrange [10:200000]\n"
        << "set xlabel 'N (points per set)'\nset ylabel 'CPU seconds per set'\nset grid\n";
    std::ostringstream plots;
    plots << "set multiplot layout 1,3 title 'Generation time vs N (study Figure 3, redone)'\n";
    for (int dim = 1; dim <= 3; ++dim) {
        plots << "set title '" << dim << "D'\nplot ";
        int k = 0;
        for (int p = 0; p < 5; ++p)
            plots << (k++ ? ", " : "") << "'" << timingDat << "' index " << (dim - 1) * 5 + p
                  << " using 1:2 with linespoints title '" << kPatterns[p] << "'";
        plots << "\n";
    }
    plots << "unset multiplot\n";
    std::string fig3 = fig.str();
    writeScript(opt.out / "figure3.gp", fig3 + "set terminal pngcairo size 1500,500\nset output '" +
                                            (opt.out / "figure3.png").string() + "'\n" + plots.str() +
                                            "set terminal svg size 1500,500\nset output '" +
                                            (opt.out / "figure3.svg").string() + "'\n" + plots.str());

    const std::string rhoDat = (opt.out / "rho.dat").string();
    {
        std::ofstream dat(rhoDat);
        for (int dim = 1; dim <= 3; ++dim)
            for (const char* g : {"poisson", "poisson-seed"}) {
                dat << "# " << g << " " << dim << "D: n rho_min rho_mean nn_rho_mean\n";
                for (const auto& row : rhoRows)
                    if (row.dim == dim && row.generator == g)
                        dat << row.n << " " << row.min << " " << row.mean << " " << row.nn << "\n";
                dat << "\n\n";
            }
    }
    std::ostringstream rp;
    rp << "set multiplot layout 1,3 title 'relative radius rho over " << opt.sets << " sets'\n";
    for (int dim = 1; dim <= 3; ++dim) {
        rp << "set title '" << dim << "D'\nplot ";
        int k = 0;
        for (int g = 0; g < 2; ++g)
            for (int col : {2, 3}) {
                rp << (k++ ? ", " : "") << "'" << rhoDat << "' index " << (dim - 1) * 2 + g << " using 1:" << col
                   << " with linespoints title '" << (g == 0 ? "poisson" : "poisson-seed")
                   << (col == 2 ? " min" : " mean") << "'";
            }
        rp << "\n";
    }
    rp << "unset multiplot\n";
    const std::string rhoHead = "set key bottom left font ',9'\nset logscale x\nset yrange [0.3:1.05]\n"
                                "set xlabel 'N'\nset ylabel 'rho'\nset grid\n";
    writeScript(opt.out / "rho.gp", rhoHead + "set terminal pngcairo size 1500,500\nset output '" +
                                        (opt.out / "rho.png").string() + "'\n" + rp.str() +
                                        "set terminal svg size 1500,500\nset output '" +
                                        (opt.out / "rho.svg").string() + "'\n" + rp.str());

    const std::string specCsv = (opt.out / "spectrum.csv").string();
    std::ostringstream sp;
    sp << "set multiplot layout 1,2 title 'Radial power spectrum and anisotropy, 2D, N = 1024, " << opt.spectrumSets
       << " sets'\n";
    for (int col : {3, 4}) {
        sp << "set title '" << (col == 3 ? "radial power" : "anisotropy (dB)") << "'\nset ylabel '"
           << (col == 3 ? "P(f)" : "dB") << "'\n";
        if (col == 4) sp << "set yrange [-30:10]\n";
        sp << "plot ";
        int k = 0;
        for (const char* pattern : {"independent", "stratified", "poisson-seed", "poisson"})
            sp << (k++ ? ", " : "") << "'" << specCsv << "' using (strcol(1) eq '" << pattern << "' ? $2 : 1/0):" << col
               << " with lines title '" << pattern << "'";
        if (col == 4)
            sp << ", " << 10.0 * std::log10(1.0 / opt.spectrumSets)
               << " with lines dt 2 lc 'black' title 'isotropic floor'";
        sp << "\n";
    }
    sp << "unset multiplot\n";
    const std::string specHead =
        "set datafile separator ','\nset key top right font ',9'\nset xlabel 'f / sqrt(N)'\nset grid\n";
    writeScript(opt.out / "spectrum.gp", specHead + "set terminal pngcairo size 1300,500\nset output '" +
                                             (opt.out / "spectrum.png").string() + "'\n" + sp.str() +
                                             "set terminal svg size 1300,500\nset output '" +
                                             (opt.out / "spectrum.svg").string() + "'\n" + sp.str());
    bool plotted =
        runGnuplot(opt.out / "figure3.gp") & runGnuplot(opt.out / "rho.gp") & runGnuplot(opt.out / "spectrum.gp");

    // ---- 5. summary -----------------------------------------------------------------------------------------
    std::ostringstream summary;
    summary << "# Figure 3, redone: generation time and quality of the Poisson sets\n\n"
            << "Times are thread CPU seconds per set of N points (independent, stratified, poisson-served: one "
               "stipple_sampler_fill_pixel call; poisson, poisson-seed: fresh generation).\n\n"
            << "## Log-log slopes of time vs N (all N; N >= 1024 in parentheses)\n\n"
            << slopeTable.str() << "\n## Speed-ups of fresh poisson over poisson-seed\n\n"
            << "| dim | N | poisson-seed s | poisson s | speed-up | poisson points/s |\n|---|---|---|---|---|---|\n";
    for (int dim = 1; dim <= 3; ++dim)
        for (uint32_t n : {4096u, 100000u}) {
            double a = cpuOf[{"poisson-seed", dim, n}], b = cpuOf[{"poisson", dim, n}];
            char line[200];
            std::snprintf(line, sizeof line, "| %d | %u | %.4g | %.4g | %.2f | %.3g |\n", dim, n, a, b, a / b, n / b);
            summary << line;
        }
    summary << "\n## rho over " << opt.sets << " sets per N\n\n"
            << rhoTable.str() << "\nFigures: figure3.png, rho.png, spectrum.png (and .svg)"
            << (plotted ? "" : " — gnuplot failed") << ".\n";
    std::ofstream(opt.out / "summary.md") << summary.str();
    std::cout << summary.str();
    return plotted ? 0 : 1;
}
