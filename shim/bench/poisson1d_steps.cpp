// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson1d_steps.cpp — the Weyl steps of the 1D "poisson" families below 64 points (kSmallFamilies1D in
// src/pointsets/cell_set_1d.cpp), found by a minimax over probe integrands.
//
//   shim_poisson1d_steps [--first N0 (8)] [--last N1 (63)]
//
// A 1D set of n points has one point in each cell [c/n, (c+1)/n) at the offset frac(c q / n) (plus half a sub-cell);
// the serving shifts it by whole cells, reflects it and rotates every offset by one uniform tau. Its MSE is then
// exact to compute: with g_p the centred integrand inside served cell p (over n), the error variance is
// sum over lags L of W_L(L q mod n), W_L(j) = sum_p of the cross-correlation of g_p and g_{p+L} at the shift j / n,
// averaged over reflection; jittered sampling is the L = 0 term. A family of 32 sets may mix steps: its MSE is the
// count-weighted mean. The probes are classes of random instances (fixed seed, not the battery's instances): the
// six Genz families in 1D, each in three bands of difficulty (x0.5 .. 2) with uniform centres (the kink and the peaks
// of a cell's width are where a common rotation costs), ramps, exp(-x), Gaussians of width 0.2 at random centres,
// steps at random positions. For each n the steps (q = 0 or q / n in [1/2, 1): every served pair at least half a
// cell apart) and their weights minimise max over classes of (ratio to jittered) / target, target 1 for kinks and
// edges and t for the smooth classes, t the smallest of 0.5, 0.6, .., 1 whose optimum keeps every class within 5% of
// the best worst ratio (or of 1), i.e. smooth gains bought with at most 5% on the worst class (every mixture of three
// steps with counts of 32, then single sets moved between steps, a fourth allowed, while the worst falls). Prints the
// table and each n's ratios (about a minute on one core).
//
// stipple-link: shared
#include "battery_integrands.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

