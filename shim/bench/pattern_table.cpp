// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_table.cpp — the one table of shim/POINTSETS.md for every pattern, the blue-noise spectrum and the
// poisson / stratified MSE ratios, measured through the C API in one run.
//
//   shim_pattern_table -o DIR [--sets R (500)] [--quick] [--poisson-only] [--blue-only] [--ns N,N,...]
//                      [--shifts S (1000)]
//
// Writes DIR/table.md (rho, MSE slopes on disk / step / Gaussian with 95% bootstrap intervals, cost per value),
// DIR/blue_noise.md + spectrum_blue.csv + blue_noise.{png,svg} (radial power spectrum of the per-pixel error of
// the Gaussian, gnuplot; flag / plain MSE ratios on the Gaussian, the step, a ramp and an off-centre Gaussian),
// DIR/poisson_vs_stratified.md (MSE ratios per N and integrand with 95% intervals, 2D and 3D) and
// DIR/poisson_spread.md (MSE of each cached poisson base set, max / min per N, with the base sets' rho and
// generation time). --poisson-only writes only the last two (the poisson / stratified comparison); --ns sets
// its N. --blue-only writes only the blue-noise files.
#include "pointsets/pointsets.h"
#include "poisson_cache.h"
#include "hash.h"

#include <stipple/stipple.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Every pattern the library lists (stipple_pattern_count / stipple_pattern_name, through the kit).
std::vector<std::string> allPatterns() {
    std::vector<std::string> names;
    const stipple::Status s = stipple::patternNames(names);
    if (!s.ok()) throw std::runtime_error("listing the library's patterns: " + s.message());
    return names;
}

struct Integrand {
    const char* name;
    std::function<double(const float*)> f;
    double exact;
};

// 2D: a disk (edge along a curve), a slanted step (straight edge), a smooth Gaussian. 3D: ball and Gaussian.
std::vector<Integrand> integrands(int dim) {
    const double pi = 3.14159265358979323846;
    const double sigma = 0.15;
    const double g1 = sigma * std::sqrt(2 * pi) * std::erf(0.5 / (sigma * std::sqrt(2.0)));
    auto gauss = [sigma, dim](const float* p) {
        double r2 = 0;
        for (int c = 0; c < dim; ++c) r2 += (p[c] - 0.5) * (p[c] - 0.5);
        return std::exp(-r2 / (2 * sigma * sigma));
    };
    if (dim == 2)
        return {{"disk",
                 [](const float* p) {
                     return (p[0] - 0.5) * (p[0] - 0.5) + (p[1] - 0.5) * (p[1] - 0.5) < 0.16 ? 1.0 : 0.0;
                 },
                 pi * 0.16},
                {"step", [](const float* p) { return p[0] < 0.3 + 0.4 * p[1] ? 1.0 : 0.0; }, 0.5},
                {"gaussian", gauss, g1 * g1}};
    return {{"ball",
             [](const float* p) {
                 double r2 = 0;
                 for (int c = 0; c < 3; ++c) r2 += (p[c] - 0.5) * (p[c] - 0.5);
                 return r2 < 0.16 ? 1.0 : 0.0;
             },
             4.0 / 3.0 * pi * 0.064},
            {"gaussian", gauss, g1 * g1 * g1}};
}

void check(stipple_status s, const char* what) {
    if (s != STIPPLE_OK) {
        std::cerr << what << ": " << stipple_last_error_message() << "\n";
        std::exit(1);
    }
}

void check(const stipple::Status& s, const char* what) {
    if (!s.ok()) {
        std::cerr << what << ": " << s.message() << "\n";
        std::exit(1);
    }
}

// A one-dimension layout (arity dim, one value per sample) through stipple.hpp; failures end the tool.
struct LayoutSampler {
    stipple::Sampler sampler;
    uint32_t floats = 0;
    LayoutSampler(const char* pattern, uint32_t n, int dim, uint64_t seed, uint32_t flags = 0)
        : floats(n * uint32_t(dim)) {
        check(stipple::Sampler::create(sampler, pattern, n, seed, {{uint32_t(dim), 1, ""}}, flags), pattern);
    }
    void fill(uint32_t x, uint32_t y, std::vector<float>& out) const {
        out.resize(floats);
        check(sampler.fillPixel(stipple::Pixel{int32_t(x), int32_t(y)}, 0, out.data(), out.size()), "fill_pixel");
    }
};

