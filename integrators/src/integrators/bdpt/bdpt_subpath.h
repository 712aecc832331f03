// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// BDPT's two random walks: the camera subpath z_0 (lens) .. and the light subpath y_0 (a light chosen by power)
// .., each vertex carrying its throughput and its area densities from both ends (pdfFwd from its own walk;
// pdfRev, from the other end, filled as soon as the next scattering direction is known). No Russian roulette:
// walks stop at the depth limit, so every strategy's density is known exactly.
//
// Dimensions (max depth D; bB = scattering at the B-th surface hit of that subpath, only what the scene uses):
//   cam.bB.bsdf.lobe 1D, cam.bB.bsdf.dir 2D           B = 0 .. D-1  (lobe only when a material has two lobes)
//   light.choice 1D (more than one light), light.pos 2D
//   light.dir 2D, light.bB.bsdf.lobe 1D, light.bB.bsdf.dir 2D    B = 0 .. D-2, when connections are possible
#pragma once

#include "integrators/bdpt/bdpt_vertex.h"
#include "integrators/integrator.h"

#include <vector>

namespace stipple::render::bdpt {

class SubpathGenerator {
public:
    SubpathGenerator(const RenderScene& scene, const Camera& camera, int maxDepth)
        : scene_(scene), camera_(camera), maxDepth_(maxDepth) {}

    // Declares the walks' dimensions. `lightWalk`: whether light subpaths go past their first vertex (false when
    // no vertex could ever be connected, e.g. every material is specular).
    void declareDimensions(SampleLayout& layout, bool lightWalk);

    // z_0 on the lens (from the primary ray, whose closest hit is `first`) and up to D + 1 surface vertices.
    void cameraSubpath(const Ray& ray, const TracedHit& first, const SampleView& sv, TileContext& tile,
                       std::vector<PathVertex>& out) const;
    // y_0 on a light and, when the light walk is declared, up to D surface vertices. Empty without lights.
    void lightSubpath(const SampleView& sv, TileContext& tile, std::vector<PathVertex>& out) const;

    // Splitting along a specular chain (bdpt_integrator.cpp): continues `path`, a camera subpath whose last vertex
    // is a non-delta surface, with one BSDF sample there and then through delta vertices only, until it stops on
    // a non-delta surface (true) or is lost (false). Probe j >= 1 reads the walk's own values of the same
    // dimensions shifted by j times a fixed irrational offset: each probe's values are uniform like the walk's,
    // so each probe is distributed as the walk's own continuation, and together they stratify the BSDF sample.
    bool specularChainProbe(std::vector<PathVertex>& path, int probe, const SampleView& sv, TileContext& tile) const;

private:
    struct BounceDims {
        int lobe = -1, dir = -1;
    };
    // Appends the surface vertex found by a ray sampled with solid-angle density pdfDir (0 after a delta lobe).
    static void pushSurface(const SurfaceHit& hit, const Spectrum& beta, float pdfDir, std::vector<PathVertex>& path);
    // Samples the BSDF at path.back() (reached from woW, world space, pointing away from it): updates the
    // throughput, sets the previous vertex's reverse density and returns the next ray; false when nothing is left.
    static bool scatter(std::vector<PathVertex>& path, const Vec3& woW, float uc, Point2 u, TransportMode mode,
                        Spectrum& beta, float& pdfDir, Ray& ray);
    // `first`: the first ray's closest hit when already traced (camera rays), else null.
    void walk(Ray ray, const TracedHit* first, Spectrum beta, float pdfDir, TransportMode mode,
              const std::vector<BounceDims>& dims, int maxSurface, const SampleView& sv, TileContext& tile,
              std::vector<PathVertex>& path) const;

    const RenderScene& scene_;
    const Camera& camera_;
    int maxDepth_;
    std::vector<BounceDims> camBounce_, lightBounce_;
    int lightChoice_ = -1, lightPos_ = -1, lightDir_ = -1;
};

} // namespace stipple::render::bdpt
