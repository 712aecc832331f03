// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "perceptual/thurstone.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace stipple::validation {

namespace {

const double kSigma = 1.0 / 0.6744897501960817; // Φ⁻¹(0.75): 1 JOD is 75% preference

double logPhi(double x) { return std::log(0.5 * std::erfc(-x / std::sqrt(2.0))); }
// φ(x) / Φ(x), stable for very negative x (the inverse Mills ratio).
double millsRatio(double x) {
    if (x < -30) return -x; // asymptote
    const double phi = std::exp(-0.5 * x * x) / std::sqrt(2 * M_PI);
    return phi / (0.5 * std::erfc(-x / std::sqrt(2.0)));
}

struct Model {
    const std::vector<std::vector<double>>& w;
    size_t n;
    // Log posterior (up to a constant) of the free scores q[1..n-1], q[0] = 0.
    double value(const std::vector<double>& q) const {
        double f = 0, m = 0;
        for (size_t i = 0; i < n; ++i) m += q[i] / double(n);
        for (size_t i = 0; i < n; ++i) {
            f -= (q[i] - m) * (q[i] - m) / (2 * kPriorJod * kPriorJod);
            for (size_t j = 0; j < n; ++j)
                if (i != j && w[i][j] > 0) f += w[i][j] * logPhi((q[i] - q[j]) / kSigma);
        }
        return f;
    }
    // Gradient and Hessian over all n scores (row/column 0 dropped by the caller).
    void derivatives(const std::vector<double>& q, std::vector<double>& g, std::vector<std::vector<double>>& h) const {
        g.assign(n, 0);
        h.assign(n, std::vector<double>(n, 0));
        double m = 0;
        for (size_t i = 0; i < n; ++i) m += q[i] / double(n);
        const double p = 1 / (kPriorJod * kPriorJod);
        for (size_t k = 0; k < n; ++k) {
            g[k] -= p * (q[k] - m); // the centring's terms sum to zero
            for (size_t l = 0; l < n; ++l) h[k][l] -= p * ((k == l) - 1.0 / double(n));
        }
        for (size_t i = 0; i < n; ++i)
            for (size_t j = 0; j < n; ++j) {
                if (i == j || w[i][j] <= 0) continue;
                const double x = (q[i] - q[j]) / kSigma, r = millsRatio(x);
                const double d1 = w[i][j] * r / kSigma, d2 = -w[i][j] * r * (x + r) / (kSigma * kSigma);
                g[i] += d1;
                g[j] -= d1;
                h[i][i] += d2;
                h[j][j] += d2;
                h[i][j] -= d2;
                h[j][i] -= d2;
            }
    }
};

// Solves a·x = b (a negative definite, small) by Gaussian elimination with partial pivoting.
std::vector<double> solve(std::vector<std::vector<double>> a, std::vector<double> b) {
    const size_t n = b.size();
    for (size_t c = 0; c < n; ++c) {
        size_t p = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
        std::swap(a[c], a[p]);
        std::swap(b[c], b[p]);
        for (size_t r = c + 1; r < n; ++r) {
            const double f = a[r][c] / a[c][c];
            for (size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
            b[r] -= f * b[c];
        }
    }
    std::vector<double> x(n);
    for (size_t c = n; c-- > 0;) {
        double s = b[c];
        for (size_t k = c + 1; k < n; ++k) s -= a[c][k] * x[k];
        x[c] = s / a[c][c];
    }
    return x;
}

} // namespace

std::vector<double> thurstoneScores(const std::vector<std::vector<double>>& wins) {
    const size_t n = wins.size();
    std::vector<double> q(n, 0.0);
    if (n < 2) return q;
    Model model{wins, n};
    double f = model.value(q);
    for (int iteration = 0; iteration < 100; ++iteration) {
        std::vector<double> g;
        std::vector<std::vector<double>> h;
        model.derivatives(q, g, h);
        // Free scores 1..n-1.
        std::vector<std::vector<double>> a(n - 1, std::vector<double>(n - 1));
        std::vector<double> b(n - 1);
        for (size_t i = 1; i < n; ++i) {
            b[i - 1] = -g[i];
            for (size_t j = 1; j < n; ++j) a[i - 1][j - 1] = h[i][j];
        }
        const std::vector<double> step = solve(a, b);
        double t = 1, gain = 0;
        std::vector<double> next = q;
        for (int halving = 0; halving < 40; ++halving, t /= 2) {
            for (size_t i = 1; i < n; ++i) next[i] = q[i] + t * step[i - 1];
            const double fn = model.value(next);
            if (fn >= f) {
                gain = fn - f;
                f = fn;
                break;
            }
        }
        double moved = 0;
        for (size_t i = 1; i < n; ++i) moved = std::max(moved, std::fabs(next[i] - q[i]));
        q = next;
        if (moved < 1e-10 || gain < 1e-14) break;
    }
    return q;
}

} // namespace stipple::validation
