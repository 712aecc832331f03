// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// low_frequency.cpp — see low_frequency.h.
//
// exp(2 pi i k.x) for every mode comes from per-axis powers of exp(2 pi i x) (one sincos per point and axis),
// in double: the modes' sums over N points must be accurate to far below their own size ~sqrt(N).
#include "low_frequency.h"

#include <array>
#include <cmath>
#include <complex>

#include "torus.h"

namespace stipple::detail::pointsets {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 6.283185307179586476925286766559;

// Modes 0 < |k| <= K, one of each pair +-k (the first nonzero component positive).
template <int D>
std::vector<std::array<int, D>> halfSpaceModes(int K) {
    std::vector<std::array<int, D>> modes;
    std::array<int, D> k{};
    const int side = 2 * K + 1;
    int total = 1;
    for (int c = 0; c < D; ++c) total *= side;
    for (int code = 0; code < total; ++code) {
        int rest = code, norm2 = 0, first = 0;
        for (int c = 0; c < D; ++c, rest /= side) {
            k[c] = rest % side - K;
            norm2 += k[c] * k[c];
            if (first == 0) first = k[c];
        }
        if (norm2 > 0 && norm2 <= K * K && first > 0) modes.push_back(k);
    }
    return modes;
}

// exp(2 pi i k.x) of one point for every mode, from the powers of exp(2 pi i x_c).
template <int D>
void modeValues(const float* x, int K, const std::vector<std::array<int, D>>& modes, std::vector<Complex>& powers,
                std::vector<Complex>& out) {
    const int side = 2 * K + 1;
    powers.resize(size_t(D) * side);
    for (int c = 0; c < D; ++c) {
        const Complex w = std::polar(1.0, kTwoPi * double(x[c]));
        Complex* p = &powers[size_t(c) * side + K];
        p[0] = 1.0;
        for (int m = 1; m <= K; ++m) {
            p[m] = p[m - 1] * w;
            p[-m] = std::conj(p[m]);
        }
    }
    out.resize(modes.size());
    for (size_t m = 0; m < modes.size(); ++m) {
        Complex v = powers[size_t(K + modes[m][0])];
        for (int c = 1; c < D; ++c) v *= powers[size_t(c * side + K + modes[m][c])];
        out[m] = v;
    }
}

template <int D>
std::vector<Complex> modeSums(const std::vector<float>& pts, uint32_t n, int K,
                              const std::vector<std::array<int, D>>& modes) {
    std::vector<Complex> sums(modes.size()), powers, values;
    for (uint32_t i = 0; i < n; ++i) {
        modeValues<D>(&pts[size_t(i) * D], K, modes, powers, values);
        for (size_t m = 0; m < modes.size(); ++m) sums[m] += std::conj(values[m]); // S(k) = sum exp(-2 pi i k.x)
    }
    return sums;
}

} // namespace

template <int D>
void cancelLowFrequencies(std::vector<float>& pts, uint32_t n, int maxFrequency, int iterations) {
    const auto modes = halfSpaceModes<D>(maxFrequency);
    std::vector<Complex> powers, values, a(modes.size());
    for (int it = 0; it < iterations; ++it) {
        const std::vector<Complex> S = modeSums<D>(pts, n, maxFrequency, modes);
        for (size_t m = 0; m < modes.size(); ++m) {
            int norm2 = 0;
            for (int c = 0; c < D; ++c) norm2 += modes[m][c] * modes[m][c];
            a[m] = S[m] / (Complex(0.0, kTwoPi) * double(norm2) * double(n));
        }
        for (uint32_t i = 0; i < n; ++i) {
            float* x = &pts[size_t(i) * D];
            modeValues<D>(x, maxFrequency, modes, powers, values);
            double u[D] = {};
            for (size_t m = 0; m < modes.size(); ++m) {
                const double s = 2.0 * (a[m] * values[m]).real();
                for (int c = 0; c < D; ++c) u[c] += s * modes[m][c];
            }
            for (int c = 0; c < D; ++c) x[c] = wrapUnit(float(double(x[c]) + u[c]));
        }
    }
}

template <int D>
double lowFrequencyEnergy(const std::vector<float>& pts, uint32_t n, int maxFrequency) {
    const auto modes = halfSpaceModes<D>(maxFrequency);
    double energy = 0.0;
    for (const Complex& s : modeSums<D>(pts, n, maxFrequency, modes)) energy += std::norm(s) / double(n);
    return energy;
}

template void cancelLowFrequencies<2>(std::vector<float>&, uint32_t, int, int);
template void cancelLowFrequencies<3>(std::vector<float>&, uint32_t, int, int);
template double lowFrequencyEnergy<2>(const std::vector<float>&, uint32_t, int);
template double lowFrequencyEnergy<3>(const std::vector<float>&, uint32_t, int);

} // namespace stipple::detail::pointsets
