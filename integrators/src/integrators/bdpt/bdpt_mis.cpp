// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "integrators/bdpt/bdpt_mis.h"

namespace stipple::render::bdpt {

namespace {
struct Scratch {
    std::vector<const PathVertex*> x;
    std::vector<double> fromLight, fromCamera; // area densities of x_j from either end, zeros read as 1
    std::vector<char> delta;
};
inline double remapZero(double p) { return p != 0 ? p : 1.0; }
} // namespace

float MisWeights::weight(const std::vector<PathVertex>& lightPath, const std::vector<PathVertex>& cameraPath, int s,
                         int t, const ConnectionVertices& fresh) const {
    const int n = s + t;
    thread_local Scratch sc;
    sc.x.resize(size_t(n));
    sc.fromLight.assign(size_t(n), 0.0);
    sc.fromCamera.assign(size_t(n), 0.0);
    sc.delta.assign(size_t(n), 0);
    for (int j = 0; j < s; ++j)
        sc.x[size_t(j)] = (s == 1 && fresh.freshLight) ? fresh.freshLight : &lightPath[size_t(j)];
    for (int j = s; j < n; ++j)
        sc.x[size_t(j)] = (t == 1 && fresh.freshCamera) ? fresh.freshCamera : &cameraPath[size_t(n - 1 - j)];
    auto X = [&](int j) -> const PathVertex& { return *sc.x[size_t(j)]; };

    for (int j = 0; j < n; ++j) {
        const PathVertex& v = X(j);
        sc.delta[size_t(j)] = v.delta;
        // Densities fixed by each subpath's own walk.
        if (j < s) {
            sc.fromLight[size_t(j)] = v.pdfFwd;
            if (j < s - 2) sc.fromCamera[size_t(j)] = v.pdfRev;
        } else {
            sc.fromCamera[size_t(j)] = v.pdfFwd;
            if (j > s + 1) sc.fromLight[size_t(j)] = v.pdfRev;
        }
    }
    // Densities that depend on the connection between x_{s-1} and x_s.
    const PathVertex& xs = X(s);
    if (s == 0) {
        sc.fromLight[0] = eval_.pdfLightOrigin(xs);
        if (n > 2) sc.fromLight[1] = eval_.pdfLightEmission(xs, X(1));
    } else {
        const PathVertex& xl = X(s - 1);
        sc.fromLight[size_t(s)] = eval_.pdf(s >= 2 ? &X(s - 2) : nullptr, xl, xs);
        if (s + 1 < n - 1) sc.fromLight[size_t(s + 1)] = eval_.pdf(&xl, xs, X(s + 1));
        sc.fromCamera[size_t(s - 1)] = eval_.pdf(t >= 2 ? &X(s + 1) : nullptr, xs, xl);
        if (s >= 2) sc.fromCamera[size_t(s - 2)] = eval_.pdf(&xs, xl, X(s - 2));
    }
    // x_0 from the light side: by area (light subpaths) or by the s = 1 connection's own sampling.
    const double pOrigin = remapZero(eval_.pdfLightOrigin(X(0)));
    const double pConnect = n >= 3 ? remapZero(eval_.pdfLightConnect(X(0), X(1))) : pOrigin;
    for (int j = 0; j < n; ++j) {
        sc.fromLight[size_t(j)] = remapZero(sc.fromLight[size_t(j)]);
        sc.fromCamera[size_t(j)] = remapZero(sc.fromCamera[size_t(j)]);
    }
    // p_{i+1} / p_i. Strategy 1 (n >= 3) uses pConnect for x_0, every other s' >= 1 uses pOrigin.
    auto ratioUp = [&](int i) -> double {
        if (i == 0) return pConnect / sc.fromCamera[0];
        double r = sc.fromLight[size_t(i)] / sc.fromCamera[size_t(i)];
        if (i == 1) r *= pOrigin / pConnect;
        return r;
    };
    auto valid = [&](int sp) { return sp == 0 || (!sc.delta[size_t(sp - 1)] && !sc.delta[size_t(sp)]); };

    double sum = 1.0; // the strategy itself: r_s = 1
    double r = 1.0;
    for (int sp = s + 1; sp <= n - 1; ++sp) { // more vertices from the light
        r *= ratioUp(sp - 1);
        if (valid(sp)) sum += r * r;
    }
    r = 1.0;
    for (int sp = s - 1; sp >= 0; --sp) { // more vertices from the camera
        r /= ratioUp(sp);
        if (valid(sp)) sum += r * r;
    }
    return std::isfinite(sum) ? float(1.0 / sum) : 0.0f;
}

} // namespace stipple::render::bdpt
