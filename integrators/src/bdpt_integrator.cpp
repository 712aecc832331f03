// Bidirectional path tracing: a camera subpath z_0 .. z_{t-1} and a light subpath y_0 .. y_{s-1} per camera
// sample, connected by every strategy (s, t) with t >= 1 and s + t - 2 <= max depth:
//   s = 0       the camera subpath itself ends on an emitter;
//   s = 1       (t >= 2) a fresh light sample from z_{t-1} (next-event estimation), not y_0;
//   t = 1       light tracing: y_{s-1} connected to a lens point and splatted at its raster position (through
//               the tile's SplatList, so images do not depend on the thread count);
//   otherwise   y_{s-1} and z_{t-1} joined by a shadow ray.
// Each contribution carries the power-heuristic weight of bdpt_mis.h. Vertices with delta BSDFs (mirror, glass)
// are never connection ends. Light subpaths start on a light chosen by power and scatter with the adjoint BSDF
// (TransportMode::Importance: no 1/eta^2 at refractions, shading-normal correction). No Russian roulette: the
// walks stop at the depth limit, so every strategy's density is known exactly.
//
// Dimensions (max depth D; only what the scene uses; bB = scattering at the B-th surface hit of that subpath):
//   cam.bB.bsdf.lobe 1D, cam.bB.bsdf.dir 2D           B = 0 .. D-1  (lobe only when a material has two lobes)
//   light.choice 1D (more than one light), light.pos 2D, light.dir 2D (D >= 1)
//   light.bB.bsdf.lobe 1D, light.bB.bsdf.dir 2D       B = 0 .. D-2
//   connect.s1.tT.light.choice 1D, connect.s1.tT.light.pos 2D   T = 2 .. D+1 (the fresh s = 1 samples)
//   connect.t1.sS.lens 2D                             S = 1 .. D+1, thin-lens cameras only
// Light subpath and s = 1 dimensions are skipped when every material is specular (no connection can be made).
#include "bdpt_integrator.h"

#include "bdpt_mis.h"
#include "bdpt_vertex.h"
#include "integrator_registry.h"

#include <stdexcept>

namespace stipple::render {

namespace bdpt {

StrategyFilter parseVariant(const std::string& name) {
    StrategyFilter f;
    if (name == "bdpt") return f;
    auto fail = [&]() -> StrategyFilter {
        throw std::invalid_argument("unknown integrator '" + name +
                                    "'; BDPT debug variants are bdpt:s=S,t=T (one strategy, unweighted), "
                                    "bdpt:s=S,t=T,mis (one strategy, MIS-weighted) and bdpt:depth=D");
    };
    if (name.rfind("bdpt:", 0) != 0) return fail();
    std::string rest = name.substr(5);
    auto number = [&](const std::string& text) {
        if (text.empty() || text.size() > 4 || text.find_first_not_of("0123456789") != std::string::npos) fail();
        return std::stoi(text);
    };
    if (rest.rfind("depth=", 0) == 0) {
        f.depth = number(rest.substr(6));
        return f;
    }
    if (rest.rfind("s=", 0) != 0) return fail();
    size_t comma = rest.find(",t=");
    if (comma == std::string::npos) return fail();
    f.s = number(rest.substr(2, comma - 2));
    std::string tail = rest.substr(comma + 3);
    f.weighted = false;
    size_t mis = tail.find(",mis");
    if (mis != std::string::npos) {
        if (tail.substr(mis) != ",mis") return fail();
        f.weighted = true;
        tail = tail.substr(0, mis);
    }
    f.t = number(tail);
    if (f.t < 1 || f.s + f.t < 2) {
        throw std::invalid_argument("BDPT strategy s=" + std::to_string(f.s) + ", t=" + std::to_string(f.t) +
                                    " does not exist: t must be >= 1 and s + t >= 2");
    }
    return f;
}

namespace {

struct BounceDims {
    int lobe = -1, dir = -1;
};

class BdptIntegrator final : public Integrator {
public:
    BdptIntegrator(const RenderScene& scene, const Camera& camera, const IntegratorSettings& s, std::string name)
        : scene_(scene), camera_(camera), eval_(scene, camera), mis_(eval_), maxDepth_(std::max(0, s.maxDepth)),
          name_(std::move(name)), filter_(parseVariant(name_)) {}

    const char* name() const override { return name_.c_str(); }