double estimate(const Integrand& g, const std::vector<float>& points, int dim) {
    const size_t n = points.size() / dim;
    double sum = 0;
    for (size_t i = 0; i < n; ++i) sum += g.f(&points[i * dim]);
    return sum / double(n);
}

double threadSeconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / double(v.size());
}

// Least-squares slope of log MSE against log N.
double fitSlope(const std::vector<double>& ns, const std::vector<double>& mses) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double m = double(ns.size());
    for (size_t i = 0; i < ns.size(); ++i) {
        const double x = std::log(ns[i]), y = std::log(mses[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

struct SlopeEstimate {
    double slope, low, high;
};

// Slope of the MSE curve with a 95% percentile-bootstrap interval over the sets at each N.
SlopeEstimate slopeWithInterval(const std::vector<double>& ns, const std::vector<std::vector<double>>& sq,
                                uint64_t seed) {
    std::vector<double> mses;
    for (const auto& v : sq) mses.push_back(mean(v));
    const double slope = fitSlope(ns, mses);
    constexpr int kBoot = 400;
    std::vector<double> boots;
    for (int b = 0; b < kBoot; ++b) {
        std::vector<double> m;
        for (size_t i = 0; i < sq.size(); ++i) {
            double s = 0;
            for (size_t j = 0; j < sq[i].size(); ++j)
                s += sq[i][stipple::detail::hashAt(seed, (uint64_t(b) << 40) ^ (uint64_t(i) << 24) ^ j) % sq[i].size()];
            m.push_back(s / double(sq[i].size()));
        }
        boots.push_back(fitSlope(ns, m));
    }
    std::sort(boots.begin(), boots.end());
    return {slope, boots[size_t(0.025 * kBoot)], boots[size_t(0.975 * kBoot) - 1]};
}

// A ratio with two significant digits at least (ratios far below 1 would print as 0.00).
std::string fmtRatio(double v) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(v >= 0.1 ? 2 : v >= 0.01 ? 3 : v >= 0.001 ? 4 : 5) << v;
    return s.str();
}

// Ratio of two MSEs with a 95% interval (delta method on the log of each mean, the two samples independent).
struct Ratio {
    double ratio, low, high;
};
Ratio mseRatio(const std::vector<double>& a, const std::vector<double>& b) {
    auto logVar = [](const std::vector<double>& v) {
        const double m = mean(v);
        double s = 0;
        for (double x : v) s += (x - m) * (x - m);
        return s / double(v.size() - 1) / double(v.size()) / (m * m);
    };
    const double r = mean(a) / mean(b), se = std::sqrt(logVar(a) + logVar(b));
    return {r, r * std::exp(-1.96 * se), r * std::exp(1.96 * se)};
}

std::string fmt(double v, int precision = 2) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

// In-place radix-2 FFT.
void fft(std::vector<std::complex<double>>& a) {
    const size_t n = a.size();
    for (size_t i = 1, j = 0; i < n; ++i) {
        size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(a[i], a[j]);
    }
    for (size_t len = 2; len <= n; len <<= 1) {
        const double angle = -2 * 3.14159265358979323846 / double(len);
        const std::complex<double> w(std::cos(angle), std::sin(angle));
        for (size_t i = 0; i < n; i += len) {
            std::complex<double> wk(1);
            for (size_t j = 0; j < len / 2; ++j, wk *= w) {
                const auto u = a[i + j], v = a[i + j + len / 2] * wk;
                a[i + j] = u + v;
                a[i + j + len / 2] = u - v;
            }
        }
    }
}

// Periodogram |F(k)|^2 / pixels of a size x size error image (white noise of variance s^2 has mean s^2).
std::vector<double> periodogram(const std::vector<double>& image, size_t size) {
    std::vector<std::complex<double>> rows(size * size);
    for (size_t i = 0; i < image.size(); ++i) rows[i] = image[i];
    std::vector<std::complex<double>> line(size);
    for (size_t y = 0; y < size; ++y) {
        for (size_t x = 0; x < size; ++x) line[x] = rows[y * size + x];
        fft(line);
        for (size_t x = 0; x < size; ++x) rows[y * size + x] = line[x];
    }
    for (size_t x = 0; x < size; ++x) {
        for (size_t y = 0; y < size; ++y) line[y] = rows[y * size + x];
        fft(line);
        for (size_t y = 0; y < size; ++y) rows[y * size + x] = line[y];
    }
    std::vector<double> power(size * size);
    for (size_t i = 0; i < power.size(); ++i) power[i] = std::norm(rows[i]) / double(size * size);
    return power;
}

} // namespace

int main(int argc, char** argv) {
    fs::path outDir = "pattern_table";
    int sets = 500;
    bool quick = false, poissonOnly = false, blueOnly = false;
    int shiftsOption = 0; // toroidal shifts per base set in poisson_spread.md
    std::vector<uint32_t> ratioNs;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "-o" && i + 1 < argc)
            outDir = argv[++i];
        else if (a == "--sets" && i + 1 < argc)
            sets = std::atoi(argv[++i]);
        else if (a == "--quick")
            quick = true;
        else if (a == "--poisson-only")
            poissonOnly = true;
        else if (a == "--blue-only")
            blueOnly = true;
        else if (a == "--shifts" && i + 1 < argc)
            shiftsOption = std::atoi(argv[++i]);
        else if (a == "--ns" && i + 1 < argc) {
            std::istringstream list(argv[++i]);
            for (std::string item; std::getline(list, item, ',');) {
                const long n = std::atol(item.c_str());
                if (n < 1 || n > 65536) {
                    std::cerr << "--ns: '" << item << "' is not a set size in 1..65536\n";
                    return 2;
                }
                ratioNs.push_back(uint32_t(n));
            }
        } else {
            std::cout << "usage: " << argv[0]
                      << " [-o DIR] [--sets R (500)] [--quick] [--poisson-only] [--blue-only] [--ns N,N,...] [--shifts "
                         "S (1000)]\n";
            return a == "-h" || a == "--help" ? 0 : 2;
        }
    }
    if (quick) sets = std::min(sets, 100);
    fs::create_directories(outDir);
    const std::vector<uint32_t> slopeNs = {16, 64, 256, 1024, 4096};

    // ---- the table: rho, slopes, cost ----------------------------------------------------------------------
    const auto g2 = integrands(2);
    if (!poissonOnly && !blueOnly) {
        std::ofstream table(outDir / "table.md");
        table << "| pattern | rho (2D, N = 1024, mean) | disk slope [95%] | step slope [95%] | Gaussian slope [95%] | "
                 "Gaussian slope N = 256..4096 [95%] | cost per value (ns, 2D N = 4096) "
                 "|\n|---|---|---|---|---|---|---|\n";
        for (const std::string& name : allPatterns()) {
            const char* pattern = name.c_str();
            std::vector<std::vector<std::vector<double>>> sq(g2.size(),
                                                             std::vector<std::vector<double>>(slopeNs.size()));
            std::vector<float> points;
            double rhoSum = 0;
            int rhoCount = 0;
            for (size_t ni = 0; ni < slopeNs.size(); ++ni) {
                const uint32_t n = slopeNs[ni];
                const int r = std::string(pattern) == "poisson-seed" && n >= 1024 ? std::max(sets / 5, 50) : sets;
                LayoutSampler s(pattern, n, 2, 0x7ab1e000 + n);
                for (int set = 0; set < r; ++set) {
                    s.fill(uint32_t(set), 0, points);
                    for (size_t gi = 0; gi < g2.size(); ++gi) {
                        const double e = estimate(g2[gi], points, 2) - g2[gi].exact;
                        sq[gi][ni].push_back(e * e);
                    }
                    if (n == 1024 && set < 50) {
                        rhoSum += stipple::detail::pointsets::relativeRadius(2, points.data(), n);
                        ++rhoCount;
                    }
                }
            }
            std::vector<double> ns(slopeNs.begin(), slopeNs.end());
            table << "| " << pattern << " | " << fmt(rhoSum / rhoCount, 3);
            for (size_t gi = 0; gi < g2.size(); ++gi) {
                const SlopeEstimate e = slopeWithInterval(ns, sq[gi], 11 + gi);
                table << " | " << fmt(e.slope) << " [" << fmt(e.low) << ", " << fmt(e.high) << "]";
            }
            {
                std::vector<double> hi(ns.begin() + 2, ns.end());
                std::vector<std::vector<double>> hiSq(sq[2].begin() + 2, sq[2].end());
                const SlopeEstimate e = slopeWithInterval(hi, hiSq, 99);
                table << " | " << fmt(e.slope) << " [" << fmt(e.low) << ", " << fmt(e.high) << "]";
            }
            // Cost: thread CPU time of fill_pixel per float, 2D N = 4096, warm (poisson's cache family generated).
            LayoutSampler s(pattern, 4096, 2, 0xc057);
            const int calls = std::string(pattern) == "poisson-seed" ? 20 : 400;
            for (int i = 0; i < 40; ++i) s.fill(uint32_t(i), 1, points);
            const double t0 = threadSeconds();
            for (int i = 0; i < calls; ++i) s.fill(uint32_t(i), 2, points);
            const double ns_ = (threadSeconds() - t0) / (double(calls) * s.floats) * 1e9;
            table << " | " << fmt(ns_, 1) << " |\n";
            std::cerr << pattern << " done\n";
        }
        table.close();
    }

    // ---- blue noise: spectrum of the per-pixel error of a fixed integrand ------------------------------------------
    if (!poissonOnly) {
        constexpr size_t kSize = 128;
        const int images = quick ? 6 : 24;
        // The spectrum is measured on the Gaussian; the MSE ratios also on integrands a toroidal shift makes worse:
        // the step (an edge), a ramp and the Gaussian off centre (smooth, not periodic: the shift adds a seam).
        const double sigma = 0.15, root2 = std::sqrt(2.0), pi = 3.14159265358979323846;
        const double cx = 0.3, cy = 0.6;
        auto mass = [&](double c) {
            return sigma * std::sqrt(2 * pi) / 2 *
                   (std::erf((1 - c) / (sigma * root2)) + std::erf(c / (sigma * root2)));
        };
        const std::vector<Integrand> gs = {g2[2],
                                           g2[1],
                                           {"ramp", [](const float* p) { return double(p[0]) + double(p[1]); }, 1.0},
                                           {"gaussian off centre",
                                            [=](const float* p) {
                                                const double dx = p[0] - cx, dy = p[1] - cy;
                                                return std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma));
                                            },
                                            mass(cx) * mass(cy)}};
        std::ofstream md(outDir / "blue_noise.md");
        std::ofstream csv(outDir / "spectrum_blue.csv");
        csv << "pattern,flag,N,radius,power_over_mse\n";
        md << "| pattern | N | flag | per-pixel MSE | MSE ratio flag/plain [95%] | low-quarter energy vs white noise "
              "(white / measured) | MSE ratio step [95%] | MSE ratio ramp x + y [95%] | MSE ratio Gaussian at (0.3, "
              "0.6) [95%] |\n|---|---|---|---|---|---|---|---|---|\n";
        const uint32_t blueNs[] = {16, 256};
        const uint32_t kReplicateTiles = quick ? 16 : 32; // squared, times the images: independent pixels per row
        // The patterns that take the flag (the others refuse it at creation; shim_blue_noise_gain measures why).
        for (const char* pattern : {"stratified"})
            for (uint32_t n : blueNs) {
                std::vector<std::vector<double>> plainSq;
                for (uint32_t flag : {0u, 1u}) {
                    // Several images with their own seeds, for the spectrum. The MSE ratios come from other pixels
                    // of the same samplers, one per 64 x 64 tile away from the image: a tile's pixels share its
                    // lattice map and base set, so pixels of one image are not independent replicates (their
                    // per-image means scatter with a heavy tail), while pixels of different tiles are.
                    std::vector<std::vector<double>> imageMse(gs.size()), pixelSq(gs.size());
                    std::vector<double> power(kSize * kSize, 0.0);
                    for (int image = 0; image < images; ++image) {
                        LayoutSampler s(pattern, n, 2, 0xb1e0 + n + 1000 * uint64_t(image), flag);
                        std::vector<double> error(kSize * kSize), sum(gs.size(), 0.0);
                        std::vector<float> points;
                        for (size_t y = 0; y < kSize; ++y)
                            for (size_t x = 0; x < kSize; ++x) {
                                s.fill(uint32_t(x), uint32_t(y), points);
                                for (size_t gi = 0; gi < gs.size(); ++gi) {
                                    const double e = estimate(gs[gi], points, 2) - gs[gi].exact;
                                    if (gi == 0) error[y * kSize + x] = e;
                                    sum[gi] += e * e;
                                }
                            }
                        for (size_t gi = 0; gi < gs.size(); ++gi)
                            imageMse[gi].push_back(sum[gi] / double(kSize * kSize));
                        for (uint32_t ty = 0; ty < kReplicateTiles; ++ty)
                            for (uint32_t tx = 0; tx < kReplicateTiles; ++tx) {
                                s.fill(64 * (tx + 2) + (37 * tx + 11 * ty) % 64, 64 * (ty + 2) + (23 * tx + 41 * ty) % 64,
                                       points);
                                for (size_t gi = 0; gi < gs.size(); ++gi) {
                                    const double e = estimate(gs[gi], points, 2) - gs[gi].exact;
                                    pixelSq[gi].push_back(e * e);
                                }
                            }
                        const auto p = periodogram(error, kSize);
                        for (size_t i = 0; i < p.size(); ++i) power[i] += p[i] / images;
                    }
                    const double mse = mean(imageMse[0]);
                    // Lowest quarter of frequencies: |f| < Nyquist / 4 = 1/8 cycle per pixel, DC excluded.
                    double band = 0;
                    int bins = 0;
                    std::vector<double> radial(kSize / 2 + 1, 0.0);
                    std::vector<int> radialCount(kSize / 2 + 1, 0);
                    for (size_t ky = 0; ky < kSize; ++ky)
                        for (size_t kx = 0; kx < kSize; ++kx) {
                            const double fx = double(kx <= kSize / 2 ? kx : kSize - kx) / kSize;
                            const double fy = double(ky <= kSize / 2 ? ky : kSize - ky) / kSize;
                            const double f = std::sqrt(fx * fx + fy * fy);
                            if (kx == 0 && ky == 0) continue;
                            if (f < 0.125) band += power[ky * kSize + kx], ++bins;
                            const size_t ring = size_t(std::lround(f * kSize));
                            if (ring < radial.size()) radial[ring] += power[ky * kSize + kx], ++radialCount[ring];
                        }
                    const double ratio = (bins * mse) / band;
                    for (size_t r = 1; r < radial.size(); ++r)
                        if (radialCount[r])
                            csv << pattern << "," << flag << "," << n << "," << double(r) / kSize << ","
                                << radial[r] / radialCount[r] / mse << "\n";
                    const auto ratioCell = [&](size_t gi) {
                        if (!flag) return std::string("-");
                        const Ratio r = mseRatio(pixelSq[gi], plainSq[gi]);
                        return fmt(r.ratio, 3) + " [" + fmt(r.low, 3) + ", " + fmt(r.high, 3) + "]";
                    };
                    md << "| " << pattern << " | " << n << " | " << (flag ? "blue noise" : "-") << " | "
                       << std::scientific << std::setprecision(3) << mse << std::fixed << " | " << ratioCell(0) << " | "
                       << fmt(ratio, 1);
                    for (size_t gi = 1; gi < gs.size(); ++gi) md << " | " << ratioCell(gi);
                    md << " |\n";
                    if (!flag) plainSq = pixelSq;
                }
                std::cerr << pattern << " N=" << n << " blue noise done\n";
            }
        md.close();
        std::ofstream gp(outDir / "blue_noise.gp");
        gp << "set datafile separator ','\nset logscale y\nset xlabel 'frequency (cycles per pixel)'\n"
              "set ylabel 'radial power / per-pixel MSE (white noise = 1)'\nset key top left\n"
              "set title 'Per-pixel error spectrum, Gaussian integrand, 128x128 pixels'\n"
              "set arrow from 0.125, graph 0 to 0.125, graph 1 nohead dt 2\n"
              "sel(p,f,n)=(strcol(1) eq p && $2 == f && $3 == n) ? $5 : 1/0\n"
              "plot for [p in 'stratified'] for [f in '0 1'] '"
           << (outDir / "spectrum_blue.csv").string()
           << "' using 4:(sel(p, f + 0, 16)) with lines title sprintf('%s N=16 %s', p, f eq '1' ? 'blue noise' : "
              "'plain')\n";
        gp.close();
        for (const char* term : {"pngcairo size 900,600", "svg size 900,600"}) {
            const std::string ext = std::string(term).substr(0, 3) == "png" ? "png" : "svg";
            const std::string cmd = "gnuplot -e \"set terminal " + std::string(term) + "; set output '" +
                                    (outDir / ("blue_noise." + ext)).string() + "'\" '" +
                                    (outDir / "blue_noise.gp").string() + "' 2>&1";
            if (std::system(cmd.c_str()) != 0) std::cerr << "gnuplot failed: " << cmd << "\n";
        }
        std::cerr << "blue noise done\n";
    }
    if (blueOnly) return 0;

    // ---- poisson vs stratified, 2D and 3D, every N ----------------------------------------------------------
    {
        std::ofstream md(outDir / "poisson_vs_stratified.md");
        md << "| dim | N | integrand | MSE poisson / stratified [95%] |\n|---|---|---|---|\n";
        const std::vector<uint32_t> ns = !ratioNs.empty() ? ratioNs
                                         : quick          ? std::vector<uint32_t>{16, 256, 4096}
                                                 : std::vector<uint32_t>{16, 32, 64, 128, 256, 512, 1024, 2048, 4096};
        for (int dim : {2, 3}) {
            const auto gs = integrands(dim);
            for (uint32_t n : ns) {
                std::vector<std::vector<double>> sqP(gs.size()), sqS(gs.size());
                std::vector<float> points;
                LayoutSampler p("poisson", n, dim, 0x9e55 + n), s("stratified", n, dim, 0x57a7 + n);
                for (int set = 0; set < sets; ++set) {
                    p.fill(uint32_t(set), 7, points);
                    for (size_t gi = 0; gi < gs.size(); ++gi) {
                        const double e = estimate(gs[gi], points, dim) - gs[gi].exact;
                        sqP[gi].push_back(e * e);
                    }
                    s.fill(uint32_t(set), 7, points);
                    for (size_t gi = 0; gi < gs.size(); ++gi) {
                        const double e = estimate(gs[gi], points, dim) - gs[gi].exact;
                        sqS[gi].push_back(e * e);
                    }
                }
                for (size_t gi = 0; gi < gs.size(); ++gi) {
                    const Ratio r = mseRatio(sqP[gi], sqS[gi]);
                    md << "| " << dim << " | " << n << " | " << gs[gi].name << " | " << fmtRatio(r.ratio) << " ["
                       << fmtRatio(r.low) << ", " << fmtRatio(r.high) << "] |\n";
                }
            }
        }
        // Spread between the cached base sets: each set under `shifts` uniform toroidal shifts. The family is
        // a fresh one (same content as the cache's), so generating it measures the one-time cost per set.
        std::ofstream spread(outDir / "poisson_spread.md");
        spread << "| dim | N | integrand | base sets | MSE max / min over base sets | rho min / mean over base sets "
                  "| generation (ms per set, one thread) |\n|---|---|---|---|---|---|---|\n";
        const int shifts = shiftsOption > 0 ? shiftsOption : quick ? 100 : 1000;
        for (int dim : {2, 3}) {
            const auto gs = integrands(dim);
            for (uint32_t n : ns) {
                const stipple::detail::PoissonFamily family(
                    uint32_t(dim), n, stipple::detail::PoissonCache::setCountFor(uint32_t(dim), n));
                const double t0 = threadSeconds();
                for (uint32_t j = 0; j < family.setCount(); ++j) family.set(j);
                const double msPerSet = (threadSeconds() - t0) / family.setCount() * 1e3;
                double rhoMin = 1e9, rhoSum = 0;
                std::vector<std::vector<double>> perSet(gs.size());
                std::vector<float> shifted(size_t(n) * dim);
                for (uint32_t j = 0; j < family.setCount(); ++j) {
                    const float* base = family.set(j);
                    const double rho = stipple::detail::pointsets::relativeRadius(dim, base, n);
                    rhoMin = std::min(rhoMin, rho), rhoSum += rho;
                    std::vector<double> acc(gs.size(), 0.0);
                    for (int t = 0; t < shifts; ++t) {
                        float shift[3];
                        for (int c = 0; c < dim; ++c)
                            shift[c] =
                                stipple::detail::unitFloat(stipple::detail::hashAt(0x5b1f7 + j, uint64_t(t) * 3 + c));
                        for (size_t i = 0; i < size_t(n) * dim; ++i) {
                            float v = base[i] + shift[i % dim];
                            shifted[i] = v - float(v >= 1.0f);
                        }
                        for (size_t gi = 0; gi < gs.size(); ++gi) {
                            const double e = estimate(gs[gi], shifted, dim) - gs[gi].exact;
                            acc[gi] += e * e;
                        }
                    }
                    for (size_t gi = 0; gi < gs.size(); ++gi) perSet[gi].push_back(acc[gi] / shifts);
                }
                for (size_t gi = 0; gi < gs.size(); ++gi) {
                    const auto [lo, hi] = std::minmax_element(perSet[gi].begin(), perSet[gi].end());
                    spread << "| " << dim << " | " << n << " | " << gs[gi].name << " | " << family.setCount() << " | "
                           << fmt(*hi / *lo) << " | " << fmt(rhoMin, 3) << " / " << fmt(rhoSum / family.setCount(), 3)
                           << " | " << fmt(msPerSet, 2) << " |\n";
                }
            }
        }
    }
    std::cout << "wrote " << outDir
              << "/{table.md, blue_noise.md, blue_noise.png, poisson_vs_stratified.md, "
                 "poisson_spread.md}\n";
    return 0;
}
