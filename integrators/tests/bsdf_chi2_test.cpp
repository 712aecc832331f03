// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Chi-square goodness of fit of each material's sample() against its pdf() (pbrt-v4 bsdfs_test, Mitsuba 3's
// chi2 test). Directions are binned on a grid centred on the mirror direction of wo: polar angle psi from it,
// warped as psi = pi t^4 so that narrow lobes (roughness 0.001) fall across many cells, and azimuth phi.
// Expected counts integrate pdf() over each cell (composite Simpson, 8x8 per cell); cells expecting fewer than 5
// samples are pooled. Uniform inputs come from the shim's independent pattern through the loader (no other
// random source in integrators/). alpha = 0.01, Sidak-corrected over every configuration tested here.
#define BOOST_TEST_MODULE bsdf_chi2
#include <boost/test/unit_test.hpp>

#include "materials/material.h"
#include "sampling/pixel_sampler.h"

#include <stipple/testing/statistics.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace stipple::render;

namespace {

constexpr int kThetaBins = 24, kPhiBins = 24, kSub = 8;
constexpr uint32_t kSamplesPerPixel = 1u << 16, kPixels = 4; // 262144 samples per configuration

struct Config {
    std::string label;
    Material m;
    float cosThetaO;
};

Vec3 directionOf(const Frame& f, float psi, float phi) {
    return f.toWorld(Vec3(std::sin(psi) * std::cos(phi), std::sin(psi) * std::sin(phi), std::cos(psi)));
}

// Returns the p-value of the chi-square statistic; also the number of pooled cells used.
double chi2PValue(const Config& c, const ShimLibrary& shim, uint32_t configIndex, int& cellsUsed, double& lost) {
    Vec3 wo(std::sqrt(1 - c.cosThetaO * c.cosThetaO), 0, c.cosThetaO);
    Frame mirror(Vec3(-wo.x, -wo.y, wo.z));
    auto cellOf = [&](const Vec3& w) {
        Vec3 l = mirror.toLocal(w);
        float psi = std::atan2(std::sqrt(l.x * l.x + l.y * l.y), l.z); // precise for tiny angles, unlike acos
        float phi = std::atan2(l.y, l.x);
        if (phi < 0) phi += 2 * kPi;
        int ti = std::min(kThetaBins - 1, int(std::pow(psi / kPi, 0.25f) * kThetaBins));
        int pi = std::min(kPhiBins - 1, int(phi / (2 * kPi) * kPhiBins));
        return ti * kPhiBins + pi;
    };
    // Histogram of samples.
    std::vector<double> observed(kThetaBins * kPhiBins, 0.0);
    SampleLayout layout;
    int dLobe = layout.add("lobe", 1), dDir = layout.add("dir", 2);
    PixelSampler sampler(shim, "independent", kSamplesPerPixel, 1234 + configIndex, layout);
    PixelSamples buf(sampler);
    double total = 0;
    for (uint32_t px = 0; px < kPixels; ++px) {
        sampler.startPixel(px, configIndex, buf);
        for (uint32_t i = 0; i < kSamplesPerPixel; ++i) {
            SampleView sv(buf, i);
            total += 1;
            BsdfSample bs;
            if (!c.m.sample(wo, sv.get1D(dLobe), sv.get2D(dDir), bs)) continue;
            // The reported pdf must equal pdf() for the sampled direction (non-delta materials).
            float p = c.m.pdf(wo, bs.wi);
            if (std::abs(p - bs.pdf) > 1e-3f * std::max(1.0f, p))
                BOOST_ERROR(c.label << ": sample pdf " << bs.pdf << " != pdf() " << p);
            observed[size_t(cellOf(bs.wi))] += 1;
        }
    }
    // Expected counts: integrate pdf over each cell in (t, phi), Jacobian sin(psi) * dpsi/dt = 4 pi t^3.
    std::vector<double> expected(observed.size(), 0.0);
    double integral = 0;
    for (int ti = 0; ti < kThetaBins; ++ti)
        for (int pj = 0; pj < kPhiBins; ++pj) {
            double t0 = double(ti) / kThetaBins, p0 = 2 * M_PI * pj / kPhiBins;
            auto density = [&](double t, double phi) {
                double psi = M_PI * t * t * t * t;
                Vec3 wi = directionOf(mirror, float(psi), float(phi));
                return double(c.m.pdf(wo, wi)) * std::sin(psi) * 4 * M_PI * t * t * t;
            };
            // Composite Simpson on kSub x kSub; where the cell straddles the horizon (some zero, some non-zero
            // values: a discontinuity Simpson cannot integrate), a 96 x 96 midpoint rule instead.
            double sum = 0, dt = 1.0 / kThetaBins / kSub, dp = 2 * M_PI / kPhiBins / kSub;
            bool zero = false, nonZero = false;
            for (int a = 0; a <= kSub; ++a)
                for (int b = 0; b <= kSub; ++b) {
                    double wa = (a == 0 || a == kSub) ? 1 : (a % 2 ? 4 : 2);
                    double wb = (b == 0 || b == kSub) ? 1 : (b % 2 ? 4 : 2);
                    double v = density(t0 + a * dt, p0 + b * dp);
                    (v > 0 ? nonZero : zero) = true;
                    sum += wa * wb * v;
                }
            double cellIntegral = sum * dt * dp / 9.0;
            if (zero && nonZero) {
                const int n = 96;
                double ht = 1.0 / kThetaBins / n, hp = 2 * M_PI / kPhiBins / n;
                sum = 0;
                for (int a = 0; a < n; ++a)
                    for (int b = 0; b < n; ++b) sum += density(t0 + (a + 0.5) * ht, p0 + (b + 0.5) * hp);
                cellIntegral = sum * ht * hp;
            }
            double cell = cellIntegral;
            expected[size_t(ti * kPhiBins + pj)] = cell * total;
            integral += cell;
        }
    lost = 1 - integral; // mass of failed samples (below the horizon), reported for information
    // Cells expecting fewer than 5 samples are pooled (stipple::testing::chiSquareTest states the rule).
    const stipple::testing::ChiSquareResult chi = stipple::testing::chiSquareTest(observed, expected);
    cellsUsed = chi.degreesOfFreedom + 1;
    if (std::getenv("CHI2_DEBUG")) {
        std::vector<std::pair<double, size_t>> worst;
        for (size_t i = 0; i < observed.size(); ++i)
            if (expected[i] >= 5)
                worst.push_back({(observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i], i});
        std::sort(worst.rbegin(), worst.rend());
        for (size_t k = 0; k < std::min<size_t>(6, worst.size()); ++k) {
            size_t i = worst[k].second;
            std::printf("%s cell t%zu p%zu obs %.0f exp %.1f\n", c.label.c_str(), i / kPhiBins, i % kPhiBins,
                        observed[i], expected[i]);
        }
    }
    return chi.pValue;
}

std::vector<Config> configs() {
    std::vector<Config> out;
    for (float ct : {0.9f, 0.5f, 0.1f}) {
        Material d;
        d.type = MaterialType::Diffuse;
        d.albedo = Spectrum(0.5f);
        out.push_back({"diffuse cos " + std::to_string(ct), d, ct});
        for (float a : {0.001f, 0.05f, 0.3f, 1.0f}) {
            Material m;
            m.type = MaterialType::Conductor;
            m.roughness = a;
            out.push_back({"conductor alpha " + std::to_string(a) + " cos " + std::to_string(ct), m, ct});
        }
        for (float a : {0.001f, 0.1f, 0.5f}) {
            Material m;
            m.type = MaterialType::Plastic;
            m.roughness = a;
            m.ior = 1.5f;
            m.albedo = Spectrum(0.4f, 0.3f, 0.2f);
            out.push_back({"plastic alpha " + std::to_string(a) + " cos " + std::to_string(ct), m, ct});
        }
    }
    return out;
}

} // namespace