    void declareDimensions(SampleLayout& layout) override {
        const size_t nLights = scene_.lights().size();
        if (nLights == 0) return; // nothing can be seen: no dimension is read
        const bool lobe = scene_.anyMaterialUsesLobeChoice();
        const bool connectible = scene_.anyNonSpecularMaterial();
        auto bounce = [&](const std::string& prefix) {
            BounceDims d;
            if (lobe) d.lobe = layout.add(prefix + "bsdf.lobe", 1);
            d.dir = layout.add(prefix + "bsdf.dir", 2);
            return d;
        };
        camBounce_.clear();
        for (int b = 0; b < maxDepth_; ++b) camBounce_.push_back(bounce("cam.b" + std::to_string(b) + "."));
        if (nLights > 1) lightChoice_ = layout.add("light.choice", 1);
        lightPos_ = layout.add("light.pos", 2);
        lightBounce_.clear();
        if (connectible && maxDepth_ >= 1) {
            lightDir_ = layout.add("light.dir", 2);
            for (int b = 0; b + 2 <= maxDepth_; ++b)
                lightBounce_.push_back(bounce("light.b" + std::to_string(b) + "."));
        }
        connectChoice_.assign(size_t(maxDepth_ + 2), -1);
        connectPos_.assign(size_t(maxDepth_ + 2), -1);
        if (connectible) {
            for (int t = 2; t <= maxDepth_ + 1; ++t) {
                std::string p = "connect.s1.t" + std::to_string(t) + ".light.";
                if (nLights > 1) connectChoice_[size_t(t)] = layout.add(p + "choice", 1);
                connectPos_[size_t(t)] = layout.add(p + "pos", 2);
            }
        }
        connectLens_.assign(size_t(maxDepth_ + 2), -1);
        if (camera_.isThinLens())
            for (int s = 1; s <= (connectible ? maxDepth_ + 1 : 1); ++s)
                connectLens_[size_t(s)] = layout.add("connect.t1.s" + std::to_string(s) + ".lens", 2);
    }

    Spectrum Li(const Ray& ray, const SampleView& sv, TileContext& tile) const override {
        if (scene_.lights().empty()) return {};
        thread_local std::vector<PathVertex> cam, light;
        cameraSubpath(ray, sv, tile, cam);
        lightSubpath(sv, tile, light);

        Spectrum L;
        const int nCam = int(cam.size()), nLight = int(light.size());
        for (int t = 1; t <= nCam; ++t) {
            const int sMax = std::min(nLight, maxDepth_ + 2 - t);
            for (int s = 0; s <= std::max(sMax, t >= 2 ? 1 : 0); ++s) {
                if (s + t < 2 || s + t - 2 > maxDepth_ || !filter_.accepts(s, t)) continue;
                if (t == 1) {
                    if (s <= nLight) lightTracing(light, s, sv, tile);
                } else if (s == 0) {
                    L += hitEmitter(light, cam, t);
                } else if (s == 1) {
                    L += freshLightSample(light, cam, t, sv, tile);
                } else if (s <= nLight) {
                    L += joinSubpaths(light, cam, s, t, tile);
                }
            }
        }
        return L;
    }

private:
    // Scatters from the last vertex of `path` along `ray` until maxSurface surface vertices were added, the ray
    // escapes or sampling fails. dims[b] drives the scattering at the b-th surface vertex.
    void walk(Ray ray, Spectrum beta, float pdfDir, TransportMode mode, const std::vector<BounceDims>& dims,
              int maxSurface, const SampleView& sv, TileContext& tile, std::vector<PathVertex>& path) const {
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
            if (!v.material->sample(wo, sv.get1D(dims[size_t(b)].lobe), sv.get2D(dims[size_t(b)].dir), bs, mode))
                return;
            Vec3 wiW = frame.toWorld(bs.wi);
            beta *= bs.f * (std::abs(bs.wi.z) / bs.pdf);
            if (mode == TransportMode::Importance) beta *= shadingNormalCorrection(v.ns, v.n, woW, wiW);
            // Densities of a delta lobe are Dirac terms: stored as 0, read as 1 by the MIS walk.
            pdfDir = bs.isSpecular() ? 0.0f : bs.pdf;
            float pdfRevDir = bs.isSpecular() ? 0.0f : v.material->pdf(bs.wi, wo);
            PathVertex& prev = path[path.size() - 2];
            prev.pdfRev = PathEvaluator::toArea(pdfRevDir, path.back(), prev);
            if (beta.isBlack()) return;
            ray = Ray{offsetRayOrigin(v.p, v.n, wiW), wiW};
        }
    }

