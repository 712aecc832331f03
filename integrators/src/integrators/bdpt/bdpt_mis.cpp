// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "integrators/bdpt/bdpt_mis.h"

namespace stipple::render::bdpt {

namespace {
struct Scratch {
    std::vector<const PathVertex*> x;
    std::vector<double> fromLight, fromCamera; // area densities of x_j from either end, zeros read as 1
};
inline double remapZero(double p) { return p != 0 ? p : 1.0; }
} // namespace

float MisWeights::weight(const std::vector<PathVertex>& lightPath, const std::vector<PathVertex>& cameraPath, int s,
                         int t, const ConnectionVertices& fresh) const {
    const int n = s + t;
    thread_local Scratch sc;
    if (sc.x.size() < size_t(n)) { // grows to the longest path once; every entry below is written before use
        sc.x.resize(size_t(n));
        sc.fromLight.resize(size_t(n));
        sc.fromCamera.resize(size_t(n));
    }
    const PathVertex** x = sc.x.data();
    double* fromLight = sc.fromLight.data();
    double* fromCamera = sc.fromCamera.data();
    for (int j = 0; j < s; ++j) x[j] = (s == 1 && fresh.freshLight) ? fresh.freshLight : &lightPath[size_t(j)];
    for (int j = s; j < n; ++j)
        x[j] = (t == 1 && fresh.freshCamera) ? fresh.freshCamera : &cameraPath[size_t(n - 1 - j)];

    // Densities fixed by each subpath's own walk.
    for (int j = 0; j < s; ++j) {
        fromLight[j] = x[j]->pdfFwd;
        fromCamera[j] = j < s - 2 ? x[j]->pdfRev : 0.0;
    }
    for (int j = s; j < n; ++j) {
        fromCamera[j] = x[j]->pdfFwd;
        fromLight[j] = j > s + 1 ? x[j]->pdfRev : 0.0;
    }
    // Densities that depend on the connection between x_{s-1} and x_s.
    const PathVertex& xs = *x[s];
    if (s == 0) {
        fromLight[0] = eval_.pdfLightOrigin(xs);
        if (n > 2) fromLight[1] = eval_.pdfLightEmission(xs, normalize(x[1]->p - xs.p), *x[1]);
    } else {
        const Link& link = *fresh.link;
        const PathVertex& xl = *x[s - 1];
        fromLight[s] = eval_.pdfOnward(xl, link.yz, link.yzLocal, xs);
        if (s + 1 < n - 1) fromLight[s + 1] = PathEvaluator::pdfBackward(xs, link.zyLocal, *x[s + 1]);
        fromCamera[s - 1] = eval_.pdfOnward(xs, link.zy, link.zyLocal, xl);
        if (s >= 2) fromCamera[s - 2] = PathEvaluator::pdfBackward(xl, link.yzLocal, *x[s - 2]);
    }
    // x_0 from the light side: by area (light subpaths) or by the s = 1 connection's own sampling.
    LightStart start0;
    if (s >= 2 && fresh.lightStart) {
        start0 = *fresh.lightStart;
    } else if (n >= 3) {
        start0 = start(*x[0], *x[1]);
    } else {
        start0.pOrigin = start0.pConnect = remapZero(eval_.pdfLightOrigin(*x[0]));
    }
    const double pOrigin = start0.pOrigin, pConnect = start0.pConnect;
    for (int j = 0; j < n; ++j) {
        fromLight[j] = remapZero(fromLight[j]);
        fromCamera[j] = remapZero(fromCamera[j]);
    }
    // p_{i+1} / p_i. Strategy 1 (n >= 3) uses pConnect for x_0, every other s' >= 1 uses pOrigin.
    auto ratioUp = [&](int i) -> double {
        if (i == 0) return pConnect / fromCamera[0];
        double r = fromLight[i] / fromCamera[i];
        if (i == 1) r *= pOrigin / pConnect;
        return r;
    };
    auto valid = [&](int sp) { return sp == 0 || (!x[sp - 1]->delta && !x[sp]->delta); };

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

LightStart MisWeights::start(const PathVertex& x0, const PathVertex& x1) const {
    LightStart l;
    l.pOrigin = remapZero(eval_.pdfLightOrigin(x0));
    l.pConnect = remapZero(eval_.pdfLightConnect(x0, x1));
    return l;
}

} // namespace stipple::render::bdpt
