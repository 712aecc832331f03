#include "integrators/bdpt/bdpt_subpath.h"

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

void SubpathGenerator::walk(Ray ray, Spectrum beta, float pdfDir, TransportMode mode,
                            const std::vector<BounceDims>& dims, int maxSurface, const SampleView& sv,
                            TileContext& tile, std::vector<PathVertex>& path) const {
    for (int b = 0; b < maxSurface; ++b) {
        SurfaceHit hit;
        ++tile.rays;
        if (!scene_.intersect(ray, hit)) return;
        PathVertex v;
        v.kind = VertexKind::Surface;
        v.p = hit.p;
        v.n = v.ns = hit.ng;
        v.material = hit.material;
        v.light = hit.light;
        v.beta = beta;
        v.delta = hit.material->isSpecular();
        v.pdfFwd = PathEvaluator::toArea(pdfDir, path.back(), v);
        path.push_back(v);
        if (b + 1 >= maxSurface || size_t(b) >= dims.size()) return;

        Frame frame(v.ns);
        Vec3 woW = -ray.d, wo = frame.toLocal(woW);
        BsdfSample bs;
        if (!v.material->sample(wo, sv.get1D(dims[size_t(b)].lobe), sv.get2D(dims[size_t(b)].dir), bs, mode)) return;
        Vec3 wiW = frame.toWorld(bs.wi);
        beta *= bs.f * (std::abs(bs.wi.z) / bs.pdf);
        if (mode == TransportMode::Importance) beta *= shadingNormalCorrection(v.ns, v.n, woW, wiW);
        // Densities of a delta lobe are Dirac terms: stored as 0, read as 1 by the MIS walk.
        pdfDir = bs.isSpecular() ? 0.0f : bs.pdf;
        // The reverse density: the previous vertex as sampled from here, arriving from the next one.
        float pdfRevDir = bs.isSpecular() ? 0.0f : v.material->pdf(bs.wi, wo);
        PathVertex& prev = path[path.size() - 2];
        prev.pdfRev = PathEvaluator::toArea(pdfRevDir, path.back(), prev);
        if (beta.isBlack()) return;
        ray = Ray{offsetRayOrigin(v.p, v.n, wiW), wiW};
    }
}

void SubpathGenerator::cameraSubpath(const Ray& ray, const SampleView& sv, TileContext& tile,
                                     std::vector<PathVertex>& cam) const {
    cam.clear();
    PathVertex z0;
    z0.kind = VertexKind::Camera;
    z0.p = ray.o;
    z0.n = z0.ns = camera_.forward();
    z0.beta = Spectrum(1.0f); // We cos / (pdfPos pdfDir) = 1 for raster-uniform primary rays
    cam.push_back(z0);
    float pdfPos, pdfDir;
    camera_.pdfWe(ray, pdfPos, pdfDir);
    walk(ray, Spectrum(1.0f), pdfDir, TransportMode::Radiance, camBounce_, maxDepth_ + 1, sv, tile, cam);
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
    walk(le.ray, beta, le.pdfDir, TransportMode::Importance, lightBounce_, maxDepth_, sv, tile, light);
}

} // namespace stipple::render::bdpt