namespace {

using stipple::battery::detail::kPi;
using Rng = stipple::battery::detail::ParameterRng; // SplitMix64, as the battery's parameters

struct ProbeClass {
    std::string name;
    bool smooth;
    std::vector<std::function<double(double)>> instances;
};

std::vector<ProbeClass> probeClasses() {
    constexpr int kInstances = 8;
    Rng rng{0x9e0b35ull};
    std::vector<ProbeClass> out;
    const char* names[6] = {"oscillatory", "product peak", "corner peak", "gaussian", "continuous", "discontinuous"};
    const double difficulty[6] = {9.0, 7.25, 1.85, 7.03, 20.4, 4.3};
    // Each family in three bands of difficulty (x0.5-0.8, x0.8-1.25, x1.25-2): a class's mean over a wide band could
    // hide one scale of the kink or the peak that loses.
    const double bands[4] = {0.5, 0.8, 1.25, 2.0};
    for (int family = 0; family < 6; ++family)
        for (int band = 0; band < 3; ++band) {
            ProbeClass c{std::string(names[family]) + " x" + std::to_string(bands[band]).substr(0, 4), family < 4, {}};
            for (int k = 0; k < kInstances; ++k) {
                const double u = rng.next();
                const double a = difficulty[family] * bands[band] * std::pow(bands[band + 1] / bands[band], rng.next());
                switch (family) {
                case 0: c.instances.push_back([a, u](double x) { return std::cos(2 * kPi * u + a * x); }); break;
                case 1:
                    c.instances.push_back([a, u](double x) { return 1 / (1 / (a * a) + (x - u) * (x - u)); });
                    break;
                case 2: c.instances.push_back([a](double x) { return std::pow(1 + a * x, -2.0); }); break;
                case 3: c.instances.push_back([a, u](double x) { return std::exp(-a * a * (x - u) * (x - u)); }); break;
                case 4: c.instances.push_back([a, u](double x) { return std::exp(-a * std::abs(x - u)); }); break;
                default: c.instances.push_back([a, u](double x) { return x > u ? 0.0 : std::exp(a * x); }); break;
                }
            }
            out.push_back(c);
        }
    out.push_back({"ramp", true, {[](double x) { return x; }}});
    out.push_back({"exp(-x)", true, {[](double x) { return std::exp(-x); }}});
    ProbeClass gauss{"gaussian 0.2", true, {}}, step{"step", false, {}};
    for (int k = 0; k < kInstances; ++k) {
        const double c = rng.next(), s = rng.next();
        gauss.instances.push_back([c](double x) { return std::exp(-(x - c) * (x - c) / 0.08); });
        step.instances.push_back([s](double x) { return x < s ? 1.0 : 0.0; });
    }
    out.push_back(gauss);
    out.push_back(step);
    return out;
}

// W[L][j] over a class, normalised by the class's jittered MSE (so that ratio(q) = sum_L W[L][L q mod n]).
std::vector<std::vector<double>> classWeights(const ProbeClass& c, int n) {
    const int U = n * ((64 + n - 1) / n); // quadrature points per cell, a multiple of n
    std::vector<std::vector<double>> W(n, std::vector<double>(n, 0.0));
    std::vector<std::complex<double>> F(size_t(n) * U), twiddle(U);
    for (int h = 0; h < U; ++h) twiddle[h] = std::polar(1.0, -2 * kPi * h / U);
    std::vector<double> g(U);
    for (const auto& f : c.instances)
        for (int reflect = 0; reflect < 2; ++reflect) {
            double m1 = 0, m2 = 0; // the instance's variance over [0,1), for normalising like the battery
            for (int p = 0; p < n; ++p) {
                double mean = 0;
                for (int i = 0; i < U; ++i) {
                    const double x = (p + (i + 0.5) / U) / n;
                    g[i] = f(reflect ? 1 - x : x);
                    mean += g[i] / U, m1 += g[i], m2 += g[i] * g[i];
                }
                for (int i = 0; i < U; ++i) g[i] = (g[i] - mean) / n;
                for (int h = 0; h < U; ++h) {
                    std::complex<double> s = 0;
                    for (int i = 0; i < U; ++i) s += g[i] * twiddle[(size_t(h) * i) % U];
                    F[size_t(p) * U + h] = s;
                }
            }
            m1 /= double(n) * U, m2 /= double(n) * U;
            const double variance = std::max(m2 - m1 * m1, 1e-300);
            for (int L = 0; L < n; ++L) {
                std::vector<std::complex<double>> S(U, 0.0);
                for (int p = 0; p < n; ++p)
                    for (int h = 0; h < U; ++h)
                        S[h] += std::conj(F[size_t(p) * U + h]) * F[size_t((p + L) % n) * U + h];
                for (int j = 0; j < n; ++j) {
                    std::complex<double> s = 0;
                    for (int h = 0; h < U; ++h) s += S[h] * std::conj(twiddle[(size_t(h) * j * (U / n)) % U]);
                    W[L][j] += s.real() / (double(U) * U) / variance;
                }
            }
        }
    // W[0][0] summed every instance's jittered MSE (over its variance): the class's jittered MSE.
    const double total = W[0][0];
    for (auto& row : W)
        for (double& v : row) v /= total;
    return W;
}

double ratio(const std::vector<std::vector<double>>& W, int n, int q) {
    double s = 0;
    for (int L = 0; L < n; ++L) s += W[L][(int64_t(L) * q) % n];
    return s;
}

constexpr size_t kMaxSteps = 4; // steps mixed in one family

struct Choice {
    std::vector<std::pair<int, int>> steps; // (q, count of 32)
    std::vector<double> ratios;             // per class
    double smoothTarget;
};

Choice choose(int n, const std::vector<ProbeClass>& classes, const std::vector<std::vector<std::vector<double>>>& W) {
    std::vector<int> qs{0};
    for (int q = (n + 1) / 2; q < n; ++q) qs.push_back(q);
    const size_t C = classes.size(), J = qs.size();
    std::vector<std::vector<double>> r(C, std::vector<double>(J));
    for (size_t c = 0; c < C; ++c)
        for (size_t j = 0; j < J; ++j) r[c][j] = ratio(W[c], n, qs[j]);
    // Every mixture of at most three steps with counts of 32 (exhaustive: at most ~33^3 / 6 triples x 528 splits):
    // the least max over classes of ratio / target.
    auto solve = [&](double target) {
        std::vector<std::vector<double>> scaled(J, std::vector<double>(C));
        for (size_t j = 0; j < J; ++j)
            for (size_t c = 0; c < C; ++c) scaled[j][c] = r[c][j] / (classes[c].smooth ? target : 1.0);
        double best = 1e300;
        size_t bj[3] = {0, 0, 0};
        int bk[3] = {32, 0, 0};
        std::vector<double> mix(C);
        for (size_t a = 0; a < J; ++a)
            for (size_t b = a; b < J; ++b)
                for (size_t c3 = b; c3 < J; ++c3)
                    for (int ka = 1; ka <= 32; ++ka)
                        for (int kb = (b == a ? 0 : 1); ka + kb <= 32; ++kb) {
                            const int kc = 32 - ka - kb;
                            if ((c3 == b) != (kc == 0)) continue;
                            if (b == a && kb != 0) break;
                            double m = 0;
                            for (size_t c = 0; c < C && m < best; ++c)
                                m = std::max(m, (ka * scaled[a][c] + kb * scaled[b][c] + kc * scaled[c3][c]) / 32.0);
                            if (m < best)
                                best = m, bj[0] = a, bj[1] = b, bj[2] = c3, bk[0] = ka, bk[1] = kb, bk[2] = kc;
                        }
        // Then single sets moved from one step to another (a fourth step allowed) while the worst ratio falls.
        std::vector<int> count(J, 0);
        for (int k = 0; k < 3; ++k) count[bj[k]] += bk[k];
        auto value = [&](const std::vector<int>& k) {
            double m = 0, mean = 0;
            for (size_t c = 0; c < C; ++c) {
                double v = 0;
                for (size_t j = 0; j < J; ++j) v += k[j] * scaled[j][c];
                m = std::max(m, v / 32.0), mean += v / 32.0 / C;
            }
            return m + 1e-3 * mean;
        };
        double current = value(count);
        for (bool improved = true; improved;) {
            improved = false;
            for (size_t from = 0; from < J; ++from)
                for (size_t to = 0; to < J && count[from] > 0; ++to) {
                    if (to == from) continue;
                    const int used = int(std::count_if(count.begin(), count.end(), [](int k) { return k > 0; }));
                    if (count[to] == 0 && count[from] > 1 && used >= int(kMaxSteps)) continue;
                    --count[from], ++count[to];
                    const double v = value(count);
                    if (v < current - 1e-12)
                        current = v, improved = true;
                    else
                        ++count[from], --count[to];
                }
        }
        Choice out{{}, std::vector<double>(C, 0.0), target};
        for (size_t j = 0; j < J; ++j)
            if (count[j] > 0) {
                out.steps.push_back({qs[j], count[j]});
                for (size_t c = 0; c < C; ++c) out.ratios[c] += r[c][j] * count[j] / 32.0;
            }
        std::sort(out.steps.begin(), out.steps.end(), [](const auto& x, const auto& y) { return x.second > y.second; });
        return out;
    };
    auto worst = [](const Choice& ch) { return *std::max_element(ch.ratios.begin(), ch.ratios.end()); };
    const Choice flat = solve(1.0);
    const double bound = std::max(1.0, worst(flat)) * 1.05;
    for (double target = 0.5; target < 0.99; target += 0.1) {
        const Choice ch = solve(target);
        if (worst(ch) <= bound) return ch;
    }
    return flat;
}

} // namespace

