// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Which of Embree's queries pay on which rays: the renderer's single-ray queries (RenderScene::intersect,
// occluded) against its 16-ray packet queries (intersectPacket, occludedPacket), timed on the rays a scene's
// integrators trace, grouped as a lock-step renderer would group them: one pixel's 16 samples.
//
//     stipple-ray-queries SCENE.yaml... [--stride S (2)] [--rounds K (5)] [--shim LIB]
//
// Per scene, four sets of rays, every pixel S-th in x and y, 16 samples each (the shim's independent pattern):
//   camera   a pixel's camera rays (one point, one pixel: coherent);
//   bounce1  from each camera ray's hit, a cosine-distributed direction (what a path tracer traces next);
//   bounce2  the same from bounce1's hits;
//   shadow   from each camera ray's hit to a point on a light chosen by power (next-event estimation).
// The first three are closest-hit queries, shadow an any-hit query. K rounds, each timing every ray of a set once
// one at a time and once in packets of its pixel's rays, in alternating order (ABBA), on one thread. Per set:
// the median time per ray of each, and the median of the per-round ratios single / packet (above 1: packets pay).
// The hits of both are counted; they must agree.
#include "camera/camera.h"
#include "sampling/pixel_sampler.h"
#include "sampling/sample_layout.h"
#include "scene/render_scene.h"
#include "scene/scene_loader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

using namespace stipple::render;

namespace {

constexpr int kBundle = RenderScene::kPacketSize;

// Rays in bundles of at most kBundle (one pixel's, those still alive), as a lock-step renderer would trace them.
struct RaySet {
    RaySet(const char* n, bool any) : name(n), anyHit(any) {}
    const char* name;
    bool anyHit; // shadow rays: any hit
    std::vector<Ray> rays;
    std::vector<size_t> bundleStart{0};
    void closeBundle() {
        if (rays.size() > bundleStart.back()) bundleStart.push_back(rays.size());
    }
};

struct Options {
    std::vector<std::string> scenes;
    int stride = 2, rounds = 5;
    std::string shim;
};

[[noreturn]] void usage(const std::string& why) {
    std::fprintf(stderr,
                 "stipple-ray-queries: %s\nusage: stipple-ray-queries SCENE.yaml... [--stride S] [--rounds K] "
                 "[--shim LIB]\n",
                 why.c_str());
    std::exit(2);
}

int positiveArgument(const char* name, const char* value) {
    char* end = nullptr;
    const long v = std::strtol(value, &end, 10);
    if (end == value || *end != '\0' || v < 1 || v > 1000)
        usage(std::string(name) + " takes 1 to 1000, got '" + value + "'");
    return int(v);
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if ((a == "--stride" || a == "--rounds" || a == "--shim") && i + 1 >= argc) usage(a + " needs a value");
        if (a == "--stride")
            o.stride = positiveArgument("--stride", argv[++i]);
        else if (a == "--rounds")
            o.rounds = positiveArgument("--rounds", argv[++i]);
        else if (a == "--shim")
            o.shim = argv[++i];
        else if (a.starts_with("-"))
            usage("unknown option " + a);
        else
            o.scenes.push_back(a);
    }
    if (o.scenes.empty()) usage("no scene given");
    return o;
}

// Continues a ray from its hit in a cosine-distributed direction on the side it arrived from.
Ray bounce(const Ray& ray, const SurfaceHit& hit, Point2 u) {
    const Frame frame(hit.ng);
    Vec3 wi = frame.toWorld(sampleCosineHemisphere(u));
    if (dot(ray.d, hit.ng) > 0) wi = -wi;
    return Ray{offsetRayOrigin(hit.p, hit.ng, wi), wi};
}

