// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Bidirectional path tracing: a camera subpath z_0 .. z_{t-1} and a light subpath y_0 .. y_{s-1} per camera
// sample, connected by every strategy (s, t) with t >= 1 and s + t - 2 <= max depth:
//   s = 0       the camera subpath itself ends on an emitter;
//   s = 1       (t >= 2) a fresh light sample from z_{t-1} (next-event estimation), not y_0;
//   t = 1       light tracing: y_{s-1} connected to a lens point and splatted at its raster position (through
//               the tile's SplatList, so images do not depend on the thread count);
//   otherwise   y_{s-1} and z_{t-1} joined by a shadow ray.
// Each contribution carries the power-heuristic weight of bdpt_mis.h. Vertices with delta BSDFs (mirror, glass)
// are never connection ends, so an emitter seen through glass from a diffuse surface (a caustic seen in the glass
// that casts it) is left to s = 0 alone; those paths are split along their specular chain (kChainProbes below). Light
// subpaths start on a light chosen by power and scatter with the adjoint BSDF (TransportMode::Importance: no 1/eta^2 at
// refractions, shading-normal correction). No Russian roulette: the walks stop at the depth limit, so every strategy's
// density is known exactly.
//
// Dimensions: the walks' (bdpt_subpath.h), then per connection (max depth D; only what the scene uses):
//   connect.s1.tT.light.choice 1D (more than one light), connect.s1.tT.light.pos 2D   T = 2 .. D+1
//   connect.t1.sS.lens 2D                             S = 1 .. D+1, thin-lens cameras only
// Light walks and s = 1 samples are skipped when every material is specular (no connection can be made). The
// specular-chain probes declare nothing: they read the camera walk's dimensions, shifted (bdpt_subpath.h).
#include "integrators/bdpt/bdpt_integrator.h"

#include "integrators/bdpt/bdpt_mis.h"
#include "integrators/bdpt/bdpt_subpath.h"
#include "integrators/bdpt/bdpt_vertex.h"
#include "integrators/integrator_registry.h"

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

class BdptIntegrator final : public Integrator {
public:
    BdptIntegrator(const RenderScene& scene, const Camera& camera, const IntegratorSettings& s, std::string name)
        : scene_(scene), camera_(camera), eval_(scene, camera), mis_(eval_), maxDepth_(std::max(0, s.maxDepth)),
          subpaths_(scene, camera, maxDepth_), name_(std::move(name)), filter_(parseVariant(name_)) {}

    const char* name() const override { return name_.c_str(); }