int main(int argc, char** argv) {
    int first = 8, last = 63;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--first")
            first = std::atoi(argv[i + 1]);
        else if (a == "--last")
            last = std::atoi(argv[i + 1]);
        else {
            std::fprintf(stderr, "shim_poisson1d_steps: unknown argument \"%s\"\n", a.c_str());
            return 2;
        }
    }
    if (first < 2 || last > 63 || first > last) {
        std::fprintf(stderr, "shim_poisson1d_steps: --first/--last must satisfy 2 <= first <= last <= 63\n");
        return 2;
    }
    const std::vector<ProbeClass> classes = probeClasses();
    std::printf("// n: {q, count of 32} ... | probe ratios to jittered:");
    for (const auto& c : classes) std::printf(" %s;", c.name.c_str());
    std::printf("\n");
    for (int n = first; n <= last; ++n) {
        std::vector<std::vector<std::vector<double>>> W;
        for (const auto& c : classes) W.push_back(classWeights(c, n));
        const Choice ch = choose(n, classes, W);
        std::printf("    {%d, {", n);
        for (size_t k = 0; k < kMaxSteps; ++k)
            std::printf("{%d, %d}%s", k < ch.steps.size() ? ch.steps[k].first : 0,
                        k < ch.steps.size() ? ch.steps[k].second : 0, k + 1 < kMaxSteps ? ", " : "");
        std::printf("}}, // smooth target %.1f |", ch.smoothTarget);
        for (double v : ch.ratios) std::printf(" %.2f", v);
        std::printf("\n");
        std::fflush(stdout);
    }
    return 0;
}