std::vector<RaySet> gatherRays(const RenderScene& scene, const Options& o) {
    const SceneDescription& desc = scene.description();
    const Camera camera(desc.camera, desc.settings.width, desc.settings.height);
    SampleLayout layout;
    const int dimPixel = layout.add("pixel", 2), dimLens = layout.add("lens", 2);
    const int dimBounce1 = layout.add("bounce1", 2), dimBounce2 = layout.add("bounce2", 2);
    const int dimLight = layout.add("light.choice", 1), dimLightPos = layout.add("light.pos", 2);
    PixelSampler sampler(ShimLibrary::get(o.shim), "independent", kBundle, 1, layout);
    PixelSamples samples(sampler);

    std::vector<RaySet> sets{{"camera", false}, {"bounce1", false}, {"bounce2", false}, {"shadow", true}};
    RaySet &cam = sets[0], &b1 = sets[1], &b2 = sets[2], &shadow = sets[3];
    for (int y = 0; y < desc.settings.height; y += o.stride) {
        for (int x = 0; x < desc.settings.width; x += o.stride) {
            sampler.startPixel(uint32_t(x), uint32_t(y), samples);
            for (uint32_t i = 0; i < kBundle; ++i) {
                const SampleView sv(samples, i);
                const Point2 u = sv.get2D(dimPixel);
                const Ray r0 = camera.generateRay({float(x) + u.x, float(y) + u.y}, sv.get2D(dimLens));
                cam.rays.push_back(r0);
                SurfaceHit h0, h1;
                if (!scene.intersect(r0, h0)) continue;
                if (!scene.lights().empty()) {
                    float pmf = 1;
                    const size_t li = scene.lightChoice().sample(sv.get1D(dimLight), &pmf);
                    LightLiSample ls;
                    Ray s;
                    if (scene.lights()[li].sampleLi(h0.p, sv.get2D(dimLightPos), ls) &&
                        RenderScene::shadowRay(h0.p, h0.ng, ls.p, s))
                        shadow.rays.push_back(s);
                }
                const Ray r1 = bounce(r0, h0, sv.get2D(dimBounce1));
                b1.rays.push_back(r1);
                if (scene.intersect(r1, h1)) b2.rays.push_back(bounce(r1, h1, sv.get2D(dimBounce2)));
            }
            for (RaySet& s : sets) s.closeBundle();
        }
    }
    return sets;
}

struct Timed {
    double seconds;
    size_t hits;
};

Timed traceSingle(const RenderScene& scene, const RaySet& set) {
    const auto start = std::chrono::steady_clock::now();
    size_t hits = 0;
    SurfaceHit hit;
    for (const Ray& r : set.rays) hits += set.anyHit ? scene.occluded(r) : scene.intersect(r, hit);
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), hits};
}

Timed tracePackets(const RenderScene& scene, const RaySet& set) {
    const auto start = std::chrono::steady_clock::now();
    size_t hits = 0;
    TracedHit traced[kBundle];
    bool blocked[kBundle];
    for (size_t b = 0; b + 1 < set.bundleStart.size(); ++b) {
        const Ray* rays = &set.rays[set.bundleStart[b]];
        const int n = int(set.bundleStart[b + 1] - set.bundleStart[b]);
        if (set.anyHit) {
            scene.occludedPacket(rays, n, blocked);
            hits += size_t(std::count(blocked, blocked + n, true));
        } else {
            scene.intersectPacket(rays, n, traced);
            for (int k = 0; k < n; ++k) hits += traced[k].found;
        }
    }
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), hits};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace

int main(int argc, char** argv) try {
    const Options o = parseOptions(argc, argv);
    std::printf("%-14s %-8s %9s %8s %12s %12s %9s\n", "scene", "rays", "count", "per pkt", "single ns", "packet ns",
                "speed-up");
    int status = 0;
    for (const std::string& path : o.scenes) {
        const RenderScene scene(loadSceneDescription(path));
        for (const RaySet& set : gatherRays(scene, o)) {
            if (set.rays.empty()) continue;
            std::vector<double> single, packet, ratio;
            size_t singleHits = 0, packetHits = 0;
            for (int k = 0; k < o.rounds; ++k) {
                Timed a, b;
                if (k % 4 == 0 || k % 4 == 3) {
                    a = traceSingle(scene, set);
                    b = tracePackets(scene, set);
                } else {
                    b = tracePackets(scene, set);
                    a = traceSingle(scene, set);
                }
                singleHits = a.hits;
                packetHits = b.hits;
                single.push_back(a.seconds * 1e9 / double(set.rays.size()));
                packet.push_back(b.seconds * 1e9 / double(set.rays.size()));
                ratio.push_back(a.seconds / b.seconds);
            }
            const double perPacket = double(set.rays.size()) / double(set.bundleStart.size() - 1);
            std::printf("%-14s %-8s %9zu %8.1f %12.1f %12.1f %9.2f\n", scene.description().name.c_str(), set.name,
                        set.rays.size(), perPacket, median(single), median(packet), median(ratio));
            // Both kernels must find the same hits. Inside instances Embree's packet kernels may move a hit in its
            // last bits (RenderScene::intersectPacket); a grazing ray could then hit in one and miss in the other,
            // which the four scenes have not shown. The smoke test runs the Cornell box, without instances.
            if (singleHits != packetHits) {
                std::fprintf(stderr, "stipple-ray-queries: %s, %s: %zu hits one at a time, %zu in packets\n",
                             path.c_str(), set.name, singleHits, packetHits);
                status = 1;
            }
        }
    }
    return status;
} catch (const std::exception& e) {
    std::fprintf(stderr, "stipple-ray-queries: %s\n", e.what());
    return 1;
}