    void declareDimensions(SampleLayout& layout) override {
        const size_t nLights = scene_.lights().size();
        if (nLights == 0) return; // nothing can be seen: no dimension is read
        const bool connectible = scene_.anyNonSpecularMaterial();
        subpaths_.declareDimensions(layout, connectible);
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

    Spectrum Li(const Ray& ray, const TracedHit& first, const SampleView& sv, TileContext& tile) const override {
        if (scene_.lights().empty()) return {};
        thread_local std::vector<PathVertex> cam, light;
        subpaths_.cameraSubpath(ray, first, sv, tile, cam);
        subpaths_.lightSubpath(sv, tile, light);

        Spectrum L;
        const int nCam = int(cam.size()), nLight = int(light.size());
        const int chain = specularChainStart(cam);
        LightStart start; // x_0's densities, shared by every strategy with s >= 2
        if (nLight >= 2 && filter_.weighted) start = mis_.lightStart(light);
        for (int t = 1; t <= nCam; ++t) {
            const int sMax = std::min(nLight, maxDepth_ + 2 - t);
            for (int s = 0; s <= std::max(sMax, t >= 2 ? 1 : 0); ++s) {
                if (s + t < 2 || s + t - 2 > maxDepth_ || !filter_.accepts(s, t)) continue;
                if (t == 1) {
                    if (s <= nLight) lightTracing(light, s, start, sv, tile);
                } else if (s == 0) {
                    Spectrum c = hitEmitter(light, cam, t);
                    L += endsChain(cam, chain, t) ? c * (1.0f / (kChainProbes + 1)) : c;
                } else if (s == 1) {
                    L += freshLightSample(light, cam, t, sv, tile);
                } else if (s <= nLight) {
                    L += joinSubpaths(light, cam, s, t, start, tile);
                }
            }
        }
        if (chain > 0 && filter_.s <= 0) { // the probes estimate s = 0 only
            thread_local std::vector<PathVertex> probe;
            for (int j = 1; j <= kChainProbes; ++j) {
                probe.assign(cam.begin(), cam.begin() + chain + 1);
                if (!subpaths_.specularChainProbe(probe, j, sv, tile)) continue;
                const int t = int(probe.size());
                if (endsChain(probe, chain, t) && filter_.accepts(0, t))
                    L += hitEmitter(light, probe, t) * (1.0f / (kChainProbes + 1));
            }
        }
        return L;
    }

private:
    // Splitting for emitters seen through delta surfaces from a non-delta one (a caustic seen in the glass that
    // makes it: light -> glass -> table -> glass -> camera). Only s = 0 samples such paths (every connection
    // would end on a delta vertex), and it hits a small light's image through the glass rarely: the rare, very
    // bright samples that dominate a reference's variance. At the first non-delta camera vertex reached through
    // a delta one, kChainProbes more BSDF samples continue through delta vertices only; every path of that form
    // (that vertex, one or more delta vertices, an emitter) is estimated by the mean over the walk's own
    // continuation and the probes, each distributed like the walk's, so the estimate stays unbiased and the
    // strategy weights are unchanged. The probes cost rays only on camera subpaths that pass through glass: on
    // veach-bidir at 128x128, 63 probes add 11% to the rays (15 add 2.6%) and turn a sample worth ~2400 once in
    // ~1.7e7 samples into one worth ~40 once in ~2.6e5, about once per 16-spp render of the whole image.
    static constexpr int kChainProbes = 63;

    // Index of the first non-delta surface vertex of the camera subpath that follows a delta one; -1 when none.
    static int specularChainStart(const std::vector<PathVertex>& cam) {
        for (size_t k = 2; k < cam.size(); ++k)
            if (cam[k - 1].delta && !cam[k].delta) return int(k);
        return -1;
    }
    // Whether z_0 .. z_{t-1} continues the vertex `chain` with one or more delta vertices and then stops: an
    // emitter hit at z_{t-1} is then the one the probes also estimate.
    static bool endsChain(const std::vector<PathVertex>& cam, int chain, int t) {
        if (chain < 0 || t - 2 <= chain) return false;
        for (int j = chain + 1; j <= t - 2; ++j)
            if (!cam[size_t(j)].delta) return false;
        return true;
    }

    float weight(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int s, int t,
                 const ConnectionVertices& fresh) const {
        return filter_.weighted ? mis_.weight(light, cam, s, t, fresh) : 1.0f;
    }

    // s = 0: the camera subpath's last vertex lies on an emitter.
    Spectrum hitEmitter(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int t) const {
        const PathVertex& z = cam[size_t(t - 1)];
        if (z.light < 0) return {};
        Spectrum Le = eval_.Le(z, z.wPrev);
        if (Le.isBlack()) return {};
        return z.beta * Le * weight(light, cam, 0, t, {});
    }

    // s = 1, t >= 2: a fresh light sample seen from z_{t-1}, drawn with the light's own sampleLi.
    Spectrum freshLightSample(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int t,
                              const SampleView& sv, TileContext& tile) const {
        const PathVertex& z = cam[size_t(t - 1)];
        if (z.delta || connectPos_[size_t(t)] < 0) return {};
        float pmf = 1;
        size_t li =
            scene_.lights().size() == 1 ? 0 : scene_.lightChoice().sample(sv.get1D(connectChoice_[size_t(t)]), &pmf);
        LightLiSample ls;
        if (!scene_.lights()[li].sampleLi(z.p, sv.get2D(connectPos_[size_t(t)]), ls)) return {};
        PathVertex y;
        y.kind = VertexKind::Light;
        y.p = ls.p;
        y.n = y.ns = ls.n;
        y.light = int(li);
        y.pdfFwd = eval_.pdfLightOrigin(y);
        const Link link(y, z);
        Spectrum c = z.beta * eval_.f(z, link.zy, link.zyLocal, TransportMode::Radiance) * ls.L *
                     (absDot(z.ns, ls.wi) / (pmf * ls.pdf));
        if (c.isBlack()) return {};
        ++tile.rays;
        if (scene_.occludedBetween(z.p, z.n, ls.p)) return {};
        ConnectionVertices fresh;
        fresh.freshLight = &y;
        fresh.link = &link;
        return c * weight(light, cam, 1, t, fresh);
    }

    // s >= 2, t >= 2: join y_{s-1} and z_{t-1}.
    Spectrum joinSubpaths(const std::vector<PathVertex>& light, const std::vector<PathVertex>& cam, int s, int t,
                          const LightStart& start, TileContext& tile) const {
        const PathVertex &y = light[size_t(s - 1)], &z = cam[size_t(t - 1)];
        if (y.delta || z.delta) return {};
        const Link link(y, z);
        Spectrum c = y.beta * eval_.f(y, link.yz, link.yzLocal, TransportMode::Importance) *
                     eval_.f(z, link.zy, link.zyLocal, TransportMode::Radiance) * z.beta *
                     PathEvaluator::geometry(y, z);
        if (c.isBlack()) return {};
        ++tile.rays;
        if (scene_.occludedBetween(z.p, z.n, y.p)) return {};
        ConnectionVertices connection;
        connection.link = &link;
        connection.lightStart = &start;
        return c * weight(light, cam, s, t, connection);
    }

    // t = 1: connect y_{s-1} to a lens point and splat the contribution where it lands on the film.
    void lightTracing(const std::vector<PathVertex>& light, int s, const LightStart& start, const SampleView& sv,
                      TileContext& tile) const {
        const PathVertex& y = light[size_t(s - 1)];
        if (y.delta) return;
        Point2 uLens = sv.get2D(connectLens_[size_t(s)]);
        CameraWiSample cs;
        if (!camera_.sampleWi(y.p, uLens, cs)) return;
        PathVertex z;
        z.kind = VertexKind::Camera;
        z.p = cs.pLens;
        z.n = z.ns = cs.nLens;
        const Link link(y, z);
        Spectrum c = y.beta * eval_.f(y, link.yz, link.yzLocal, TransportMode::Importance) * cs.We *
                     (absDot(y.ns, cs.wi) / cs.pdf);
        if (c.isBlack()) return;
        ++tile.rays;
        if (scene_.occludedBetween(y.p, y.n, cs.pLens)) return;
        ConnectionVertices fresh;
        fresh.freshCamera = &z;
        fresh.link = &link;
        fresh.lightStart = &start;
        std::vector<PathVertex> noCamera; // t = 1 reads only the fresh lens vertex
        tile.splats->add(cs.raster, c * weight(light, noCamera, s, 1, fresh), tile.width, tile.height);
    }

    const RenderScene& scene_;
    const Camera& camera_;
    PathEvaluator eval_;
    MisWeights mis_;
    int maxDepth_;
    SubpathGenerator subpaths_;
    std::string name_;
    StrategyFilter filter_;
    std::vector<int> connectChoice_, connectPos_, connectLens_; // indexed by t (s = 1) and by s (t = 1)
};

} // namespace
} // namespace bdpt

std::unique_ptr<Integrator> makeBdptIntegrator(const RenderScene& scene, const Camera& camera,
                                               const IntegratorSettings& settings, const std::string& name) {
    return std::make_unique<bdpt::BdptIntegrator>(scene, camera, settings, name);
}

} // namespace stipple::render
