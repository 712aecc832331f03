// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "integrators/bdpt/bdpt_subpath.h"

#include <algorithm>
#include <cmath>

namespace stipple::render::bdpt {

void SubpathGenerator::declareDimensions(SampleLayout& layout, bool lightWalk) {
    camBounce_.clear();
    lightBounce_.clear();
    lightChoice_ = lightPos_ = lightDir_ = -1;
    const size_t nLights = scene_.lights().size();
    if (nLights == 0) return;
    const bool lobe = scene_.anyMaterialUsesLobeChoice();
    auto bounce = [&](const std::string& prefix) {
        BounceDims d;
        if (lobe) d.lobe = layout.add(prefix + "bsdf.lobe", 1);
        d.dir = layout.add(prefix + "bsdf.dir", 2);
        return d;
    };
    for (int b = 0; b < maxDepth_; ++b) camBounce_.push_back(bounce("cam.b" + std::to_string(b) + "."));
    if (nLights > 1) lightChoice_ = layout.add("light.choice", 1);
    lightPos_ = layout.add("light.pos", 2);
    if (lightWalk && maxDepth_ >= 1) {
        lightDir_ = layout.add("light.dir", 2);
        for (int b = 0; b + 2 <= maxDepth_; ++b) lightBounce_.push_back(bounce("light.b" + std::to_string(b) + "."));
    }
}

void SubpathGenerator::pushSurface(const SurfaceHit& hit, const Spectrum& beta, float pdfDir,
                                   std::vector<PathVertex>& path) {
    PathVertex v;
    v.kind = VertexKind::Surface;
    v.p = hit.p;
    v.n = v.ns = hit.ng;
    v.material = hit.material;
    v.light = hit.light;
    v.beta = beta;
    v.delta = hit.material->isSpecular();
    v.pdfFwd = PathEvaluator::toArea(pdfDir, path.back(), v);
    v.follow(path.back());
    path.push_back(v);
}

bool SubpathGenerator::scatter(std::vector<PathVertex>& path, const Vec3& woW, float uc, Point2 u, TransportMode mode,
                               Spectrum& beta, float& pdfDir, Ray& ray) {
    const PathVertex& v = path.back();
    const Frame& frame = v.frame;
    Vec3 wo = frame.toLocal(woW);
    BsdfSample bs;
    if (!v.material->sample(wo, uc, u, bs, mode)) return false;
    Vec3 wiW = frame.toWorld(bs.wi);
    beta *= bs.f * (std::abs(bs.wi.z) / bs.pdf);
    if (mode == TransportMode::Importance) beta *= shadingNormalCorrection(v.ns, v.n, woW, wiW);
    // Densities of a delta lobe are Dirac terms: stored as 0, read as 1 by the MIS walk.
    pdfDir = bs.isSpecular() ? 0.0f : bs.pdf;
    // The reverse density: the previous vertex as sampled from here, arriving from the next one.
    float pdfRevDir = bs.isSpecular() ? 0.0f : v.material->pdf(bs.wi, wo);
    PathVertex& prev = path[path.size() - 2];
    prev.pdfRev = PathEvaluator::toArea(pdfRevDir, v, prev);
    if (beta.isBlack()) return false;
    ray = Ray{offsetRayOrigin(v.p, v.n, wiW), wiW};
    return true;
}

void SubpathGenerator::walk(Ray ray, const TracedHit* first, Spectrum beta, float pdfDir, TransportMode mode,
                            const std::vector<BounceDims>& dims, int maxSurface, const SampleView& sv,
                            TileContext& tile, std::vector<PathVertex>& path) const {
    for (int b = 0; b < maxSurface; ++b) {
        SurfaceHit traced;
        const SurfaceHit* hit = &traced;
        if (b == 0 && first) {
            if (!first->found) return;
            hit = &first->hit;
        } else {
            ++tile.rays;
            if (!scene_.intersect(ray, traced)) return;
        }
        pushSurface(*hit, beta, pdfDir, path);
        if (b + 1 >= maxSurface || size_t(b) >= dims.size()) return;
        const BounceDims& d = dims[size_t(b)];
        if (!scatter(path, -ray.d, sv.get1D(d.lobe), sv.get2D(d.dir), mode, beta, pdfDir, ray)) return;
    }
}

namespace {
// Probe j's offsets: the additive recurrences of the golden ratio (1D) and of the plastic number (2D, Roberts'
// R2), so the walk's own sample and its probes spread evenly over each dimension's unit interval or square.
inline float shifted(float u, double offset) {
    double v = double(u) + offset;
    return std::min(float(v - std::floor(v)), 0x1.fffffep-1f);
}
} // namespace

bool SubpathGenerator::specularChainProbe(std::vector<PathVertex>& path, int probe, const SampleView& sv,
                                          TileContext& tile) const {
    const int maxSurface = maxDepth_ + 1;
    Spectrum beta = path.back().beta;
    Vec3 woW = normalize(path[path.size() - 2].p - path.back().p);
    for (int b = int(path.size()) - 2;; ++b) { // bounce index of path.back(): the first surface vertex is bounce 0
        if (b + 1 >= maxSurface || size_t(b) >= camBounce_.size()) return false;
        const BounceDims& d = camBounce_[size_t(b)];
        const Point2 u = sv.get2D(d.dir);
        const float uc = shifted(sv.get1D(d.lobe), probe * 0.6180339887498949);
        const Point2 uShifted{shifted(u.x, probe * 0.7548776662466927), shifted(u.y, probe * 0.5698402909980532)};
        float pdfDir = 0;
        Ray ray;
        if (!scatter(path, woW, uc, uShifted, TransportMode::Radiance, beta, pdfDir, ray)) return false;
        SurfaceHit hit;
        ++tile.rays;
        if (!scene_.intersect(ray, hit)) return false;
        pushSurface(hit, beta, pdfDir, path);
        if (!path.back().delta) return true;
        woW = -ray.d;
    }
}

void SubpathGenerator::cameraSubpath(const Ray& ray, const TracedHit& first, const SampleView& sv,
                                     TileContext& tile, std::vector<PathVertex>& cam) const {
    cam.clear();
    PathVertex z0;
    z0.kind = VertexKind::Camera;
    z0.p = ray.o;
    z0.n = z0.ns = camera_.forward();
    z0.beta = Spectrum(1.0f); // We cos / (pdfPos pdfDir) = 1 for raster-uniform primary rays
    cam.push_back(z0);
    float pdfPos, pdfDir;
    camera_.pdfWe(ray, pdfPos, pdfDir);
    walk(ray, &first, Spectrum(1.0f), pdfDir, TransportMode::Radiance, camBounce_, maxDepth_ + 1, sv, tile, cam);
}

void SubpathGenerator::lightSubpath(const SampleView& sv, TileContext& tile, std::vector<PathVertex>& light) const {
    light.clear();
    if (lightPos_ < 0) return;
    float pmf = 1;
    size_t li = scene_.lights().size() == 1 ? 0 : scene_.lightChoice().sample(sv.get1D(lightChoice_), &pmf);
    const Light& l = scene_.lights()[li];
    LightLeSample le;
    if (!l.sampleLe(sv.get2D(lightPos_), sv.get2D(lightDir_), le)) return;
    PathVertex y0;
    y0.kind = VertexKind::Light;
    // sampleLe offsets the ray origin off the light along the emitting side; undo it for the vertex itself.
    y0.p = le.ray.o - le.n * surfaceEpsilon(le.ray.o);
    y0.n = y0.ns = le.n;
    y0.light = int(li);
    y0.pdfFwd = pmf * le.pdfPos;
    y0.beta = Spectrum(1 / y0.pdfFwd); // the light vertex's "f" is its emitted radiance (PathEvaluator::f)
    light.push_back(y0);
    if (lightDir_ < 0) return;
    Spectrum beta = le.L * (absDot(le.n, le.ray.d) / (y0.pdfFwd * le.pdfDir));
    walk(le.ray, nullptr, beta, le.pdfDir, TransportMode::Importance, lightBounce_, maxDepth_, sv, tile, light);
}

} // namespace stipple::render::bdpt