    void cameraSubpath(const Ray& ray, const SampleView& sv, TileContext& tile, std::vector<PathVertex>& cam) const {
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

    void lightSubpath(const SampleView& sv, TileContext& tile, std::vector<PathVertex>& light) const {
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

    float weight(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int s, int t,
                 const ConnectionVertices& fresh) const {
        return filter_.weighted ? mis_.weight(light, cam, s, t, fresh) : 1.0f;
    }

    // s = 0: the camera subpath's last vertex lies on an emitter.
    Spectrum hitEmitter(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int t) const {
        const PathVertex& z = cam[size_t(t - 1)];
        if (z.light < 0) return {};
        Spectrum Le = eval_.Le(z, cam[size_t(t - 2)]);
        if (Le.isBlack()) return {};
        return z.beta * Le * weight(light, cam, 0, t, {});
    }

    // s = 1, t >= 2: a fresh light sample seen from z_{t-1}, drawn with the light's own sampleLi.
    Spectrum freshLightSample(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int t,
                              const SampleView& sv, TileContext& tile) const {
        const PathVertex& z = cam[size_t(t - 1)];
        if (z.delta || connectPos_[size_t(t)] < 0) return {};
        float pmf = 1;
        size_t li = scene_.lights().size() == 1
                        ? 0
                        : scene_.lightChoice().sample(sv.get1D(connectChoice_[size_t(t)]), &pmf);
        LightLiSample ls;
        if (!scene_.lights()[li].sampleLi(z.p, sv.get2D(connectPos_[size_t(t)]), ls)) return {};
        PathVertex y;
        y.kind = VertexKind::Light;
        y.p = ls.p;
        y.n = y.ns = ls.n;
        y.light = int(li);
        y.pdfFwd = eval_.pdfLightOrigin(y);
        Spectrum c = z.beta * eval_.f(&cam[size_t(t - 2)], z, y, TransportMode::Radiance) * ls.L *
                     (absDot(z.ns, ls.wi) / (pmf * ls.pdf));
        if (c.isBlack()) return {};
        ++tile.rays;
        if (scene_.occludedBetween(z.p, z.n, ls.p)) return {};
        ConnectionVertices fresh;
        fresh.freshLight = &y;
        return c * weight(light, cam, 1, t, fresh);
    }

    // s >= 2, t >= 2: join y_{s-1} and z_{t-1}.
    Spectrum joinSubpaths(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int s, int t,
                          TileContext& tile) const {
        const PathVertex &y = light[size_t(s - 1)], &z = cam[size_t(t - 1)];
        if (y.delta || z.delta) return {};
        Spectrum c = y.beta * eval_.f(&light[size_t(s - 2)], y, z, TransportMode::Importance) *
                     eval_.f(&cam[size_t(t - 2)], z, y, TransportMode::Radiance) * z.beta *
                     PathEvaluator::geometry(y, z);
        if (c.isBlack()) return {};
        ++tile.rays;
        if (scene_.occludedBetween(z.p, z.n, y.p)) return {};
        return c * weight(light, cam, s, t, {});
    }

    // t = 1: connect y_{s-1} to a lens point and splat the contribution where it lands on the film.
    void lightTracing(const std::vector<PathVertex>& light, int s, const SampleView& sv, TileContext& tile) const {
        const PathVertex& y = light[size_t(s - 1)];
        if (y.delta) return;
        Point2 uLens = sv.get2D(connectLens_[size_t(s)]);
        CameraWiSample cs;
        if (!camera_.sampleWi(y.p, uLens, cs)) return;
        PathVertex z;
        z.kind = VertexKind::Camera;
        z.p = cs.pLens;
        z.n = z.ns = cs.nLens;
        const PathVertex* prev = s >= 2 ? &light[size_t(s - 2)] : nullptr;
        Spectrum c = y.beta * eval_.f(prev, y, z, TransportMode::Importance) * cs.We *
                     (absDot(y.ns, cs.wi) / cs.pdf);
        if (c.isBlack()) return;
        ++tile.rays;
        if (scene_.occludedBetween(y.p, y.n, cs.pLens)) return;
        ConnectionVertices fresh;
        fresh.freshCamera = &z;
        std::vector<PathVertex> noCamera; // t = 1 reads only the fresh lens vertex
        tile.splats->add(cs.raster, c * weight(light, noCamera, s, 1, fresh), tile.width, tile.height);
    }

    const RenderScene& scene_;
    const Camera& camera_;
    PathEvaluator eval_;
    MisWeights mis_;
    int maxDepth_;
    std::string name_;
    StrategyFilter filter_;
    std::vector<BounceDims> camBounce_, lightBounce_;
    int lightChoice_ = -1, lightPos_ = -1, lightDir_ = -1;
    std::vector<int> connectChoice_, connectPos_, connectLens_; // indexed by t (s = 1) and by s (t = 1)
};

} // namespace
} // namespace bdpt

std::unique_ptr<Integrator> makeBdptIntegrator(const RenderScene& scene, const Camera& camera,
                                               const IntegratorSettings& settings, const std::string& name) {
    return std::make_unique<bdpt::BdptIntegrator>(scene, camera, settings, name);
}

} // namespace stipple::render
