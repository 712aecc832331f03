// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "integrators/bdpt/bdpt_vertex.h"

namespace stipple::render::bdpt {

namespace {
inline Vec3 direction(const PathVertex& from, const PathVertex& to) { return normalize(to.p - from.p); }
} // namespace

void PathVertex::follow(const PathVertex& prev) {
    frame = Frame(ns);
    wPrev = direction(*this, prev);
    wPrevLocal = frame.toLocal(wPrev);
}

Link::Link(const PathVertex& y, const PathVertex& z) : yz(direction(y, z)), zy(direction(z, y)) {
    if (y.kind == VertexKind::Surface) yzLocal = y.frame.toLocal(yz);
    if (z.kind == VertexKind::Surface) zyLocal = z.frame.toLocal(zy);
}

float PathEvaluator::pdfOnward(const PathVertex& cur, const Vec3& w, const Vec3& wLocal, const PathVertex& next) const {
    switch (cur.kind) {
    case VertexKind::Camera: {
        float pdfPos, pdfDir;
        camera_.pdfWe(Ray{cur.p, w}, pdfPos, pdfDir);
        return toArea(pdfDir, cur, next);
    }
    case VertexKind::Light: return pdfLightEmission(cur, w, next);
    case VertexKind::Surface: return toArea(cur.material->pdf(cur.wPrevLocal, wLocal), cur, next);
    }
    return 0;
}

float PathEvaluator::pdf(const PathVertex* prev, const PathVertex& cur, const PathVertex& next) const {
    const Vec3 w = direction(cur, next);
    if (cur.kind != VertexKind::Surface) return pdfOnward(cur, w, Vec3(), next);
    if (!prev) return 0;
    const Frame frame(cur.ns);
    return toArea(cur.material->pdf(frame.toLocal(direction(cur, *prev)), frame.toLocal(w)), cur, next);
}

float PathEvaluator::pdfBackward(const PathVertex& cur, const Vec3& wLocal, const PathVertex& prev) {
    return toArea(cur.material->pdf(wLocal, cur.wPrevLocal), cur, prev);
}

float PathEvaluator::pdfLightOrigin(const PathVertex& v) const {
    if (v.light < 0) return 0;
    return scene_.lightChoicePmf(v.light) / scene_.lights()[size_t(v.light)].area();
}

float PathEvaluator::pdfLightEmission(const PathVertex& v, const Vec3& w, const PathVertex& next) const {
    if (v.light < 0) return 0;
    float pdfPos, pdfDir;
    scene_.lights()[size_t(v.light)].pdfLe(v.n, w, pdfPos, pdfDir);
    return toArea(pdfDir, v, next);
}

float PathEvaluator::pdfLightConnect(const PathVertex& v, const PathVertex& ref) const {
    if (v.light < 0) return 0;
    const Light& light = scene_.lights()[size_t(v.light)];
    // sampleLi's density is a solid angle at ref (a cone for spheres seen from outside, else area-uniform).
    return toArea(scene_.lightChoicePmf(v.light) * light.pdfLi(ref.p, v.p, v.n), ref, v);
}

Spectrum PathEvaluator::f(const PathVertex& cur, const Vec3& w, const Vec3& wLocal, TransportMode mode) const {
    switch (cur.kind) {
    case VertexKind::Light: return Le(cur, w);
    case VertexKind::Surface: {
        Spectrum v = cur.material->f(cur.wPrevLocal, wLocal, mode);
        if (mode == TransportMode::Importance) v *= shadingNormalCorrection(cur.ns, cur.n, cur.wPrev, w);
        return v;
    }
    case VertexKind::Camera: return {};
    }
    return {};
}

Spectrum PathEvaluator::Le(const PathVertex& v, const Vec3& w) const {
    if (v.light < 0) return {};
    return scene_.lights()[size_t(v.light)].L(v.n, w);
}

} // namespace stipple::render::bdpt