BOOST_AUTO_TEST_CASE(sampling_matches_pdf) {
    const ShimLibrary& shim = ShimLibrary::get();
    std::vector<Config> cs = configs();
    const double alpha = stipple::testing::sidak(0.01, int(cs.size()));
    for (size_t i = 0; i < cs.size(); ++i) {
        int cells = 0;
        double lost = 0;
        double p = chi2PValue(cs[i], shim, uint32_t(i), cells, lost);
        BOOST_TEST_MESSAGE(cs[i].label << ": p = " << p << " over " << cells << " cells, mass below horizon " << lost);
        BOOST_TEST(cells >= 2);
        BOOST_TEST(p > alpha, cs[i].label << ": chi2 p-value " << p << " < " << alpha);
    }
}

BOOST_AUTO_TEST_CASE(pdf_integrates_to_at_most_one) {
    // Over the full sphere (uniform-in-solid-angle midpoint grid fine enough for roughness >= 0.05).
    for (const Config& c : configs()) {
        if (c.m.type != MaterialType::Diffuse && c.m.roughness < 0.05f) continue;
        Vec3 wo(std::sqrt(1 - c.cosThetaO * c.cosThetaO), 0, c.cosThetaO);
        const int n = 400;
        double sum = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < 2 * n; ++j) {
                double z = 1 - 2 * (i + 0.5) / n, phi = 2 * M_PI * (j + 0.5) / (2 * n);
                double r = std::sqrt(std::max(0.0, 1 - z * z));
                sum += c.m.pdf(wo, Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
            }
        sum *= 4 * M_PI / (2.0 * n * n);
        BOOST_TEST(sum < 1.01, c.label << ": integral of pdf " << sum);
        BOOST_TEST(sum > 0.5, c.label << ": integral of pdf " << sum);
    }
}
